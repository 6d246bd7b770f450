#pragma once
// The neighbour-list tests' particles: a jittered, compressed lattice of three bodies (walls,
// fluid, a deformable block; the walls' and the block's density sums skip their own body) sorted
// into a grid small enough to wrap, so periodic images share cells with real neighbours; and a GPU
// team's lists of them, recorded on the host.
#include "common/fluid_physics.hpp"
#include "common/neighbour_list.hpp"
#include "sorted_particles.hpp"

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

namespace mssph::testing {

using kernels::Vec3;
using kernels::Vec4;

constexpr std::uint32_t kWallBody = 0, kFluidBody = 1, kDeformableBody = 2;

// 12 x 12 x 12 lattice sites, spacing dx (compressed), jittered by 0.1 dx: the lowest
// two layers are wall, the sites with x above the middle deformable, the rest fluid. Support
// h = 2 dx; cells of side h (or cell_size_over_h times h), 4 per axis: the lattice spans about 6
// cells, so the grid wraps.
class JitteredLattice {
 public:
  // Spacing 0.02 m times `compression` (1: none); cells of cell_size_over_h times h; the block
  // (kDeformableBody) of kind block_kind; 2^grid_bits cells per axis.
  JitteredLattice(std::mt19937_64& random, float compression, float cell_size_over_h = 1.0f,
                  std::uint32_t block_kind = kernels::kDeformable, std::uint32_t grid_bits = 2) {
    const float dx = 0.02f * compression;
    std::uniform_real_distribution<float> jitter(-0.1f * dx, 0.1f * dx);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<Vec4> particles;
    const int sites = 12;
    for (int i = 0; i < sites; ++i) {
      for (int j = 0; j < sites; ++j) {
        for (int k = 0; k < sites; ++k) {
          const std::uint32_t body = k < 2 ? kWallBody : (i >= sites / 2 ? kDeformableBody : kFluidBody);
          const Vec3 site{static_cast<float>(i) * dx, static_cast<float>(j) * dx, static_cast<float>(k) * dx};
          particles.push_back(kernels::make_vec4(site + Vec3{jitter(random), jitter(random), jitter(random)},
                                                 kernels::index_as_float_bits(body)));
        }
      }
    }
    kernels::GridShape shape;
    shape.inverse_cell_size = 1.0f / (cell_size_over_h * 2.0f * dx);
    shape.bits_x = shape.bits_y = shape.bits_z = grid_bits;
    sorted_ = sort_into_grid(particles, shape);
    for (std::size_t s = 0; s < particles.size(); ++s) {
      velocity_.push_back(Vec4{unit(random), unit(random), unit(random), 0.0f});
      volume_pressure_.push_back({dx * dx * dx * (1.0f + 0.1f * unit(random)), 1000.0f * (1.0f + unit(random))});
    }
    bodies_ = {{kernels::kBoundary, kernels::kNotRigid, 0, 1000, 100, 0.0f, 0},
               {kernels::kFluid, kernels::kNotRigid, 0, 1000, 100, 1.0f, 0},
               {block_kind, kernels::kNotRigid, 0, 1000, 100, 2.0f, 0}};
    step_.smoothing = kernels::SmoothingKernels::for_support(2.0 * dx);
    step_.inverse_gradient_consistency = 1.0f;
    step_.particle_count = static_cast<std::uint32_t>(particles.size());
  }

  // Has the walks of the block's particles leave out the rows that hold only the block
  // (CellRanges::cell_body); empty cells' entries are kMixedCell, as a stale entry may be.
  void leave_out_own_rows() { sorted_.note_cell_bodies(kernels::kMixedCell); }

  // Body b's parameters, which the view reads (its kind, whether it moves).
  kernels::BodyParameters& body_parameters(std::uint32_t b) { return bodies_[b]; }
  const std::vector<kernels::BodyParameters>& bodies() const { return bodies_; }

  // Moves sorted particle s by `by`, keeping the cell order and the grid (as a step that keeps the
  // lists does).
  void move(std::uint32_t s, Vec3 by) {
    sorted_.position[s] = kernels::make_vec4(kernels::xyz(sorted_.position[s]) + by, sorted_.position[s].w);
  }

