// The `cuda` backend: the step's kernels (neighbour_grid, step_kernels, rigid_bodies) captured in
// a CUDA graph and replayed each step (a second graph with events between the phases for when
// phase timing is asked for); the device arrays (device_state) and what the logs and the haptic
// loop read back (body_readback). A scene small
// enough for teams of lanes, or one that asks for lists (team_lanes.hpp), keeps neighbour lists with
// a skin and rebuilds the grid only when they expire (list_skin.hpp), a decision the grid kernel
// takes on the device; its steps read the particles in cell order from one pair of arrays and
// write them for the next step into the other (next_cell_order.cuh), so each graph comes in two
// ways round.
#include "cuda_backend.hpp"

#include "../common/eigen_conversion.hpp"
#include "../common/float_state.hpp"
#include "../common/list_skin.hpp"
#include "../common/read_back.hpp"
#include "../common/team_lanes.hpp"
#include "body_readback.cuh"
#include "cuda_device.cuh"
#include "force_probe.cuh"
#include "neighbour_grid.cuh"
#include "rigid_bodies.cuh"
#include "step_kernels.cuh"

#include <array>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mssph::kernels {
namespace {

// Lanes per particle of the scene's neighbour sums on this GPU (choose_team_lanes).
unsigned team_lanes_for(const ParticleSetup& setup) {
  return choose_team_lanes(setup.size(), resident_threads(), setup.neighbour_lists == NeighbourListUse::always);
}

// The scene in the kernels' form. With teams of lanes (choose_team_lanes), whose lists have a
// skin, the grid's cells are h + skin wide (list_skin.hpp).
FloatScene cuda_scene(const ParticleSetup& setup, unsigned team_lanes) {
  return team_lanes > 1 ? make_float_scene_with_list_cells(setup) : make_float_scene(setup);
}

class CudaBackend final : public Backend {
 public:
  explicit CudaBackend(ParticleSetup setup);
  ~CudaBackend() override;

  BackendInfo info() const override { return {"cuda", device_name_, "float32"}; }
  std::size_t particle_count() const override { return setup_.size(); }
  double time() const override { return time_; }
  void set_external_wrench(std::size_t body, const Eigen::Vector3d& force, const Eigen::Vector3d& torque) override;
  void step() override;
  std::vector<BodyState> body_states() override { return readback_.body_states(state_, stream_); }
  BodyState rigid_body_state(std::size_t body) override {
    return readback_.rigid_body_state(body, movable_rigid_index(scene_, body), stream_);
  }
  ParticleSnapshot snapshot() override;
  std::vector<double> last_phase_seconds() const override;
  void set_phase_timing(bool on) override { phase_timing_ = on; }
  void synchronize() override { cuda_check(cudaStreamSynchronize(stream_), "synchronise"); }
  std::optional<std::uint64_t> neighbour_grid_builds() override;
  std::optional<StepGraphSize> step_graph_size() const override;
  ForceEvaluation evaluate_forces() override;
  void set_particle_positions(const std::vector<Eigen::Vector3d>& positions) override;
  StateArrays save_state() override;
  void restore_state(const StateArrays& state) override;

 private:
  // One step's kernels, captured once and replayed: one launch per step instead of one per kernel.
  struct StepGraph {
    cudaGraph_t graph = nullptr;
    cudaGraphExec_t exec = nullptr;
  };
  StepGraph capture_step(bool timed);
  void swap_cell_orders();
  void record_step(cudaStream_t stream, bool timed);
  void record_neighbour_grid(cudaStream_t stream);
  bool keeps_lists() const { return team_lanes_ > 1; }
  void request_list_rebuild();
  void record_lists_at(const std::vector<Vec4>& origin, bool rebuild_requested);

