#pragma once
// The `cpu` backend: the CUDA backend's float32 per-particle functions (kernels/common/) run by
// OpenMP loops on the host, so a machine without a GPU exercises exactly the kernels' arithmetic.
// Its neighbour lists have a skin, as the GPU teams' do: the grid is rebuilt and the lists recorded
// only when they expire (list_skin.hpp).
#include "../common/float_scene.hpp"
#include "../common/neighbour_list.hpp"
#include "backend/backend.hpp"
#include "particle_partition.hpp"

#include <array>
#include <cstdint>
#include <optional>

namespace mssph::kernels {

class CpuBackend final : public Backend {
 public:
  explicit CpuBackend(ParticleSetup setup);

  BackendInfo info() const override;
  std::size_t particle_count() const override { return setup_.size(); }
  double time() const override { return time_; }
  void set_external_wrench(std::size_t body, const Eigen::Vector3d& force, const Eigen::Vector3d& torque) override;
  void step() override;
  std::vector<BodyState> body_states() override;
  BodyState rigid_body_state(std::size_t body) override;
  ParticleSnapshot snapshot() override;
  std::vector<double> last_phase_seconds() const override;
  ForceEvaluation evaluate_forces() override;
  void set_particle_positions(const std::vector<Eigen::Vector3d>& positions) override;
  StateArrays save_state() override;
  void restore_state(const StateArrays& state) override;
  std::optional<std::uint64_t> neighbour_grid_builds() override { return grid_builds_; }

 private:
  void update_neighbour_lists();
  bool lists_expired();
  void build_grid();
  void partition_by_list_length();
  void compute_rotations_and_elastic_forces();
  void compute_densities();
  void compute_forces_and_advance_particles();
  void advance_rigid_bodies();
  SortedView sorted_view() const;
  NeighbourLists recorded_lists();
  NeighbourLists neighbour_lists();
  HostDeformableView deformable_view();
  RigidBody& rigid_of(std::size_t body);

  ParticleSetup setup_;
  FloatScene scene_;
  // In the cell order of the last grid rebuild.
  std::vector<std::uint32_t> cell_start_;   // cell_count() + 1 entries
  std::vector<std::uint32_t> cell_middle_;  // CellRanges::cell_middle: where each cell's upper half begins
  std::vector<std::uint32_t> sorted_id_;
  std::vector<Vec4> sorted_position_, sorted_velocity_;  // copied every step
  std::vector<VolumePressure> volume_pressure_;
  std::vector<Mat3> velocity_gradient_;  // sorted; full_stress viscosity only, else empty
  // A particle has ~30 neighbours within h at h = 2 dx, ~35-40 within h + skin (57 the most seen,
  // in the Figure 3 scenes); a list that overflows costs only speed: the next step rebuilds
  // (neighbour_list.hpp).
  static constexpr std::uint32_t kNeighbourCapacity = 64;
  std::vector<std::uint32_t> recorded_count_, recorded_index_;  // the last rebuild's, within h + skin
  // This step's, within h, copied by the density pass from the recorded lists: the force pass visits these.
  std::vector<std::uint32_t> neighbour_count_, neighbour_index_;
  std::vector<Vec4> list_origin_;  // each sorted particle's position at the last rebuild
  // The lists' loops split by cost among the threads, set at each rebuild: the density pass, which
  // copies the entries within h (density_partition_), and the force pass (force_partition_).
  ParticlePartition density_partition_, force_partition_;
  bool rebuild_requested_ = true;  // the next step rebuilds: no lists yet, one overflowed, or positions were set
  std::uint64_t grid_builds_ = 0;
  // Canonical order.
  std::vector<Vec4> interaction_force_;
  std::vector<Vec4> elastic_force_;  // zero outside deformable bodies
  // Per deformable particle.
  std::vector<Quat> rotation_;
  std::vector<Mat3> corrected_stress_action_, deformation_;
  double time_ = 0.0;
  std::array<double, kPhaseCount> phase_seconds_{};
};

}  // namespace mssph::kernels
