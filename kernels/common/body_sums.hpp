#pragma once
// Per-body sums over particles for the logs (centre of mass, momenta, energy, interaction
// wrench), accumulated in double so that the shifts to the centre of mass do not cancel away
// float32 precision. Host and device share the accumulation; the host turns sums into
// mssph::BodyState.
#include "particle_views.hpp"
#include "vec_math.hpp"

namespace mssph::kernels {

struct BodySums {
  double mass;
  double moment[3];          // sum m x
  double momentum[3];        // sum m v
  double angular_origin[3];  // sum m x x v (about the origin)
  double kinetic_energy;     // sum m v^2 / 2
  double max_speed;
  double force[3];           // sum f_interaction
  double torque_origin[3];   // sum x x f_interaction
  double min_volume_ratio;   // deformable bodies: min det F (kNoVolumeRatio until a particle adds one)
  double compressed_count;   // deformable bodies: particles at or below the model's lowest valid det F
  double left_domain_count;  // particles deactivated after leaving the simulation domain
};

constexpr double kNoVolumeRatio = 1e30;

MSSPH_HD BodySums zero_body_sums() {
  return BodySums{0, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, 0, 0, {0, 0, 0}, {0, 0, 0}, kNoVolumeRatio, 0, 0};
}

// A deformable particle's volume ratio J = det F against its model's lowest valid one
// (ElasticParameters::lowest_valid_volume_ratio).
MSSPH_HD void add_volume_ratio(BodySums& s, float j, float lowest_valid) {
  s.min_volume_ratio = j < s.min_volume_ratio ? j : s.min_volume_ratio;
  if (j <= lowest_valid) s.compressed_count += 1.0;
}

// A particle's hold code (particle_views.hpp): counts those that left the domain.
MSSPH_HD void add_domain_status(BodySums& s, std::uint8_t hold) {
  if (hold == kLeftDomain) s.left_domain_count += 1.0;
}

MSSPH_HD void add_particle(BodySums& s, Vec3 x, Vec3 v, float m, Vec3 f) {
  const double xd[3] = {x.x, x.y, x.z};
  const double vd[3] = {v.x, v.y, v.z};
  const double fd[3] = {f.x, f.y, f.z};
  s.mass += m;
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    s.moment[a] += m * xd[a];
    s.momentum[a] += m * vd[a];
    s.angular_origin[a] += m * (xd[b] * vd[c] - xd[c] * vd[b]);
    s.force[a] += fd[a];
    s.torque_origin[a] += xd[b] * fd[c] - xd[c] * fd[b];
  }
  const double v2 = vd[0] * vd[0] + vd[1] * vd[1] + vd[2] * vd[2];
  s.kinetic_energy += 0.5 * m * v2;
  s.max_speed = s.max_speed > v2 ? s.max_speed : v2;  // squared while accumulating
}

MSSPH_HD BodySums combine(const BodySums& a, const BodySums& b) {
  BodySums s;
  s.mass = a.mass + b.mass;
  for (int k = 0; k < 3; ++k) {
    s.moment[k] = a.moment[k] + b.moment[k];
    s.momentum[k] = a.momentum[k] + b.momentum[k];
    s.angular_origin[k] = a.angular_origin[k] + b.angular_origin[k];
    s.force[k] = a.force[k] + b.force[k];
    s.torque_origin[k] = a.torque_origin[k] + b.torque_origin[k];
  }
  s.kinetic_energy = a.kinetic_energy + b.kinetic_energy;
  s.max_speed = a.max_speed > b.max_speed ? a.max_speed : b.max_speed;
  s.min_volume_ratio = a.min_volume_ratio < b.min_volume_ratio ? a.min_volume_ratio : b.min_volume_ratio;
  s.compressed_count = a.compressed_count + b.compressed_count;
  s.left_domain_count = a.left_domain_count + b.left_domain_count;
  return s;
}

}  // namespace mssph::kernels
