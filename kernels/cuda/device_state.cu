#include "device_state.cuh"

#include "util/errors.hpp"

#include <sstream>

namespace mssph::kernels {
namespace {

std::string describe_bytes(std::size_t bytes) {
  std::ostringstream out;
  out.precision(3);
  out << static_cast<double>(bytes) / (1024.0 * 1024.0) << " MiB";
  return out.str();
}

// The visitor of for_each_device_array that allocates each array and gives it its first contents.
struct Allocate {
  template <class T>
  void operator()(const char* name, DeviceBuffer<T>& array, const CopyOf<T>& contents) const {
    array = allocate<T>(name, contents.count);
    if (contents.count > 0) array.upload(*contents.host);
  }
  template <class T>
  void operator()(const char* name, DeviceBuffer<T>& array, const Filled<T>& contents) const {
    array = allocate<T>(name, contents.count);
    if (contents.count > 0) array.upload(std::vector<T>(contents.count, contents.value));
  }
  template <class T>
  void operator()(const char* name, DeviceBuffer<T>& array, const Uninitialised& contents) const {
    array = allocate<T>(name, contents.count);
  }

  template <class T>
  static DeviceBuffer<T> allocate(const char* name, std::size_t count) {
    try {
      return DeviceBuffer<T>(count);
    } catch (const CudaError& e) {
      throw CudaError(std::string(e.what()) + " (array " + name + ", " + describe_bytes(count * sizeof(T)) + ")");
    }
  }
};

}  // namespace

DeviceState allocate_device_state(const FloatScene& scene, const ChunkTables& chunks, std::size_t grid_blocks,
                                  unsigned team_lanes, const std::string& device_name) {
  const std::size_t needed = device_array_sizes(scene, chunks, grid_blocks, team_lanes).total_bytes;
  std::size_t free_bytes = 0;
  std::size_t total_bytes = 0;
  cuda_check(cudaMemGetInfo(&free_bytes, &total_bytes), "read free device memory");
  if (needed > free_bytes) {
    throw InputError("the scene does not fit on " + device_name + ": " + std::to_string(scene.position.size()) +
                     " particles need " + describe_bytes(needed) + " of device memory, " + describe_bytes(free_bytes) +
                     " of " + describe_bytes(total_bytes) + " are free");
  }
  DeviceState state;
  for_each_device_array(state, scene, chunks, grid_blocks, team_lanes, Allocate{});
  return state;
}

// cell_body and own_rest_number_density are empty, so null, in a scene of fluid alone;
// velocity_gradient unless the viscosity is full_stress.
SortedView sorted_view(const FloatScene& scene, const DeviceState& state) {
  return SortedView{scene.step,
                    state.bodies.data(),
                    CellRanges{scene.grid, state.cell_start.data(), state.cell_body.data(), state.cell_middle.data()},
                    state.sorted_position.data(),
                    state.sorted_velocity.data(),
                    state.sorted_id.data(),
                    state.volume_pressure.data(),
                    state.own_rest_number_density.data(),
                    state.velocity_gradient.data()};
}

NeighbourLists team_lists(DeviceState& state, unsigned team_lanes) {
  return lane_lists(team_list_capacity(team_lanes), static_cast<std::uint32_t>(state.list_count.size()),
                    state.list_count.data(), state.list_index.data());
}

// elastic_force is empty, so null, without deformable bodies.
CanonicalState canonical_state(DeviceState& state) {
  return CanonicalState{state.position.data(), state.velocity.data(), state.interaction_force.data(),
                        state.elastic_force.data(), state.fixed.data()};
}

ForceWalks force_walks(DeviceState& state) {
  return ForceWalks{state.force_walk.data(), state.contact_order.data(), state.contact_taken.data(),
                    static_cast<std::uint32_t>(state.contact_order.size())};
}

// A fluid particle's canonical velocity and interaction force hold nothing from the density pass
// to the force pass's store: the grid kernel has copied the velocity into cell order, and the force
// pass writes both for every fluid particle (store_advance: fluid particles always integrate), in
// the thread that read the particle's notes, after reading them; the bond passes, which may run
// while the density pass writes notes, read deformable particles' velocities only. The grid's keys
// and unordered ids are read only inside the grid kernel.
NearNotes step_near_notes(DeviceState& state) {
  return NearNotes{state.velocity.data(), state.interaction_force.data(), reinterpret_cast<float*>(state.keys.data()),
                   reinterpret_cast<float*>(state.unordered_id.data())};
}

DeviceDeformableView deformable_view(const FloatScene& scene, DeviceState& state) {
  const auto count = static_cast<std::uint32_t>(state.deformable_body.size());
  return DeviceDeformableView{state.elastic_bodies.data(),
                              state.deformable_body.data(),
                              state.bond_count.data(),
                              state.bond_neighbour.data(),
                              state.rest.data(),
                              state.correction.data(),
                              scene.step.smoothing,
                              state.position.data(),
                              state.velocity.data(),
                              state.rotation.data(),
                              Mat3Planes{state.corrected_stress_action.data(), count},
                              state.deformation.data(),
                              state.elastic_force.data(),
                              count};
}

}  // namespace mssph::kernels