  ParticleSetup setup_;
  std::string device_name_;
  unsigned team_lanes_ = 1;  // lanes per particle in the neighbour sums (team_lanes_for)
  FloatScene scene_;
  ChunkTables chunks_;
  unsigned deformable_team_lanes_ = 1;  // lanes per deformable particle in its bond sums (choose_bond_team_lanes)
  DeviceState state_;
  BodyReadback readback_;
  std::vector<std::array<Vec3, 2>> external_wrench_;  // per movable rigid body: host copy of F, tau
  std::uint64_t steps_ = 0;

  cudaStream_t stream_ = nullptr;
  // The phases in the order record_step launches them; events_[k], events_[k + 1] enclose the k-th.
  static constexpr std::array<Phase, kPhaseCount> kLaunchOrder{kNeighbours, kDensities, kRotations, kForces,
                                                               kIntegration};
  std::array<cudaEvent_t, kPhaseCount + 1> events_{};
  // Per way round (with lists: way_ reads sorted_*, writes next_sorted_*; the other way the
  // reverse; without lists only way 0): the step alone, and the step with the phase events,
  // which lengthen it (Backend::set_phase_timing).
  std::array<StepGraph, 2> plain_step_;
  std::array<StepGraph, 2> timed_step_;
  std::size_t way_ = 0;
  bool phase_timing_ = false;
  bool last_step_timed_ = false;
  double time_ = 0.0;
};

CudaBackend::CudaBackend(ParticleSetup setup)
    : setup_(std::move(setup)),
      device_name_(require_usable_device()),
      team_lanes_(team_lanes_for(setup_)),
      scene_(cuda_scene(setup_, team_lanes_)),
      chunks_(make_chunk_tables(scene_, setup_.bodies)),
      deformable_team_lanes_(choose_bond_team_lanes(scene_.deformable_body.size(), resident_threads())),
      state_(allocate_device_state(scene_, chunks_, grid_kernel_blocks(setup_.size(), scene_.grid.cell_count()),
                                   team_lanes_, device_name_)),
      readback_(scene_, setup_.bodies, chunks_),
      external_wrench_(scene_.rigid_bodies.size()) {
  cuda_check(cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking), "create stream");
  for (cudaEvent_t& e : events_) cuda_check(cudaEventCreate(&e), "create event");

  for (std::size_t way = 0; way < (keeps_lists() ? 2u : 1u); ++way) {
    plain_step_[way] = capture_step(false);
    timed_step_[way] = capture_step(true);
    if (keeps_lists()) swap_cell_orders();
  }
  cuda_check(cudaStreamSynchronize(stream_), "synchronise after set-up");
}

CudaBackend::~CudaBackend() {
  for (std::array<StepGraph, 2>* graphs : {&plain_step_, &timed_step_}) {
    for (StepGraph& g : *graphs) {
      if (g.exec) cudaGraphExecDestroy(g.exec);
      if (g.graph) cudaGraphDestroy(g.graph);
    }
  }
  for (cudaEvent_t e : events_) {
    if (e) cudaEventDestroy(e);
  }
  if (stream_) cudaStreamDestroy(stream_);
}

CudaBackend::StepGraph CudaBackend::capture_step(bool timed) {
  StepGraph g;
  cuda_check(cudaStreamBeginCapture(stream_, cudaStreamCaptureModeThreadLocal), "begin graph capture");
  record_step(stream_, timed);
  cuda_check(cudaStreamEndCapture(stream_, &g.graph), "end graph capture");
  cuda_check(cudaGraphInstantiate(&g.exec, g.graph, 0), "instantiate step graph");
  return g;
}

