#pragma once
// Where the cases' scene files are; which backends can run here is the factory's.
#include "backend_factory/backend_factory.hpp"

#include <string>

namespace mssph::validation {

// The validation/ folder: $MSSPH_VALIDATION_DIR if set, else the source tree's.
std::string validation_dir();

// The absolute path of a file given relative to validation/, e.g. "physics/hydrostatic/scene.json".
std::string validation_file(const std::string& relative);

}  // namespace mssph::validation

#include "config/scene.hpp"

#include <vector>

namespace mssph::validation {

// A case's scene, validation/<folder>/scene.json, with --set overrides.
Scene case_scene(const std::string& folder, const std::vector<std::string>& overrides = {});

// --set overrides that run a scene at spacing dx with a time step scaled like dx (the acoustic
// and elastic bounds of stability.cpp are proportional to h = 2 dx).
std::vector<std::string> resolution_overrides(const Scene& scene, double dx);

// The same for a viscous scene: the step also at most 0.8 of the viscous bound
// 0.125 h^2 rho0 / mu (stability.cpp), which shrinks with dx^2, at h = 2 dx.
std::vector<std::string> viscous_resolution_overrides(const Scene& scene, double dx, double rest_density,
                                                      double viscosity);

// A number as --set writes it, to full double precision.
std::string exact(double x);

}  // namespace mssph::validation
