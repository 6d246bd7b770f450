#include "cuda_backend.hpp"

#include "../common/elastic_physics.hpp"
#include "../common/float_scene.hpp"
#include "../common/fluid_physics.hpp"
#include "cuda_check.hpp"
#include "device_buffer.hpp"
#include "util/errors.hpp"

#include <cub/cub.cuh>

#include <array>
#include <cstring>
#include <sstream>
#include <type_traits>

namespace mssph::kernels {
namespace {

constexpr int kBlock = 256;

unsigned blocks_for(std::size_t n) { return static_cast<unsigned>((n + kBlock - 1) / kBlock); }

// ---- Kernels: each is a thin loop around one of the shared per-particle functions. ----

// The neighbour grid by a counting sort, stable like a sort of (key, index) pairs (the cpu
// backend's order), so every run lays the particles out alike. Four kernels and a CUB scan:
// 1. each particle's cell key, and a count per cell (integer atomics: the counts, not their
//    order, are kept);
// 2. an exclusive scan of the counts: the cell table, cell_start[k] = particles in cells below k;
// 3. each particle takes a slot in its cell's range (atomically, in no fixed order) and gives
//    back its count, so the counts are zero again for the next step; then
// 4. one thread per cell sorts its few slots by particle index (insertion sort), which makes
//    the order within a cell canonical; then one thread per particle copies it into cell order.
__global__ void cell_count_kernel(const Vec4* position, std::uint32_t n, GridShape grid, std::uint32_t* keys,
                                  std::uint32_t* cell_count) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  const std::uint32_t key = grid.key_of(xyz(position[i]));
  keys[i] = key;
  atomicAdd(&cell_count[key], 1u);
}

__global__ void cell_slot_kernel(const std::uint32_t* keys, std::uint32_t n, const std::uint32_t* cell_start,
                                 std::uint32_t* cell_count, std::uint32_t* sorted_id) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  const std::uint32_t key = keys[i];
  sorted_id[cell_start[key] + atomicSub(&cell_count[key], 1u) - 1u] = i;
}

__global__ void cell_sort_kernel(std::uint32_t cells, const std::uint32_t* cell_start, std::uint32_t* sorted_id) {
  const std::uint32_t k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= cells) return;
  const std::uint32_t first = cell_start[k];
  const std::uint32_t end = cell_start[k + 1];
  for (std::uint32_t s = first + 1; s < end; ++s) {
    const std::uint32_t id = sorted_id[s];
    std::uint32_t t = s;
    for (; t > first && sorted_id[t - 1] > id; --t) sorted_id[t] = sorted_id[t - 1];
    sorted_id[t] = id;
  }
}

__global__ void cell_order_kernel(std::uint32_t n, const std::uint32_t* sorted_id, const Vec4* position,
                                  const Vec4* velocity, const std::uint32_t* body, Vec4* sorted_position,
                                  Vec4* sorted_velocity) {
  const std::uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
  if (s < n) place_in_cell_order(s, sorted_id, position, velocity, body, sorted_position, sorted_velocity);
}

// For comparisons: the pressure and viscosity sums of every sorted particle, not integrated.
__global__ void force_probe_kernel(SortedView view, ForceSum* forces) {
  const std::uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
  if (s < view.step.particle_count) forces[s] = force_sum(view, load_force_particle(view, s), 0, 1);
}

__global__ void rotation_stress_kernel(DeformableView view) {
  const std::uint32_t d = blockIdx.x * blockDim.x + threadIdx.x;
  if (d < view.count) rotation_and_stress(view, d);
}

__global__ void elastic_force_kernel(DeformableView view) {
  const std::uint32_t d = blockIdx.x * blockDim.x + threadIdx.x;
  if (d < view.count) elastic_force(view, d);
}

// The neighbour sums give each particle a team of Lanes consecutive lanes of a warp (1 to 8,
// see choose_team_lanes): the lanes split its candidates (CellRanges::for_each_candidate) and add
// their partial sums by shuffles in a fixed order, so a sum's order depends only on Lanes.
template <unsigned Lanes>
__device__ float team_sum(float x) {
  for (unsigned offset = 1; offset < Lanes; offset *= 2) x += __shfl_xor_sync(0xffffffffu, x, offset);
  return x;
}
template <unsigned Lanes>
__device__ Vec3 team_sum(Vec3 v) {
  return {team_sum<Lanes>(v.x), team_sum<Lanes>(v.y), team_sum<Lanes>(v.z)};
}

template <unsigned Lanes>
__global__ void density_kernel(SortedView view, VolumePressure* volume_pressure) {
  const std::uint32_t thread = blockIdx.x * blockDim.x + threadIdx.x;
  const std::uint32_t s = thread / Lanes;
  const unsigned lane = thread % Lanes;
  const bool active = s < view.step.particle_count;
  DensitySum sum{0.0f};
  if (active) sum = density_sum(view, s, lane, Lanes);
  sum.delta = team_sum<Lanes>(sum.delta);
  if (active && lane == 0) volume_pressure[s] = density_from(sum, view, s).volume_pressure;
}

template <unsigned Lanes>
__global__ void forces_kernel(SortedView view, CanonicalState state) {
  const std::uint32_t thread = blockIdx.x * blockDim.x + threadIdx.x;
  const std::uint32_t s = thread / Lanes;
  const unsigned lane = thread % Lanes;
  const bool active = s < view.step.particle_count;
  ForceSum sum = zero_force_sum();
  if (active) sum = force_sum(view, load_force_particle(view, s), lane, Lanes);
  sum = {team_sum<Lanes>(sum.pressure), team_sum<Lanes>(sum.viscosity), team_sum<Lanes>(sum.interaction)};
  if (active && lane == 0) apply_forces(view, state, s, sum);
}