// Paper 3.2 as a kernel sequence, one phase of Backend's list each: the neighbour grid (counting
// sort into cells, cell-ordered copies), densities, rotations and elastic forces, forces with the
// leap-frog integration of the particles, rigid-body dynamics. Steps 1 and 2 need only the last
// step's particles, so the rotations, launched after the density pass, run beside it
// (rotation_stress_kernel); the force pass sums beside the elastic one, whose forces only its
// leap-frog reads (forces_kernel). When timed, events between the phases time them and keep them
// apart.
void CudaBackend::record_step(cudaStream_t stream, bool timed) {
  // External event records: the graph's replays record them, so their times can be read after
  // each launch (a plain record during capture only orders the graph's nodes). One before each
  // phase, in kLaunchOrder, and one after the last.
  std::size_t next_event = 0;
  const auto mark = [&] {
    if (timed)
      cuda_check(cudaEventRecordWithFlags(events_[next_event], stream, cudaEventRecordExternal), "record phase event");
    ++next_event;
  };
  mark();
  record_neighbour_grid(stream);
  mark();
  // One lane per particle: the density pass notes each fluid particle's near candidates for the
  // force pass (near_notes.hpp); teams visit their lists instead.
  const NearNotes notes = keeps_lists() ? NearNotes{} : step_near_notes(state_);
  launch_densities(scene_, state_, team_lanes_, notes, stream);
  mark();
  const bool elastic_forces = launch_elasticity(scene_, state_, deformable_team_lanes_, stream);
  mark();
  launch_forces(scene_, state_, team_lanes_, notes, elastic_forces, stream);
  mark();
  launch_rigid_bodies(scene_, chunks_, state_, readback_.rigid_bodies_on_device(), stream);
  mark();
  cuda_check(cudaGetLastError(), "launch step kernels");
}

// The grid: rebuilt every step without lists; with them, only when the check at the step's start
// finds them expired (list_skin.hpp).
void CudaBackend::record_neighbour_grid(cudaStream_t stream) {
  if (keeps_lists()) {
    launch_list_step_grid(state_, scene_.grid, stream);
  } else {
    launch_neighbour_grid(state_, scene_.grid, stream);
  }
}

// The arrays the step just wrote become the ones the next step reads (next_cell_order.cuh); the
// device arrays stay where they are, and the graph of the other way round holds their addresses.
void CudaBackend::swap_cell_orders() {
  std::swap(state_.sorted_position, state_.next_sorted_position);
  std::swap(state_.sorted_velocity, state_.next_sorted_velocity);
  way_ = 1 - way_;
}

// The next step rebuilds the grid and records the lists: the particles were moved from the host.
void CudaBackend::request_list_rebuild() {
  if (!keeps_lists()) return;
  const std::uint32_t requested = 1;
  cuda_check(cudaMemcpy(&state_.list_refresh.data()->requested, &requested, sizeof requested, cudaMemcpyHostToDevice),
             "request a grid rebuild");
}

std::optional<std::uint64_t> CudaBackend::neighbour_grid_builds() {
  if (!keeps_lists()) return std::nullopt;
  synchronize();
  return state_.list_refresh.download().front().rebuilds;
}

// The step's first three phases outside the graph (the grid rebuilt, the lists recorded, with one
// lane per particle the near notes taken, in arrays of the probe's own), then the force sums
// written out in canonical order instead of being integrated.
ForceEvaluation CudaBackend::evaluate_forces() {
  ProbeNearNotes probe_notes(keeps_lists() ? 0 : state_.position.size());
  const NearNotes notes = probe_notes.view();
  launch_neighbour_grid(state_, scene_.grid, stream_);
  launch_elasticity(scene_, state_, deformable_team_lanes_, stream_);
  launch_densities(scene_, state_, team_lanes_, notes, stream_);
  return probe_forces(scene_, state_, notes, stream_);
}

void CudaBackend::set_particle_positions(const std::vector<Eigen::Vector3d>& positions) {
  cuda_check(cudaStreamSynchronize(stream_), "set positions");
  std::vector<Vec4> current = state_.position.download();
  std::vector<Vec4> velocity = state_.velocity.download();
  for (std::size_t i = 0; i < current.size(); ++i) {
    const std::uint32_t kind = scene_.bodies[scene_.body[i]].kind;
    if (kind == kFluid || kind == kDeformable) {
      current[i] = make_vec4(scene_.to_kernel_frame(positions[i]), 0.0f);
      velocity[i].w = 0.0f;  // no carry: the position is a new start (compensated_position.hpp)
    }
  }
  state_.position.upload(current);
  state_.velocity.upload(velocity);
  request_list_rebuild();
}

