#include "sphere_drops.hpp"

#include "backend_factory/backend_factory.hpp"
#include "config/scene_loader.hpp"
#include "framework/fits.hpp"
#include "model/scene_builder.hpp"

#include <algorithm>
#include <sstream>

namespace mssph::validation {
namespace {

// The proxy's interaction force and centre of mass after every step.
struct ProxyTrack {
  std::vector<Eigen::Vector3d> force;
  std::vector<Eigen::Vector3d> position;
};

ProxyTrack track_proxy(const std::string& backend_name, const ParticleSetup& setup, std::size_t proxy,
                       std::size_t steps) {
  std::unique_ptr<Backend> backend = make_backend(backend_name, setup);
  ProxyTrack track;
  for (std::size_t s = 0; s < steps; ++s) {
    backend->step();
    const BodyState state = backend->rigid_body_state(proxy);
    track.force.push_back(state.interaction_force);
    track.position.push_back(state.centre_of_mass);
  }
  return track;
}

std::string text(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

}  // namespace

ParticleSetup shipped_scene(const std::string& config, double spacing, double duration,
                            const std::vector<std::string>& extra) {
  std::vector<std::string> overrides{"simulation/particle_spacing=" + text(spacing),
                                     "simulation/duration=" + text(duration)};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  return build_particles(load_scene(std::string(MSSPH_SOURCE_DIR) + "/configs/" + config, overrides));
}

DropAgreement drop_agreement(const std::string& backend, const ParticleSetup& setup, std::size_t proxy,
                             std::size_t steps) {
  const ProxyTrack reference = track_proxy("reference", setup, proxy, steps);
  const ProxyTrack candidate = track_proxy(backend, setup, proxy, steps);
  DropAgreement result;
  std::vector<Eigen::Vector3d> displacement_ref, displacement_candidate;
  for (std::size_t k = 0; k < steps; ++k) {
    result.travel = std::max(result.travel, (reference.position[k] - reference.position.front()).norm());
    displacement_ref.push_back(reference.position[k] - reference.position.front());
    displacement_candidate.push_back(candidate.position[k] - reference.position.front());
    result.time.push_back(static_cast<double>(k + 1) * setup.dt);
    result.force_reference.push_back(reference.force[k].z());
    result.force_candidate.push_back(candidate.force[k].z());
  }
  result.force_error = normalised_rms(candidate.force, reference.force);
  result.path_error = normalised_rms(displacement_candidate, displacement_ref);
  return result;
}

double drop_tolerance(const std::string& config) { return config.find("fluid") != std::string::npos ? 0.05 : 0.02; }

}  // namespace mssph::validation