// Lanes per particle: the most (up to 8) that keep n * lanes within two waves of resident
// threads. A small scene then has ~8x the threads in flight; a scene that fills the GPU on its
// own keeps one lane per particle, which wastes no shuffles.
unsigned choose_team_lanes(std::size_t particles, std::size_t resident_threads) {
  unsigned lanes = 8;
  while (lanes > 1 && particles * lanes > 2 * resident_threads) lanes /= 2;
  return lanes;
}

// Calls launch(std::integral_constant<unsigned, L>) for the team size L = lanes, so each launch
// site names its kernel once.
template <class Launch>
void with_team_lanes(unsigned lanes, Launch&& launch) {
  switch (lanes) {
    case 8: launch(std::integral_constant<unsigned, 8>{}); break;
    case 4: launch(std::integral_constant<unsigned, 4>{}); break;
    case 2: launch(std::integral_constant<unsigned, 2>{}); break;
    default: launch(std::integral_constant<unsigned, 1>{}); break;
  }
}


struct WrenchSum {
  __device__ Wrench operator()(const Wrench& a, const Wrench& b) const { return a + b; }
};

// Rigid bodies are cut into chunks of at most kChunk particles, so a body of a million particles
// is summed by many blocks. Every sum runs in a fixed order (strided per thread, CUB's block tree,
// then the chunks in order): no atomics, so runs repeat bit for bit.
constexpr std::uint32_t kChunk = 4096;

struct RigidChunk {
  std::uint32_t rigid;  // index of the rigid body
  std::uint32_t first;  // canonical particle range
  std::uint32_t count;
};

// One block per chunk: the wrench of its particles' interaction forces about the body's centre.
// The block that finishes a body's last chunk (a ticket counter tells) then adds the body's chunk
// wrenches in chunk order and integrates the body (eq. 8, 9): which block does it varies, the sum's
// order does not, so runs repeat bit for bit.
__global__ void rigid_wrench_integrate_kernel(const RigidChunk* chunks, RigidBody* bodies, CanonicalState state,
                                              Wrench* partial, const std::uint32_t* first_chunk,
                                              std::uint32_t* tickets, StepParameters step) {
  using BlockReduce = cub::BlockReduce<Wrench, kBlock>;
  __shared__ typename BlockReduce::TempStorage reduce_storage;
  __shared__ bool last;
  const RigidChunk chunk = chunks[blockIdx.x];
  const Vec3 centre = bodies[chunk.rigid].position;
  Wrench wrench{{0, 0, 0}, {0, 0, 0}};
  for (std::uint32_t i = chunk.first + threadIdx.x; i < chunk.first + chunk.count; i += blockDim.x) {
    wrench = wrench + particle_wrench(xyz(state.position[i]), xyz(state.interaction_force[i]), centre);
  }
  const Wrench total = BlockReduce(reduce_storage).Reduce(wrench, WrenchSum());
  if (threadIdx.x == 0) {
    partial[blockIdx.x] = total;
    __threadfence();  // the partial is visible before the ticket is taken
    const std::uint32_t chunks_of_body = first_chunk[chunk.rigid + 1] - first_chunk[chunk.rigid];
    last = atomicAdd(&tickets[chunk.rigid], 1u) + 1u == chunks_of_body;
  }
  __syncthreads();
  if (!last || threadIdx.x != 0) return;
  __threadfence();
  tickets[chunk.rigid] = 0;  // ready for the next step
  Wrench sum{{0, 0, 0}, {0, 0, 0}};
  for (std::uint32_t c = first_chunk[chunk.rigid]; c < first_chunk[chunk.rigid + 1]; ++c) {
    // Loaded from L2 (other blocks wrote them; this block's L1 may not hold them yet).
    const float* w = reinterpret_cast<const float*>(partial + c);
    sum = sum + Wrench{{__ldcg(w), __ldcg(w + 1), __ldcg(w + 2)}, {__ldcg(w + 3), __ldcg(w + 4), __ldcg(w + 5)}};
  }
  RigidBody body = bodies[chunk.rigid];
  body.interaction_force = sum.force;
  body.interaction_torque = sum.torque;
  integrate_rigid_body(body, step.gravity, step.dt);
  bodies[chunk.rigid] = body;
}

// One block per chunk: its particles follow the body.
__global__ void rigid_place_kernel(const RigidChunk* chunks, const RigidBody* bodies, CanonicalState state,
                                   const Vec4* rest_offset) {
  __shared__ RigidBody body;
  __shared__ Mat3 rotation;
  __shared__ Vec3 omega;
  const RigidChunk chunk = chunks[blockIdx.x];
  if (threadIdx.x == 0) {
    body = bodies[chunk.rigid];
    rotation = rotation_matrix(body.orientation);
    omega = angular_velocity(body);
  }
  __syncthreads();
  for (std::uint32_t i = chunk.first + threadIdx.x; i < chunk.first + chunk.count; i += blockDim.x) {
    place_rigid_particle(body, rotation, omega, xyz(rest_offset[i]), state.position[i], state.velocity[i]);
  }
}

