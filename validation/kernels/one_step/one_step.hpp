#pragma once
// One force evaluation from identical states: every per-particle quantity of a float32 backend
// (cpu, cuda) against the float64 reference, on a randomly perturbed lattice. Shared by the
// kernels suite's one-step case and tests/backends/one_step_agreement_test.cpp.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace mssph::validation {

struct OneStepScene {
  std::string name;
  nlohmann::json document;      // a scene in the ordinary format; its seed is replaced per run
  bool deform = false;          // stretch, rotate and shake the deformable particles before evaluating
  double rotate_degrees = 0.0;  // the rotation of that deformation
};

// The shipped one-step scenes, validation/kernels/one_step/<name>.json: fluid, rigid,
// deformable, mixed, and mixed_far (the mixed scene moved 2 km from the origin, where float32
// world coordinates would resolve only 0.1 mm).
std::vector<std::string> one_step_scene_names();
OneStepScene one_step_scene(const std::string& name);

// Relative L2 differences ||candidate - reference|| / ||reference|| over all particles.
struct OneStepErrors {
  double density = 0.0;
  double pressure = 0.0;  // against the physical scale k rho0 of each particle's body (see .cpp)
  double pressure_force = 0.0;
  double viscosity_force = 0.0;
  double total_force = 0.0;
  bool deformed = false;  // the two below are measured only on deformed scenes
  double elastic_force = 0.0;
  double rotation = 0.0;
};

// Bounds, the issue's: densities are float32 sums of ~30 terms (1e-5 relative; pressure the
// same, as P - P_ref = k (rho - rho_ref)); forces float32 sums of pair terms that partly cancel
// (1e-4); rotations an SVD polar decomposition in double against float32 iterations of Mueller
// et al. 2016 stopped at a 1e-7 rad update, agreeing to float rounding (1e-5).
constexpr double kOneStepDensityBound = 1e-5;
constexpr double kOneStepForceBound = 1e-4;
constexpr double kOneStepRotationBound = 1e-5;

OneStepErrors one_step_errors(const std::string& backend, const OneStepScene& scene, std::uint64_t seed);

}  // namespace mssph::validation
