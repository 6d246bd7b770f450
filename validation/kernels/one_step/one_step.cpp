#include "one_step.hpp"

#include "backend_factory/backend_factory.hpp"
#include "config/scene_loader.hpp"
#include "framework/backends.hpp"
#include "model/scene_builder.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

namespace mssph::validation {
namespace {

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  return nlohmann::json::parse(in);
}

// Relative L2 difference ||a - b|| / ||b|| over all particles; 0 when both are exactly zero (a
// quantity the scene does not exercise, e.g. pressure on a lone deformable body).
template <class T, class Norm2>
double relative_l2(const std::vector<T>& a, const std::vector<T>& b, Norm2 norm2) {
  double difference = 0.0;
  double reference = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    difference += norm2(a[i] - b[i]);
    reference += norm2(b[i]);
  }
  if (reference == 0.0) return difference == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  return std::sqrt(difference / reference);
}

double squared(double x) { return x * x; }
const auto vector_norm2 = [](const Eigen::Vector3d& v) { return v.squaredNorm(); };
const auto matrix_norm2 = [](const Eigen::Matrix3d& m) { return m.squaredNorm(); };

// Rounds positions to float, so both precisions start from the very same numbers.
void round_to_float(std::vector<Eigen::Vector3d>& positions) {
  for (Eigen::Vector3d& x : positions) x = x.cast<float>().cast<double>();
}

}  // namespace

std::vector<std::string> one_step_scene_names() {
  return {"fluid", "rigid", "deformable", "mixed", "mixed_far", "mixed_full_stress"};
}

OneStepScene one_step_scene(const std::string& name) {
  const bool far = name == "mixed_far";
  const bool full_stress = name == "mixed_full_stress";
  const std::string file = far || full_stress ? std::string("mixed") : name;
  OneStepScene scene{name, read_json(validation_file("kernels/one_step/" + file + ".json"))};
  scene.deform = name == "deformable" || file == "mixed";
  // No rotation in the mixed scenes: the jelly must stay clear of the water and the walls.
  scene.rotate_degrees = name == "deformable" ? 25.0 : 0.0;
  if (far) {
    const double offset[3] = {1000.0, -2000.0, 500.0};
    for (auto& [body_name, body] : scene.document["bodies"].items()) {
      for (int k = 0; k < 3; ++k) body["position"][k] = body["position"][k].get<double>() + offset[k];
    }
    scene.document["name"] = "one_step_mixed_far";
  }
  if (full_stress) {
    scene.document["simulation"]["viscosity_model"] = "full_stress";
    scene.document["name"] = "one_step_mixed_full_stress";
  }
  return scene;
}

OneStepErrors one_step_errors(const std::string& backend, const OneStepScene& scene, std::uint64_t seed) {
  nlohmann::json doc = scene.document;
  doc["simulation"]["seed"] = seed;
  ParticleSetup setup = build_particles(parse_scene(doc, scene.name));
  round_to_float(setup.position);

  // The evaluated state: the start, or for deformable bodies a deformation of it: 1% stretch
  // along x, a rotation and random displacements of 2% of a spacing, so rotations and elastic
  // forces are far from trivial. The deformation is about the deformable particles' centroid,
  // wherever the scene sits.
  std::vector<Eigen::Vector3d> positions = setup.position;
  if (scene.deform) {
    std::mt19937_64 random(seed + 1);
    std::uniform_real_distribution<double> shake(-0.02 * setup.spacing, 0.02 * setup.spacing);
    const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(scene.rotate_degrees * std::numbers::pi / 180.0, Eigen::Vector3d(1, 2, 3).normalized())
            .toRotationMatrix();
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    double count = 0.0;
    for (std::size_t i = 0; i < setup.size(); ++i) {
      if (setup.bodies[setup.body[i]].kind != BodyKind::deformable) continue;
      centroid += positions[i];
      count += 1.0;
    }
    centroid /= count;
    for (std::size_t i = 0; i < setup.size(); ++i) {
      if (setup.bodies[setup.body[i]].kind != BodyKind::deformable) continue;
      Eigen::Vector3d x = positions[i] - centroid;
      x.x() *= 1.01;
      positions[i] = centroid + rotation * x + Eigen::Vector3d(shake(random), shake(random), shake(random));
    }
    round_to_float(positions);
  }

  std::unique_ptr<Backend> reference = make_backend("reference", setup);
  std::unique_ptr<Backend> candidate = make_backend(backend, setup);
  reference->set_particle_positions(positions);
  candidate->set_particle_positions(positions);
  const ForceEvaluation ref = reference->evaluate_forces();
  const ForceEvaluation got = candidate->evaluate_forces();

  OneStepErrors e;
  e.density = relative_l2(got.density, ref.density, squared);
  // Pressure P = k (rho - rho0) cancels where rho is near rho0: its error is measured against the
  // physical scale k rho0 of each particle's body, which makes it the density error times k.
  double pressure_difference = 0.0;
  double pressure_scale = 0.0;
  for (std::size_t i = 0; i < setup.size(); ++i) {
    const Material& material = setup.bodies[setup.body[i]].material;
    pressure_difference += squared(got.pressure[i] - ref.pressure[i]);
    pressure_scale += squared(material.pressure_stiffness * material.rest_density);
  }
  e.pressure = std::sqrt(pressure_difference / pressure_scale);
  e.pressure_force = relative_l2(got.pressure_force, ref.pressure_force, vector_norm2);
  e.viscosity_force = relative_l2(got.viscosity_force, ref.viscosity_force, vector_norm2);
  std::vector<Eigen::Vector3d> total_ref, total_got;
  for (std::size_t i = 0; i < setup.size(); ++i) {
    total_ref.push_back(ref.pressure_force[i] + ref.viscosity_force[i] + ref.elastic_force[i]);
    total_got.push_back(got.pressure_force[i] + got.viscosity_force[i] + got.elastic_force[i]);
  }
  e.total_force = relative_l2(total_got, total_ref, vector_norm2);
  if (scene.deform) {
    e.deformed = true;
    e.elastic_force = relative_l2(got.elastic_force, ref.elastic_force, vector_norm2);
    e.rotation = relative_l2(got.rotation, ref.rotation, matrix_norm2);
  }
  return e;
}

}  // namespace mssph::validation