struct BodySumsCombine {
  __device__ BodySums operator()(const BodySums& a, const BodySums& b) const { return combine(a, b); }
};

constexpr std::uint32_t kNotDeformable = 0xffffffffu;

// A run of at most kChunk particles of one body (any kind), for the logged per-body sums.
struct BodyChunk {
  std::uint32_t body;
  std::uint32_t first;
  std::uint32_t count;
  std::uint32_t first_deformable;   // deformable index of particle `first`, else kNotDeformable
  float lowest_valid_volume_ratio;  // deformable bodies: the model's lowest valid det F
};

// One block per chunk: partial sums behind the logged body states; the host adds a body's chunks
// in order.
__global__ void body_sums_kernel(const BodyChunk* chunks, const BodyParameters* bodies, CanonicalState state,
                                 const Mat3* deformation, BodySums* partial) {
  using BlockReduce = cub::BlockReduce<BodySums, kBlock>;
  __shared__ typename BlockReduce::TempStorage reduce_storage;
  const BodyChunk chunk = chunks[blockIdx.x];
  const float mass = bodies[chunk.body].sph_mass;
  BodySums acc = zero_body_sums();
  for (std::uint32_t i = chunk.first + threadIdx.x; i < chunk.first + chunk.count; i += blockDim.x) {
    add_particle(acc, xyz(state.position[i]), xyz(state.velocity[i]), mass, xyz(state.interaction_force[i]));
    if (chunk.first_deformable != kNotDeformable) {
      add_volume_ratio(acc, determinant(deformation[chunk.first_deformable + (i - chunk.first)]),
                       chunk.lowest_valid_volume_ratio);
    }
  }
  const BodySums total = BlockReduce(reduce_storage).Reduce(acc, BodySumsCombine());
  if (threadIdx.x == 0) partial[blockIdx.x] = total;
}

std::string describe_bytes(std::size_t bytes) {
  std::ostringstream out;
  out.precision(3);
  out << static_cast<double>(bytes) / (1024.0 * 1024.0) << " MiB";
  return out.str();
}

// ---- The backend ----

class CudaBackend final : public Backend {
 public:
  explicit CudaBackend(ParticleSetup setup);
  ~CudaBackend() override;

  BackendInfo info() const override { return {"cuda", device_name_, "float32"}; }
  std::size_t particle_count() const override { return setup_.size(); }
  double time() const override { return time_; }
  void set_external_wrench(std::size_t body, const Eigen::Vector3d& force, const Eigen::Vector3d& torque) override;
  void step() override;
  std::vector<BodyState> body_states() override;
  BodyState rigid_body_state(std::size_t body) override;
  ParticleSnapshot snapshot() override;
  std::vector<double> last_phase_seconds() const override;
  void synchronize() override { cuda_check(cudaStreamSynchronize(stream_), "synchronise"); }
  ForceEvaluation evaluate_forces() override;
  void set_particle_positions(const std::vector<Eigen::Vector3d>& positions) override;

 private:
  void record_step(cudaStream_t stream);
  void launch_grid(cudaStream_t stream);
  void launch_elasticity(cudaStream_t stream);
  void launch_density(cudaStream_t stream);
  SortedView sorted_view() const;
  CanonicalState canonical_state();
  DeformableView deformable_view();
  std::uint32_t rigid_index(std::size_t body) const;

  ParticleSetup setup_;
  FloatScene scene_;
  std::string device_name_;
  std::uint32_t n_;
  std::vector<float> rigid_reach_;  // per movable rigid body: max |r0| over its particles [m]
  std::vector<std::array<Vec3, 2>> external_wrench_;  // per movable rigid body: host copy of F, tau

  // Canonical state.
  DeviceBuffer<Vec4> position_, velocity_, interaction_force_, elastic_force_, rest_offset_;
  DeviceBuffer<std::uint32_t> body_;
  DeviceBuffer<std::uint8_t> fixed_;
  // Grid and cell-ordered copies.
  DeviceBuffer<std::uint32_t> keys_, sorted_id_, cell_count_, cell_start_;
  DeviceBuffer<Vec4> sorted_position_, sorted_velocity_;
  DeviceBuffer<VolumePressure> volume_pressure_;
  DeviceBuffer<unsigned char> scan_storage_;
  std::size_t scan_storage_bytes_ = 0;
  // Deformable bodies.
  std::uint32_t deformables_ = 0;
  DeviceBuffer<ElasticParameters> elastic_bodies_;
  DeviceBuffer<std::uint32_t> deformable_body_, bond_start_;
  DeviceBuffer<RestBond> bonds_;
  DeviceBuffer<float> rest_volume_;
  DeviceBuffer<Quat> rotation_;
  DeviceBuffer<Mat3> stress_action_, deformation_;
  // Bodies.
  DeviceBuffer<BodyParameters> bodies_;
  DeviceBuffer<RigidBody> rigid_bodies_;
  DeviceBuffer<RigidChunk> rigid_chunks_;
  DeviceBuffer<std::uint32_t> first_chunk_;  // per rigid body, plus the end
  DeviceBuffer<Wrench> chunk_wrench_;
  DeviceBuffer<std::uint32_t> rigid_tickets_;  // per rigid body: chunks done this step
  std::vector<BodyChunk> body_chunks_host_;
  DeviceBuffer<BodyChunk> body_chunks_;
  // What a logged sample reads back, in one allocation so that it comes back in one copy: the
  // body-sum partials of every chunk, then a copy of the rigid bodies' states.
  DeviceBuffer<unsigned char> readback_;
  std::size_t readback_rigid_offset_ = 0;
  BodySums* readback_sums() { return reinterpret_cast<BodySums*>(readback_.data()); }
  RigidBody* readback_rigid() { return reinterpret_cast<RigidBody*>(readback_.data() + readback_rigid_offset_); }
  std::vector<RigidBody> rigid_host_;     // the rigid bodies as last read back...
  std::uint64_t rigid_host_step_ = ~0ull;  // ...after this many steps
  std::uint64_t steps_ = 0;