  kernels::SortedView view() const {
    kernels::SortedView v{};
    v.step = step_;
    v.bodies = bodies_.data();
    v.grid = sorted_.grid();
    v.position = sorted_.position.data();
    v.velocity = velocity_.data();
    v.volume_pressure = volume_pressure_.data();
    return v;
  }
  std::uint32_t size() const { return step_.particle_count; }

 private:
  SortedParticles sorted_;
  std::vector<Vec4> velocity_;
  std::vector<kernels::VolumePressure> volume_pressure_;
  std::vector<kernels::BodyParameters> bodies_;
  kernels::StepParameters step_{};
};

// Whether sorted particles s and t of the view are closer than sqrt(radius2), or than h.
inline bool closer_than(const kernels::SortedView& v, std::uint32_t s, std::uint32_t t, float radius2) {
  return kernels::squared_norm(kernels::xyz(v.position[s]) - kernels::xyz(v.position[t])) < radius2;
}
inline bool within_support(const kernels::SortedView& v, std::uint32_t s, std::uint32_t t) {
  return closer_than(v, s, t, v.step.smoothing.h2);
}

// Whether t belongs to the body of s when s takes its own body at rest (a wall or block particle),
// which s's density sum skips and its lists leave out.
inline bool own_body_at_rest(const kernels::SortedView& v, std::uint32_t s, std::uint32_t t) {
  const std::uint32_t body_s = kernels::body_of(v.position[s]);
  return kernels::takes_own_body_at_rest(v.bodies[body_s]) && kernels::body_of(v.position[t]) == body_s;
}

// Whether two sums have the same bits.
inline bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
inline bool same_bits(Vec3 a, Vec3 b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z); }

inline float compressed_by_up_to_4_percent(std::mt19937_64& random) {
  return std::uniform_real_distribution<float>(0.96f, 1.0f)(random);
}

// The lists of a team of `lanes` lanes for every particle of the view, laid out as on the GPU, as
// a rebuild's density pass records them within record_radius2 (density_sum_recording), and the
// density sums of that pass.
struct TeamLists {
  std::uint32_t lanes;
  std::vector<std::uint32_t> count, index;
  kernels::NeighbourLists lists;
  std::vector<float> density;              // per list: its lane's share of the particle's density sum
  std::vector<float> nearest_other_body2;  // per list: its lane's DensitySum::nearest_other_body2

  static constexpr std::uint32_t kUnwritten = 0xdeadbeefu;

  TeamLists(const kernels::SortedView& v, std::uint32_t lanes_, std::uint32_t capacity, float record_radius2)
      : lanes(lanes_),
        count(std::size_t{v.step.particle_count} * lanes, kUnwritten),
        index(count.size() * capacity, kUnwritten),
        density(count.size()),
        nearest_other_body2(count.size()) {
    lists = kernels::lane_lists(capacity, static_cast<std::uint32_t>(count.size()), count.data(), index.data());
    for (std::uint32_t s = 0; s < v.step.particle_count; ++s) {
      for (std::uint32_t lane = 0; lane < lanes; ++lane) {
        const kernels::DensitySum sum =
            kernels::density_sum_recording(v, s, lane, lanes, kernels::cells_left_out(v, s), lists, list_of(s, lane),
                                           record_radius2, kernels::body_left_out(v, v.position[s]));
        density[list_of(s, lane)] = sum.delta;
        nearest_other_body2[list_of(s, lane)] = sum.nearest_other_body2;
      }
    }
  }
  std::uint32_t list_of(std::uint32_t s, std::uint32_t lane) const { return s * lanes + lane; }
  std::uint32_t entry(std::uint32_t list, std::uint32_t k) const { return index[list + std::size_t{k} * count.size()]; }
  // The list's entries as recorded, or nothing for an overflowed or unrecorded list.
  std::vector<std::uint32_t> entries(std::uint32_t list) const {
    std::vector<std::uint32_t> out;
    if (count[list] >= lists.capacity) return out;
    for (std::uint32_t k = 0; k < count[list]; ++k) out.push_back(entry(list, k));
    return out;
  }
};

}  // namespace mssph::testing