StateArrays CudaBackend::save_state() {
  cuda_check(cudaStreamSynchronize(stream_), "checkpoint");
  FloatRunState run;
  run.position = state_.position.download();
  run.velocity = state_.velocity.download();
  run.fixed = state_.fixed.download();
  run.rigid_bodies = state_.rigid_bodies.download();
  run.rotation = state_.rotation.download();
  run.time = time_;
  run.steps = steps_;
  if (keeps_lists()) {
    // The positions the last rebuild sorted, and whether the next step rebuilds: asked for, or
    // after the last step's moves (list_check.cuh).
    run.list_origin = state_.list_origin.download();
    const ListRefreshState refresh = state_.list_refresh.download().front();
    run.list_rebuild_requested = refresh.requested != 0 || refresh.moved_far != 0;
  }
  return save_float_state(run);
}

// A restart's lists: the grid rebuilt and the lists recorded where the particles stood at the saved
// run's last rebuild, which gives the same cell order and the same lists, so that the restarted run
// sums as the saved one did (its logs bit-identical to a run left alone).
void CudaBackend::record_lists_at(const std::vector<Vec4>& origin, bool rebuild_requested) {
  state_.position.upload(origin);
  launch_neighbour_grid(state_, scene_.grid, stream_);
  launch_densities(scene_, state_, team_lanes_, NearNotes{}, stream_);
  cuda_check(cudaStreamSynchronize(stream_), "record the restart's lists");
  std::vector<ListRefreshState> refresh = state_.list_refresh.download();
  refresh.front().requested = rebuild_requested ? 1u : 0u;
  state_.list_refresh.upload(refresh);
}

void CudaBackend::restore_state(const StateArrays& saved) {
  const FloatRunState restored = restore_float_state(saved, scene_, keeps_lists());
  cuda_check(cudaStreamSynchronize(stream_), "restore a checkpoint");
  if (keeps_lists()) record_lists_at(restored.list_origin, restored.list_rebuild_requested != 0);
  state_.position.upload(restored.position);
  state_.velocity.upload(restored.velocity);
  state_.fixed.upload(restored.fixed);
  state_.rigid_bodies.upload(restored.rigid_bodies);
  if (keeps_lists()) launch_cell_order_copy(state_, scene_.grid, stream_);
  readback_.set_rigid_bodies(restored.rigid_bodies);
  if (!restored.rotation.empty()) state_.rotation.upload(restored.rotation);
  for (std::size_t b = 0; b < restored.rigid_bodies.size(); ++b) {
    external_wrench_[b] = {restored.rigid_bodies[b].external_force, restored.rigid_bodies[b].external_torque};
  }
  time_ = restored.time;
  steps_ = restored.steps;
}

void CudaBackend::step() {
  cuda_check(cudaGraphLaunch(phase_timing_ ? timed_step_[way_].exec : plain_step_[way_].exec, stream_),
             "launch step graph");
  if (keeps_lists()) swap_cell_orders();
  time_ += setup_.dt;
  ++steps_;
  last_step_timed_ = phase_timing_;
}

// The untimed step's graph: what one launch of step() runs.
std::optional<Backend::StepGraphSize> CudaBackend::step_graph_size() const {
  std::size_t count = 0;
  cuda_check(cudaGraphGetNodes(plain_step_[way_].graph, nullptr, &count), "count the step graph's nodes");
  std::vector<cudaGraphNode_t> nodes(count);
  cuda_check(cudaGraphGetNodes(plain_step_[way_].graph, nodes.data(), &count), "list the step graph's nodes");
  StepGraphSize size{count, 0};
  for (cudaGraphNode_t node : nodes) {
    cudaGraphNodeType type{};
    cuda_check(cudaGraphNodeGetType(node, &type), "read a step graph node's type");
    if (type == cudaGraphNodeTypeKernel) ++size.kernels;
  }
  return size;
}