  cudaStream_t stream_ = nullptr;
  cudaGraph_t graph_ = nullptr;
  cudaGraphExec_t graph_exec_ = nullptr;
  std::array<cudaEvent_t, kPhaseCount + 1> events_{};
  unsigned team_lanes_ = 1;  // lanes per particle in the neighbour sums (choose_team_lanes)
  double time_ = 0.0;
  bool stepped_ = false;
};

// Temporary storage of the cell table's scan over cells + 1 counts.
std::size_t scan_temp_bytes(std::uint32_t cells) {
  std::size_t bytes = 0;
  cuda_check(cub::DeviceScan::ExclusiveSum(nullptr, bytes, static_cast<const std::uint32_t*>(nullptr),
                                           static_cast<std::uint32_t*>(nullptr), cells + 1),
             "size the cell-table scan");
  return bytes;
}

void require_usable_device(std::string& name) {
  int count = 0;
  const cudaError_t status = cudaGetDeviceCount(&count);
  if (status != cudaSuccess || count == 0) {
    throw InputError(std::string("--backend cuda: no CUDA device is available (") +
                     (status != cudaSuccess ? cudaGetErrorString(status) : "no GPU found") +
                     "); use --backend cpu or --backend auto");
  }
  cudaDeviceProp properties{};
  cuda_check(cudaGetDeviceProperties(&properties, 0), "read device properties");
  name = properties.name;
  cudaFuncAttributes attributes{};
  const cudaError_t image = cudaFuncGetAttributes(&attributes, density_kernel<1>);
  if (image != cudaSuccess) {
    cudaGetLastError();  // clear the sticky error of the failed query
    throw InputError("--backend cuda: the GPU " + name + " (compute capability " + std::to_string(properties.major) +
                     "." + std::to_string(properties.minor) + ") is not supported by this build (CUDA architectures " +
                     MSSPH_CUDA_ARCHITECTURES_TEXT + "): rebuild with -DCMAKE_CUDA_ARCHITECTURES=" +
                     std::to_string(properties.major) + std::to_string(properties.minor));
  }
}

// Where the rigid bodies start in the read-back buffer: after the chunk sums, 16-byte aligned.
std::size_t readback_rigid_offset(std::size_t body_chunks) { return (body_chunks * sizeof(BodySums) + 15) / 16 * 16; }

// Every device allocation the backend makes for a scene.
std::size_t scene_bytes(const FloatScene& scene, std::size_t scan_bytes) {
  const std::size_t n = scene.position.size();
  const std::size_t canonical = 4 * sizeof(Vec4) + sizeof(std::uint32_t) + sizeof(std::uint8_t);
  const std::size_t grid = 2 * sizeof(std::uint32_t) + 2 * sizeof(Vec4) + sizeof(VolumePressure);
  const std::size_t cells = 2 * (std::size_t{scene.grid.cell_count()} + 1) * sizeof(std::uint32_t);
  const std::size_t rigid_chunks = n / kChunk + scene.rigid_bodies.size();
  const std::size_t body_chunks = n / kChunk + scene.bodies.size();
  const std::size_t bodies = scene.bodies.size() * sizeof(BodyParameters) + body_chunks * (sizeof(BodyChunk) + sizeof(BodySums)) +
                             scene.rigid_bodies.size() * (2 * sizeof(RigidBody) + sizeof(std::uint32_t)) + 16 +
                             rigid_chunks * (sizeof(RigidChunk) + sizeof(Wrench));
  const std::size_t deformable = scene.deformable_body.empty()
                                     ? 0
                                     : n * sizeof(Vec4) + scene.bonds.size() * sizeof(RestBond) +
                                           scene.deformable_body.size() * (2 * sizeof(std::uint32_t) + sizeof(float) +
                                                                           sizeof(Quat) + 2 * sizeof(Mat3));
  return n * (canonical + grid) + cells + bodies + deformable + scan_bytes;
}

