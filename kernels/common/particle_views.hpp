#pragma once
// What the kernels read and write, passed by value as a few small views (not dozens of loose
// parameters). Arrays in "canonical" order follow ParticleSetup's particle order (bodies
// contiguous); arrays in "sorted" order follow the neighbour grid's cell order, copied anew every
// step (in the order of the last rebuild where the GPU keeps lists: list_skin.hpp).
#include "cell_grid.hpp"
#include "smoothing_kernels.hpp"
#include "vec_math.hpp"

#include <cstdint>
#include <cstring>

namespace mssph::kernels {

enum BodyKindCode : std::uint32_t { kFluid = 0, kDeformable = 1, kRigid = 2, kBoundary = 3 };
inline constexpr std::uint32_t kNotRigid = 0xffffffffu;

// One per body.
struct BodyParameters {
  std::uint32_t kind;         // BodyKindCode
  std::uint32_t rigid_index;  // index of a movable rigid body's state, else kNotRigid
  float sph_mass;             // m = rho0 dx^3 [kg]
  float rest_density;         // rho0 [kg/m^3]
  float pressure_stiffness;   // k [m^2/s^2]
  float viscosity;            // mu [Pa s]
  // Where its particles' own-body number densities at rest lie (SortedView::own_rest_number_density):
  // canonical index less this, the particles before the body that hold none; 0 for a fluid body.
  std::uint32_t own_rest_offset;
};

struct StepParameters {
  SmoothingKernels smoothing;
  float dt;                            // [s]
  Vec3 gravity;                        // [m/s^2]
  float inverse_rest_number_density;   // 1 / delta0 [m^3]
  float inverse_gradient_consistency;  // 1 / g, see model/lattice_calibration.hpp
  float wall_exclusion_distance;       // d_wall: closest approach to a boundary particle [m], model/wall_exclusion.hpp
  Vec3 domain_min, domain_max;         // the simulation domain, kernel frame [m] (simulation_domain.hpp)
  std::uint32_t particle_count;
};

// An index carried in a float's bit pattern: the fourth component of a 16-byte record, so one
// load gives, e.g., a neighbour's position and body.
MSSPH_HD float index_as_float_bits(std::uint32_t index) {
  float f;
  std::memcpy(&f, &index, sizeof f);
  return f;
}
MSSPH_HD std::uint32_t index_from_float_bits(float f) {
  std::uint32_t index;
  std::memcpy(&index, &f, sizeof index);
  return index;
}
// The body index rides in the sorted position's fourth component.
MSSPH_HD std::uint32_t body_of(const Vec4& sorted_position) { return index_from_float_bits(sorted_position.w); }

struct alignas(8) VolumePressure {  // aligned: one 8-byte load
  float volume;                     // V = m / rho [m^3]
  float pressure;                   // P [Pa]
};

// Loads of a sorted array that no thread writes while the pass reading it runs, issued where they
// are written. nvcc moves a load whose value is used only past a branch into that branch, so a
// force pair's volume and velocity would be loaded after its distance test and its body's kind,
// each behind the last; on the GPU these read through the read-only data path with inline PTX
// that the compiler keeps in place (__ldg).
MSSPH_HD Vec4 load_in_place(const Vec4* array, std::uint32_t k) {
#if defined(__CUDA_ARCH__)
  const float4 v = __ldg(reinterpret_cast<const float4*>(array + k));
  return {v.x, v.y, v.z, v.w};
#else
  return array[k];
#endif
}
MSSPH_HD VolumePressure load_in_place(const VolumePressure* array, std::uint32_t k) {
#if defined(__CUDA_ARCH__)
  const float2 v = __ldg(reinterpret_cast<const float2*>(array + k));
  return {v.x, v.y};
#else
  return array[k];
#endif
}

// Read by the density and force passes.
struct SortedView {
  StepParameters step;
  const BodyParameters* bodies;
  CellRanges grid;
  const Vec4* position;                   // sorted: xyz [m], w = body index bits
  const Vec4* velocity;                   // sorted: xyz [m/s], w the position carry
  const std::uint32_t* id;                // sorted -> canonical index
  const VolumePressure* volume_pressure;  // sorted, written by the density pass
  // Canonical order, the particles of the bodies that take their own body at rest
  // (fluid_physics.hpp, takes_own_body_at_rest) alone, at their index less their body's
  // own_rest_offset: the own-body number density at rest [1/m^3], the part of a density its walks
  // do not sum; null without such bodies.
  const float* own_rest_number_density;
  // Sorted: each fluid particle's corrected velocity gradient A_i for the full_stress viscosity
  // (fluid_physics.hpp, VelocityGradientSums), zero for the others; null under the paper's eq. 3.
  const Mat3* velocity_gradient;
};

// Why a particle is held in place (CanonicalState::fixed): never, by a deformable body's fixed
// region (from the scene), or because it left the simulation domain (set by the step).
enum HoldCode : std::uint8_t { kFree = 0, kFixedRegion = 1, kLeftDomain = 2 };

// The evolving canonical state.
struct CanonicalState {
  Vec4* position;             // xyz [m]
  Vec4* velocity;             // xyz [m/s], w the position carry (compensated_position.hpp)
  Vec4* interaction_force;    // xyz [N]: from other bodies, eq. 7
  const Vec4* elastic_force;  // xyz [N]: deformable particles, else zero (may be null)
  std::uint8_t* fixed;        // HoldCode: held by a fixed region, or since it left the domain
};

}  // namespace mssph::kernels