// NaN for every phase when the last step ran without its events (Backend::set_phase_timing).
std::vector<double> CudaBackend::last_phase_seconds() const {
  std::vector<double> seconds(kPhaseCount, std::numeric_limits<double>::quiet_NaN());
  if (!last_step_timed_) return seconds;
  cuda_check(cudaEventSynchronize(events_[kPhaseCount]), "wait for the step");
  for (std::size_t k = 0; k < kPhaseCount; ++k) {
    float ms = 0.0f;
    cuda_check(cudaEventElapsedTime(&ms, events_[k], events_[k + 1]), "read phase time");
    seconds[kLaunchOrder[k]] = 1e-3 * ms;
  }
  return seconds;
}

void CudaBackend::set_external_wrench(std::size_t body, const Eigen::Vector3d& force, const Eigen::Vector3d& torque) {
  const std::uint32_t index = movable_rigid_index(scene_, body);
  // external_force and external_torque are adjacent members: one small copy, ordered in the
  // stream before the next step; its host source lives in the backend.
  std::array<Vec3, 2>& wrench = external_wrench_[index];
  wrench = {to_vec3(force), to_vec3(torque)};
  static_assert(offsetof(RigidBody, external_torque) == offsetof(RigidBody, external_force) + sizeof(Vec3));
  cuda_check(
      cudaMemcpyAsync(reinterpret_cast<char*>(state_.rigid_bodies.data() + index) + offsetof(RigidBody, external_force),
                      wrench.data(), sizeof wrench, cudaMemcpyHostToDevice, stream_),
      "upload external wrench");
}

ParticleSnapshot CudaBackend::snapshot() {
  cuda_check(cudaStreamSynchronize(stream_), "snapshot");
  const std::vector<Vec4> position = state_.position.download();
  const std::vector<Vec4> velocity = state_.velocity.download();
  const std::vector<VolumePressure> vp = state_.volume_pressure.download();
  const std::vector<std::uint32_t> id = state_.sorted_id.download();
  const std::size_t n = position.size();
  ParticleSnapshot out;
  out.position.reserve(3 * n);
  out.velocity.reserve(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d world = scene_.to_world(xyz(position[i]));
    out.position.insert(out.position.end(),
                        {static_cast<float>(world.x()), static_cast<float>(world.y()), static_cast<float>(world.z())});
    out.velocity.insert(out.velocity.end(), {velocity[i].x, velocity[i].y, velocity[i].z});
  }
  // Densities and pressures of the last force evaluation, back in canonical order.
  out.density.assign(n, 0.0f);
  out.pressure.assign(n, 0.0f);
  if (steps_ > 0) {
    for (std::size_t s = 0; s < n; ++s) {
      const std::uint32_t i = id[s];
      out.density[i] = particle_density(scene_, i, vp[s]);
      out.pressure[i] = vp[s].pressure;
    }
  }
  return out;
}

}  // namespace

std::size_t cuda_backend_bytes(const ParticleSetup& setup) {
  const unsigned team_lanes = team_lanes_for(setup);
  const FloatScene scene = cuda_scene(setup, team_lanes);
  return device_array_sizes(scene, make_chunk_tables(scene, setup.bodies),
                            grid_kernel_blocks(setup.size(), scene.grid.cell_count()), team_lanes)
      .total_bytes;
}

std::unique_ptr<Backend> make_cuda_backend(ParticleSetup setup) {
  return std::make_unique<CudaBackend>(std::move(setup));
}

}  // namespace mssph::kernels