CudaBackend::CudaBackend(ParticleSetup setup)
    : setup_(std::move(setup)), scene_(make_float_scene(setup_)), n_(static_cast<std::uint32_t>(setup_.size())) {
  require_usable_device(device_name_);
  scan_storage_bytes_ = scan_temp_bytes(scene_.grid.cell_count());
  const std::size_t needed = scene_bytes(scene_, scan_storage_bytes_);
  std::size_t free_bytes = 0;
  std::size_t total_bytes = 0;
  cuda_check(cudaMemGetInfo(&free_bytes, &total_bytes), "read free device memory");
  if (needed > free_bytes) {
    throw InputError("the scene does not fit on " + device_name_ + ": " + std::to_string(n_) + " particles need " +
                     describe_bytes(needed) + " of device memory, " + describe_bytes(free_bytes) + " of " +
                     describe_bytes(total_bytes) + " are free");
  }

  position_ = DeviceBuffer<Vec4>(scene_.position);
  velocity_ = DeviceBuffer<Vec4>(scene_.velocity);
  interaction_force_ = DeviceBuffer<Vec4>(std::vector<Vec4>(n_, Vec4{0, 0, 0, 0}));
  rest_offset_ = DeviceBuffer<Vec4>(scene_.rest_offset);
  deformables_ = static_cast<std::uint32_t>(scene_.deformable_body.size());
  if (deformables_ > 0) {
    elastic_force_ = DeviceBuffer<Vec4>(std::vector<Vec4>(n_, Vec4{0, 0, 0, 0}));
    elastic_bodies_ = DeviceBuffer<ElasticParameters>(scene_.elastic_bodies);
    deformable_body_ = DeviceBuffer<std::uint32_t>(scene_.deformable_body);
    bond_start_ = DeviceBuffer<std::uint32_t>(scene_.bond_start);
    bonds_ = DeviceBuffer<RestBond>(scene_.bonds);
    rest_volume_ = DeviceBuffer<float>(scene_.rest_volume);
    rotation_ = DeviceBuffer<Quat>(std::vector<Quat>(deformables_, Quat{0, 0, 0, 1}));
    stress_action_ = DeviceBuffer<Mat3>(deformables_);
    // Identity until the first step: the logged volume ratio of the rest state is 1.
    deformation_ = DeviceBuffer<Mat3>(std::vector<Mat3>(deformables_, identity_mat3()));
  }
  body_ = DeviceBuffer<std::uint32_t>(scene_.body);
  fixed_ = DeviceBuffer<std::uint8_t>(scene_.fixed);
  keys_ = DeviceBuffer<std::uint32_t>(n_);
  sorted_id_ = DeviceBuffer<std::uint32_t>(n_);
  cell_count_ = DeviceBuffer<std::uint32_t>(std::vector<std::uint32_t>(std::size_t{scene_.grid.cell_count()} + 1, 0u));
  cell_start_ = DeviceBuffer<std::uint32_t>(std::size_t{scene_.grid.cell_count()} + 1);
  sorted_position_ = DeviceBuffer<Vec4>(n_);
  sorted_velocity_ = DeviceBuffer<Vec4>(n_);
  volume_pressure_ = DeviceBuffer<VolumePressure>(std::vector<VolumePressure>(n_, VolumePressure{0, 0}));
  scan_storage_ = DeviceBuffer<unsigned char>(scan_storage_bytes_);
  bodies_ = DeviceBuffer<BodyParameters>(scene_.bodies);
  rigid_bodies_ = DeviceBuffer<RigidBody>(scene_.rigid_bodies);
  std::vector<RigidChunk> chunks;
  std::vector<std::uint32_t> first_chunk;
  for (std::uint32_t r = 0; r < scene_.rigid_bodies.size(); ++r) {
    first_chunk.push_back(static_cast<std::uint32_t>(chunks.size()));
    const RigidBody& body = scene_.rigid_bodies[r];
    for (std::uint32_t first = body.first; first < body.first + body.count; first += kChunk) {
      chunks.push_back({r, first, std::min(kChunk, body.first + body.count - first)});
    }
  }
  first_chunk.push_back(static_cast<std::uint32_t>(chunks.size()));
  rigid_chunks_ = DeviceBuffer<RigidChunk>(chunks);
  first_chunk_ = DeviceBuffer<std::uint32_t>(first_chunk);
  chunk_wrench_ = DeviceBuffer<Wrench>(chunks.size());
  rigid_tickets_ = DeviceBuffer<std::uint32_t>(std::vector<std::uint32_t>(scene_.rigid_bodies.size(), 0));
  for (std::uint32_t b = 0; b < setup_.bodies.size(); ++b) {
    const auto first = static_cast<std::uint32_t>(setup_.bodies[b].first);
    const auto end = first + static_cast<std::uint32_t>(setup_.bodies[b].count);
    const ElasticParameters* elastic = nullptr;
    for (const ElasticParameters& e : scene_.elastic_bodies) {
      if (e.first_particle == first && setup_.bodies[b].kind == BodyKind::deformable) elastic = &e;
    }
    for (std::uint32_t f = first; f < end; f += kChunk) {
      body_chunks_host_.push_back({b, f, std::min(kChunk, end - f),
                                   elastic ? elastic->first_deformable + (f - first) : kNotDeformable,
                                   elastic ? elastic->lowest_valid_volume_ratio : 0.0f});
    }
  }
  body_chunks_ = DeviceBuffer<BodyChunk>(body_chunks_host_);
  readback_rigid_offset_ = readback_rigid_offset(body_chunks_host_.size());
  readback_ = DeviceBuffer<unsigned char>(readback_rigid_offset_ + scene_.rigid_bodies.size() * sizeof(RigidBody));
  for (const RigidBody& r : scene_.rigid_bodies) {
    float reach = 0.0f;
    for (std::uint32_t i = r.first; i < r.first + r.count; ++i) reach = std::max(reach, norm(xyz(scene_.rest_offset[i])));
    rigid_reach_.push_back(reach);
  }
  external_wrench_.resize(scene_.rigid_bodies.size());

  cudaDeviceProp properties{};
  cuda_check(cudaGetDeviceProperties(&properties, 0), "read device properties");
  const std::size_t resident_threads =
      static_cast<std::size_t>(properties.multiProcessorCount) * static_cast<std::size_t>(properties.maxThreadsPerMultiProcessor);
  team_lanes_ = choose_team_lanes(n_, resident_threads);

  cuda_check(cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking), "create stream");
  for (cudaEvent_t& e : events_) cuda_check(cudaEventCreate(&e), "create event");

  // The whole step is captured once and replayed: one launch per step instead of one per kernel.
  cuda_check(cudaStreamBeginCapture(stream_, cudaStreamCaptureModeThreadLocal), "begin graph capture");
  record_step(stream_);
  cuda_check(cudaStreamEndCapture(stream_, &graph_), "end graph capture");
  cuda_check(cudaGraphInstantiate(&graph_exec_, graph_, 0), "instantiate step graph");
  cuda_check(cudaStreamSynchronize(stream_), "synchronise after set-up");
}

