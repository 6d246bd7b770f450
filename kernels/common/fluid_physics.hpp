#pragma once
// Steps 2 and 3 of the paper's loop (3.2) for one particle, float32: density and pressure, then
// pressure and viscosity forces (paper eq. 2, 3 inside a fluid; eq. 7 between bodies). The same
// functions run in the CUDA kernels and in the host build; cpu_reference/density.hpp and
// cpu_reference/fluid_forces.hpp document the formulation (number-density volumes after
// Solenthaler and Pajarola 2008, clamped equation of state, pressure force without the paper's
// 1/2 and with the lattice calibration 1/c).
#include "particle_views.hpp"

namespace mssph::kernels {

struct DensityResult {
  float density;  // rho = m delta [kg/m^3]
  VolumePressure volume_pressure;
};

MSSPH_HD DensityResult density_at(const SortedView& v, std::uint32_t s) {
  const Vec3 x_i = xyz(v.position[s]);
  float delta = 0.0f;
  v.grid.for_each_candidate(x_i, [&](std::uint32_t t) {
    delta += v.step.kernels.poly6(squared_norm(x_i - xyz(v.position[t])));
  });
  const BodyParameters& body = v.bodies[body_of(v.position[s])];
  const float density = body.sph_mass * delta;
  const float pressure = std::fmax(0.0f, body.pressure_stiffness * (density - body.rest_density));
  return {density, {1.0f / delta, pressure}};
}

struct PressureViscosityForces {
  Vec3 pressure;     // [N] from all neighbours
  Vec3 viscosity;    // [N] from all neighbours
  Vec3 interaction;  // [N] the part of both from other bodies (eq. 7)
};

MSSPH_HD PressureViscosityForces pressure_viscosity_at(const SortedView& v, std::uint32_t s) {
  PressureViscosityForces out{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  const Vec4 p_i = v.position[s];
  const std::uint32_t body_i = body_of(p_i);
  const BodyParameters& b_i = v.bodies[body_i];
  if (b_i.kind == kBoundary) return out;
  const Vec3 x_i = xyz(p_i);
  const Vec3 u_i = xyz(v.velocity[s]);
  const VolumePressure vp_i = v.volume_pressure[s];
  v.grid.for_each_candidate(x_i, [&](std::uint32_t t) {
    if (t == s) return;
    const Vec4 p_j = v.position[t];
    const Vec3 r_ij = x_i - xyz(p_j);
    const float r2 = squared_norm(r_ij);
    if (r2 >= v.step.kernels.h2) return;
    const std::uint32_t body_j = body_of(p_j);
    const bool same_body = body_j == body_i;
    if (same_body && b_i.kind != kFluid) return;  // rigid, deformable: no pressure among themselves
    const VolumePressure vp_j = v.volume_pressure[t];
    const float r = std::sqrt(r2);
    const float volumes = vp_i.volume * vp_j.volume;
    const Vec3 pressure = (-volumes * v.step.inverse_gradient_consistency * (vp_i.pressure + vp_j.pressure)) *
                          v.step.kernels.spiky_gradient(r_ij, r);
    const float mu = 0.5f * (b_i.viscosity + v.bodies[body_j].viscosity);
    const Vec3 viscosity = (mu * volumes * v.step.kernels.viscosity_laplacian(r)) * (xyz(v.velocity[t]) - u_i);
    out.pressure += pressure;
    out.viscosity += viscosity;
    if (!same_body) out.interaction += pressure + viscosity;
  });
  return out;
}

// Step 4 for fluid and deformable particles, leap-frog with staggered velocities:
// v_{n+1/2} = v_{n-1/2} + (f / m + g) dt, x_{n+1} = x_n + v_{n+1/2} dt; held particles stay.
MSSPH_HD void leapfrog(Vec4& position, Vec4& velocity, Vec3 force, float mass, bool held, const StepParameters& step) {
  if (held) {
    velocity = Vec4{0, 0, 0, 0};
    return;
  }
  const Vec3 v = xyz(velocity) + step.dt * (force * (1.0f / mass) + step.gravity);
  velocity = make_vec4(v, 0.0f);
  position = make_vec4(xyz(position) + step.dt * v, 0.0f);
}

// Steps 3 and 4 fused for sorted particle s: its pressure and viscosity forces (plus its elastic
// force when deformable) and, for fluid and deformable particles, the leap-frog update of its
// canonical state. Reads only sorted arrays and writes only particle s's canonical entries, so
// all particles can run at once.
MSSPH_HD void forces_and_leapfrog(const SortedView& v, const CanonicalState& c, std::uint32_t s) {
  const std::uint32_t i = v.id[s];
  const PressureViscosityForces f = pressure_viscosity_at(v, s);
  c.interaction_force[i] = make_vec4(f.interaction, 0.0f);
  const BodyParameters& body = v.bodies[c.body[i]];
  if (body.kind != kFluid && body.kind != kDeformable) return;
  Vec3 total = f.pressure + f.viscosity;
  if (c.elastic_force) total += xyz(c.elastic_force[i]);
  leapfrog(c.position[i], c.velocity[i], total, body.sph_mass, c.fixed[i] != 0, v.step);
}

// The grid's last stage for sorted particle s (after sorting the keys): marks where its cell's
// run starts and ends and copies its position (with its body index) and velocity into cell order.
MSSPH_HD void place_in_cell_order(std::uint32_t s, std::uint32_t n, const std::uint32_t* sorted_keys,
                                  const std::uint32_t* sorted_id, const Vec4* position, const Vec4* velocity,
                                  const std::uint32_t* body, Vec4* sorted_position, Vec4* sorted_velocity,
                                  std::uint32_t* cell_start, std::uint32_t* cell_end) {
  const std::uint32_t key = sorted_keys[s];
  if (s == 0 || sorted_keys[s - 1] != key) cell_start[key] = s;
  if (s + 1 == n || sorted_keys[s + 1] != key) cell_end[key] = s + 1;
  const std::uint32_t i = sorted_id[s];
  sorted_position[s] = make_vec4(xyz(position[i]), body_as_float(body[i]));
  sorted_velocity[s] = velocity[i];
}

}  // namespace mssph::kernels
