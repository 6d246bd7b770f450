#include "hertz.hpp"

#include "model/scene_builder.hpp"
#include "reference_backend.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace mssph::validation {
namespace {

using Eigen::Vector3d;

const BodyConfig& body(const Scene& scene, const std::string& name) {
  const BodyConfig* b = scene.find_body(name);
  if (!b) throw std::runtime_error(scene.source_file + ": the Hertz scene needs a body \"" + name + "\"");
  return *b;
}

}  // namespace

ParticleSetup with_body_particles(const ParticleSetup& in, std::size_t replaced, const std::vector<Vector3d>& points) {
  ParticleSetup out = in;
  out.position.clear();
  out.velocity.clear();
  out.mass.clear();
  out.body.clear();
  out.fixed.clear();
  out.rest_offset.clear();
  const auto add = [&](const Vector3d& x, std::size_t from, std::size_t body) {
    out.position.push_back(x);
    out.velocity.push_back(in.velocity[from]);
    out.mass.push_back(in.mass[from]);
    out.body.push_back(static_cast<std::uint32_t>(body));
    out.fixed.push_back(in.fixed[from]);
    out.rest_offset.push_back(in.rest_offset[from]);
  };
  for (std::size_t b = 0; b < in.bodies.size(); ++b) {
    const BodySetup& body = in.bodies[b];
    out.bodies[b].first = out.position.size();
    if (b == replaced) {
      for (const Vector3d& x : points) add(x, body.first, b);
    } else {
      for (std::size_t i = body.first; i < body.first + body.count; ++i) add(in.position[i], i, b);
    }
    out.bodies[b].count = out.position.size() - out.bodies[b].first;
    if (b == replaced) out.bodies[b].lattice_sites = out.bodies[b].count;
  }
  return out;
}

std::vector<Vector3d> spherical_shells(const Vector3d& centre, double radius, double dx, double z_max) {
  std::vector<Vector3d> points;
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (double r = radius - 0.5 * dx; r > 0.0; r -= dx) {
    const auto n = std::max<long>(1, std::lround(4.0 * std::numbers::pi * r * r / (dx * dx)));
    for (long i = 0; i < n; ++i) {
      const double z = 1.0 - (2.0 * static_cast<double>(i) + 1.0) / static_cast<double>(n);
      const double rho = std::sqrt(1.0 - z * z);
      const double phi = golden_angle * static_cast<double>(i);
      const Vector3d p = centre + r * Vector3d(rho * std::cos(phi), rho * std::sin(phi), z);
      if (p.z() <= z_max) points.push_back(p);
    }
  }
  return points;
}

Indentation press_indenter(const Scene& scene, double speed, double deepest) {
  const double dx = scene.simulation.particle_spacing;
  const double dt = scene.simulation.dt;
  const BodyConfig& ball_config = body(scene, "indenter");
  const BodyConfig& block_config = body(scene, "block");
  const double radius = ball_config.shape.radius;
  const Vector3d centre = ball_config.position;
  const double block_top = block_config.position.z() + 0.5 * block_config.shape.size.z();
  const double gap = centre.z() - radius - block_top;  // the sphere starts this far above the block

  ParticleSetup setup = build_particles(scene);
  std::size_t indenter = 0;
  while (setup.bodies[indenter].name != "indenter") ++indenter;
  const std::size_t block = setup.bodies[0].name == "block" ? 0 : 1;
  // Only the cap that can come within h of the block matters.
  setup = with_body_particles(setup, indenter, spherical_shells(centre, radius, dx, block_top + deepest + 3.0 * dx));
  reference::ReferenceBackend backend(std::move(setup));

  Indentation curve;
  const BodySetup& ball = backend.setup().bodies[indenter];
  const BodySetup& blk = backend.setup().bodies[block];
  const auto steps = static_cast<int>(std::ceil((deepest + gap) / (speed * dt)));
  for (int s = 1; s <= steps; ++s) {
    for (std::size_t i = ball.first; i < ball.first + ball.count; ++i) {
      backend.particles().position[i].z() -= speed * dt;
      backend.particles().velocity[i] = Vector3d(0.0, 0.0, -speed);
    }
    backend.step();
    double force = 0.0;
    for (std::size_t i = blk.first; i < blk.first + blk.count; ++i)
      force -= backend.particles().interaction_force[i].z();
    curve.depth.push_back(static_cast<double>(s) * speed * dt - gap);
    curve.force.push_back(force);
  }
  return curve;
}

HertzFit fit_hertz(const Indentation& curve, double d_min, double d_max) {
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, n = 0.0, moment = 0.0, norm = 0.0;
  HertzFit fit;
  fit.min_force = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < curve.depth.size(); ++k) {
    const double d = curve.depth[k];
    if (d < d_min || d > d_max) continue;
    fit.min_force = std::min(fit.min_force, curve.force[k]);
    const double x = std::log(d);
    const double y = std::log(curve.force[k]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    n += 1.0;
    moment += curve.force[k] * std::pow(d, 1.5);
    norm += std::pow(d, 3.0);
  }
  fit.exponent = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  fit.prefactor = moment / norm;
  return fit;
}

double hertz_prefactor(const Scene& scene) {
  const Material& m = body(scene, "block").material;
  return 4.0 / 3.0 * m.young_modulus / (1.0 - m.poisson_ratio * m.poisson_ratio) *
         std::sqrt(body(scene, "indenter").shape.radius);
}

}  // namespace mssph::validation