CudaBackend::~CudaBackend() {
  if (graph_exec_) cudaGraphExecDestroy(graph_exec_);
  if (graph_) cudaGraphDestroy(graph_);
  for (cudaEvent_t e : events_) {
    if (e) cudaEventDestroy(e);
  }
  if (stream_) cudaStreamDestroy(stream_);
}

SortedView CudaBackend::sorted_view() const {
  return SortedView{scene_.step,
                    bodies_.data(),
                    CellRanges{scene_.grid, cell_start_.data()},
                    sorted_position_.data(),
                    sorted_velocity_.data(),
                    sorted_id_.data(),
                    volume_pressure_.data()};
}

CanonicalState CudaBackend::canonical_state() {
  return CanonicalState{position_.data(), velocity_.data(), interaction_force_.data(),
                        deformables_ > 0 ? elastic_force_.data() : nullptr, body_.data(), fixed_.data()};
}

DeformableView CudaBackend::deformable_view() {
  return DeformableView{elastic_bodies_.data(), deformable_body_.data(), bond_start_.data(), bonds_.data(),
                        rest_volume_.data(),    position_.data(),        velocity_.data(),   rotation_.data(),
                        stress_action_.data(),  deformation_.data(),     elastic_force_.data(), deformables_};
}

// The neighbour grid: counts per cell, their scan (the cell table), slots, the order within each
// cell, cell-ordered copies (see cell_count_kernel).
void CudaBackend::launch_grid(cudaStream_t stream) {
  const std::uint32_t cells = scene_.grid.cell_count();
  cell_count_kernel<<<blocks_for(n_), kBlock, 0, stream>>>(position_.data(), n_, scene_.grid, keys_.data(), cell_count_.data());
  cuda_check(cub::DeviceScan::ExclusiveSum(scan_storage_.data(), scan_storage_bytes_, cell_count_.data(), cell_start_.data(),
                                           cells + 1, stream),
             "cell-table scan");
  cell_slot_kernel<<<blocks_for(n_), kBlock, 0, stream>>>(keys_.data(), n_, cell_start_.data(), cell_count_.data(),
                                                          sorted_id_.data());
  cell_sort_kernel<<<blocks_for(cells), kBlock, 0, stream>>>(cells, cell_start_.data(), sorted_id_.data());
  cell_order_kernel<<<blocks_for(n_), kBlock, 0, stream>>>(n_, sorted_id_.data(), position_.data(), velocity_.data(),
                                                          body_.data(), sorted_position_.data(), sorted_velocity_.data());
}

void CudaBackend::launch_elasticity(cudaStream_t stream) {
  if (deformables_ == 0) return;
  rotation_stress_kernel<<<blocks_for(deformables_), kBlock, 0, stream>>>(deformable_view());
  elastic_force_kernel<<<blocks_for(deformables_), kBlock, 0, stream>>>(deformable_view());
}

void CudaBackend::launch_density(cudaStream_t stream) {
  with_team_lanes(team_lanes_, [&](auto lanes) {
    constexpr unsigned L = decltype(lanes)::value;
    density_kernel<L><<<blocks_for(std::size_t{n_} * L), kBlock, 0, stream>>>(sorted_view(), volume_pressure_.data());
  });
}

// Paper 3.2 as a kernel sequence: grid (counting sort into cells, cell-ordered copies),
// rotations and elastic forces, densities, forces with leap-frog integration, rigid-body dynamics.
// Events between the phases time them.
void CudaBackend::record_step(cudaStream_t stream) {
  // External event records: the graph's replays record them, so their times can be read after
  // each launch (a plain record during capture only orders the graph's nodes).
  const auto mark = [&](std::size_t phase) {
    cuda_check(cudaEventRecordWithFlags(events_[phase], stream, cudaEventRecordExternal), "record phase event");
  };
  mark(0);
  launch_grid(stream);
  mark(1);
  launch_elasticity(stream);
  mark(2);
  launch_density(stream);
  mark(3);
  with_team_lanes(team_lanes_, [&](auto lanes) {
    constexpr unsigned L = decltype(lanes)::value;
    forces_kernel<L><<<blocks_for(std::size_t{n_} * L), kBlock, 0, stream>>>(sorted_view(), canonical_state());
  });
  mark(4);
  if (!scene_.rigid_bodies.empty()) {
    const auto chunks = static_cast<unsigned>(rigid_chunks_.size());
    rigid_wrench_integrate_kernel<<<chunks, kBlock, 0, stream>>>(rigid_chunks_.data(), rigid_bodies_.data(),
                                                                 canonical_state(), chunk_wrench_.data(),
                                                                 first_chunk_.data(), rigid_tickets_.data(), scene_.step);
    rigid_place_kernel<<<chunks, kBlock, 0, stream>>>(rigid_chunks_.data(), rigid_bodies_.data(), canonical_state(),
                                                      rest_offset_.data());
  }
  mark(5);
  cuda_check(cudaGetLastError(), "launch step kernels");
}

// The step's first three phases outside the graph, then the force sums written out in canonical
// order instead of being integrated.
ForceEvaluation CudaBackend::evaluate_forces() {
  launch_grid(stream_);
  launch_elasticity(stream_);
  launch_density(stream_);
  DeviceBuffer<ForceSum> forces(n_);
  force_probe_kernel<<<blocks_for(n_), kBlock, 0, stream_>>>(sorted_view(), forces.data());
  cuda_check(cudaGetLastError(), "launch force probe");
  cuda_check(cudaStreamSynchronize(stream_), "evaluate forces");
  const std::vector<ForceSum> sums = forces.download();
  const std::vector<VolumePressure> vp = volume_pressure_.download();
  const std::vector<std::uint32_t> id = sorted_id_.download();
  const std::vector<Vec4> elastic = deformables_ > 0 ? elastic_force_.download() : std::vector<Vec4>(n_, Vec4{0, 0, 0, 0});
  const std::vector<Quat> rotation = deformables_ > 0 ? rotation_.download() : std::vector<Quat>{};
  const auto to_eigen = [](Vec3 v) { return Eigen::Vector3d(v.x, v.y, v.z); };
  ForceEvaluation out;
  out.density.resize(n_);
  out.pressure.resize(n_);
  out.pressure_force.resize(n_);
  out.viscosity_force.resize(n_);
  out.elastic_force.resize(n_);
  out.rotation.assign(n_, Eigen::Matrix3d::Identity());
  for (std::uint32_t s = 0; s < n_; ++s) {
    const std::uint32_t i = id[s];
    out.density[i] = scene_.bodies[scene_.body[i]].sph_mass / vp[s].volume;
    out.pressure[i] = vp[s].pressure;
    out.pressure_force[i] = to_eigen(sums[s].pressure);
    out.viscosity_force[i] = to_eigen(sums[s].viscosity);
    out.elastic_force[i] = to_eigen(xyz(elastic[i]));
  }
  for (std::uint32_t d = 0; d < rotation.size(); ++d) {
    const ElasticParameters& body = scene_.elastic_bodies[scene_.deformable_body[d]];
    const Mat3 r = rotation_matrix(rotation[d]);
    Eigen::Matrix3d& out_r = out.rotation[body.first_particle + (d - body.first_deformable)];
    for (int k = 0; k < 9; ++k) out_r(k / 3, k % 3) = r.m[k];
  }
  return out;
}

void CudaBackend::set_particle_positions(const std::vector<Eigen::Vector3d>& positions) {
  cuda_check(cudaStreamSynchronize(stream_), "set positions");
  std::vector<Vec4> current = position_.download();
  for (std::uint32_t i = 0; i < n_; ++i) {
    const std::uint32_t kind = scene_.bodies[scene_.body[i]].kind;
    if (kind == kFluid || kind == kDeformable) {
      current[i] = make_vec4(scene_.to_kernel_frame(positions[i]), 0.0f);
    }
  }
  position_.upload(current);
}

void CudaBackend::step() {
  cuda_check(cudaGraphLaunch(graph_exec_, stream_), "launch step graph");
  time_ += setup_.dt;
  ++steps_;
  stepped_ = true;
}

std::vector<double> CudaBackend::last_phase_seconds() const {
  std::vector<double> seconds(kPhaseCount, 0.0);
  if (!stepped_) return seconds;
  cuda_check(cudaEventSynchronize(events_[kPhaseCount]), "wait for the step");
  for (std::size_t p = 0; p < kPhaseCount; ++p) {
    float ms = 0.0f;
    cuda_check(cudaEventElapsedTime(&ms, events_[p], events_[p + 1]), "read phase time");
    seconds[p] = 1e-3 * ms;
  }
  return seconds;
}

std::uint32_t CudaBackend::rigid_index(std::size_t body) const {
  const std::uint32_t index = body < scene_.bodies.size() ? scene_.bodies[body].rigid_index : kNotRigid;
  if (index == kNotRigid) throw std::invalid_argument("body " + std::to_string(body) + " is not a movable rigid body");
  return index;
}

void CudaBackend::set_external_wrench(std::size_t body, const Eigen::Vector3d& force, const Eigen::Vector3d& torque) {
  const std::uint32_t index = rigid_index(body);
  // external_force and external_torque are adjacent members: one small copy, ordered in the
  // stream before the next step; its host source lives in the backend.
  std::array<Vec3, 2>& wrench = external_wrench_[index];
  wrench = {Vec3{static_cast<float>(force.x()), static_cast<float>(force.y()), static_cast<float>(force.z())},
            Vec3{static_cast<float>(torque.x()), static_cast<float>(torque.y()), static_cast<float>(torque.z())}};
  static_assert(offsetof(RigidBody, external_torque) == offsetof(RigidBody, external_force) + sizeof(Vec3));
  cuda_check(cudaMemcpyAsync(reinterpret_cast<char*>(rigid_bodies_.data() + index) + offsetof(RigidBody, external_force),
                             wrench.data(), sizeof wrench, cudaMemcpyHostToDevice, stream_),
             "upload external wrench");
}

// What a haptic tick needs: one small device-to-host copy, or none when a logged sample has read
// every body back since the last step. The fastest particle's speed is bounded by
// |v| + |omega| r_max instead of being summed over the particles.
BodyState CudaBackend::rigid_body_state(std::size_t body) {
  const std::uint32_t index = rigid_index(body);
  RigidBody rigid{};
  if (rigid_host_step_ == steps_) {
    rigid = rigid_host_[index];
  } else {
    cuda_check(cudaMemcpyAsync(&rigid, rigid_bodies_.data() + index, sizeof rigid, cudaMemcpyDeviceToHost, stream_),
               "download rigid body");
    cuda_check(cudaStreamSynchronize(stream_), "download rigid body");
  }
  BodySums sums = zero_body_sums();
  const double bound = norm(rigid.velocity) + norm(angular_velocity(rigid)) * rigid_reach_[index];
  sums.max_speed = bound * bound;
  return to_body_state(scene_, sums, &rigid, setup_.bodies[body]);
}

// The chunk sums and a device-side copy of the rigid bodies land side by side in the read-back
// buffer, which comes back in one copy.
std::vector<BodyState> CudaBackend::body_states() {
  body_sums_kernel<<<static_cast<unsigned>(body_chunks_host_.size()), kBlock, 0, stream_>>>(
      body_chunks_.data(), bodies_.data(), canonical_state(), deformation_.data(), readback_sums());
  cuda_check(cudaGetLastError(), "launch body sums");
  if (!scene_.rigid_bodies.empty()) {
    cuda_check(cudaMemcpyAsync(readback_rigid(), rigid_bodies_.data(), rigid_bodies_.bytes(), cudaMemcpyDeviceToDevice, stream_),
               "gather rigid bodies");
  }
  std::vector<unsigned char> bytes(readback_.bytes());
  cuda_check(cudaMemcpyAsync(bytes.data(), readback_.data(), bytes.size(), cudaMemcpyDeviceToHost, stream_), "download body states");
  cuda_check(cudaStreamSynchronize(stream_), "body states");
  std::vector<BodySums> partial(body_chunks_host_.size());
  std::memcpy(partial.data(), bytes.data(), partial.size() * sizeof(BodySums));
  rigid_host_.resize(scene_.rigid_bodies.size());
  std::memcpy(rigid_host_.data(), bytes.data() + readback_rigid_offset_, rigid_host_.size() * sizeof(RigidBody));
  rigid_host_step_ = steps_;
  std::vector<BodySums> sums(setup_.bodies.size(), zero_body_sums());
  for (std::size_t c = 0; c < partial.size(); ++c) sums[body_chunks_host_[c].body] = combine(sums[body_chunks_host_[c].body], partial[c]);
  std::vector<BodyState> states;
  for (std::size_t b = 0; b < setup_.bodies.size(); ++b) {
    const std::uint32_t r = scene_.bodies[b].rigid_index;
    states.push_back(to_body_state(scene_, sums[b], r == kNotRigid ? nullptr : &rigid_host_[r], setup_.bodies[b]));
  }
  return states;
}

ParticleSnapshot CudaBackend::snapshot() {
  cuda_check(cudaStreamSynchronize(stream_), "snapshot");
  const std::vector<Vec4> position = position_.download();
  const std::vector<Vec4> velocity = velocity_.download();
  const std::vector<VolumePressure> vp = volume_pressure_.download();
  const std::vector<std::uint32_t> id = sorted_id_.download();
  ParticleSnapshot out;
  out.position.reserve(3 * n_);
  out.velocity.reserve(3 * n_);
  for (std::uint32_t i = 0; i < n_; ++i) {
    const Eigen::Vector3d world = scene_.to_world(xyz(position[i]));
    out.position.insert(out.position.end(),
                        {static_cast<float>(world.x()), static_cast<float>(world.y()), static_cast<float>(world.z())});
    out.velocity.insert(out.velocity.end(), {velocity[i].x, velocity[i].y, velocity[i].z});
  }
  // Densities and pressures of the last force evaluation, back in canonical order.
  out.density.assign(n_, 0.0f);
  out.pressure.assign(n_, 0.0f);
  if (stepped_) {
    for (std::uint32_t s = 0; s < n_; ++s) {
      const std::uint32_t i = id[s];
      out.density[i] = vp[s].volume > 0.0f ? scene_.bodies[scene_.body[i]].sph_mass / vp[s].volume : 0.0f;
      out.pressure[i] = vp[s].pressure;
    }
  }
  return out;
}

}  // namespace

std::vector<CudaDeviceInfo> cuda_devices() {
  std::vector<CudaDeviceInfo> devices;
  int count = 0;
  if (cudaGetDeviceCount(&count) != cudaSuccess) {
    cudaGetLastError();
    return devices;
  }
  for (int d = 0; d < count; ++d) {
    cudaDeviceProp p{};
    if (cudaGetDeviceProperties(&p, d) != cudaSuccess) continue;
    devices.push_back({d, p.name, p.major, p.minor, p.totalGlobalMem, p.multiProcessorCount});
  }
  return devices;
}

std::size_t cuda_backend_bytes(const ParticleSetup& setup) {
  const FloatScene scene = make_float_scene(setup);
  return scene_bytes(scene, scan_temp_bytes(scene.grid.cell_count()));
}

std::unique_ptr<Backend> make_cuda_backend(ParticleSetup setup) { return std::make_unique<CudaBackend>(std::move(setup)); }

}  // namespace mssph::kernels
