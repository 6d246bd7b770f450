#include "cuda_backend.hpp"

#include "../common/float_scene.hpp"
#include "../common/fluid_physics.hpp"
#include "cuda_check.hpp"
#include "device_buffer.hpp"
#include "util/errors.hpp"

#include <cub/cub.cuh>

#include <array>
#include <sstream>

namespace mssph::kernels {
namespace {

constexpr int kBlock = 256;

unsigned blocks_for(std::size_t n) { return static_cast<unsigned>((n + kBlock - 1) / kBlock); }

// ---- Kernels: each is a thin loop around one of the shared per-particle functions. ----

__global__ void cell_keys_kernel(const Vec4* position, std::uint32_t n, GridShape grid, std::uint32_t* keys) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < n) keys[i] = grid.key_of(xyz(position[i]));
}

__global__ void identity_kernel(std::uint32_t n, std::uint32_t* values) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < n) values[i] = i;
}

__global__ void cell_order_kernel(std::uint32_t n, const std::uint32_t* sorted_keys, const std::uint32_t* sorted_id,
                                  const Vec4* position, const Vec4* velocity, const std::uint32_t* body,
                                  Vec4* sorted_position, Vec4* sorted_velocity, std::uint32_t* cell_start,
                                  std::uint32_t* cell_end) {
  const std::uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
  if (s < n) {
    place_in_cell_order(s, n, sorted_keys, sorted_id, position, velocity, body, sorted_position, sorted_velocity,
                        cell_start, cell_end);
  }
}

__global__ void density_kernel(SortedView view, VolumePressure* volume_pressure) {
  const std::uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
  if (s < view.step.particle_count) volume_pressure[s] = density_at(view, s).volume_pressure;
}

__global__ void forces_kernel(SortedView view, CanonicalState state) {
  const std::uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
  if (s < view.step.particle_count) forces_and_leapfrog(view, state, s);
}

struct WrenchSum {
  __device__ Wrench operator()(const Wrench& a, const Wrench& b) const { return a + b; }
};

// One block per movable rigid body: the wrench of its particles' interaction forces summed in a
// fixed order (strided per thread, then CUB's block tree: no atomics, so runs repeat bit for bit),
// the body integrated, and its particles placed.
__global__ void rigid_bodies_kernel(RigidBody* bodies, CanonicalState state, const Vec4* rest_offset, StepParameters step) {
  __shared__ RigidBody body;
  __shared__ Mat3 rotation;
  __shared__ Vec3 omega;
  using BlockReduce = cub::BlockReduce<Wrench, kBlock>;
  __shared__ typename BlockReduce::TempStorage reduce_storage;
  if (threadIdx.x == 0) body = bodies[blockIdx.x];
  __syncthreads();
  Wrench wrench{{0, 0, 0}, {0, 0, 0}};
  for (std::uint32_t i = body.first + threadIdx.x; i < body.first + body.count; i += blockDim.x) {
    wrench = wrench + particle_wrench(xyz(state.position[i]), xyz(state.interaction_force[i]), body.position);
  }
  const Wrench total = BlockReduce(reduce_storage).Reduce(wrench, WrenchSum());
  if (threadIdx.x == 0) {
    body.interaction_force = total.force;
    body.interaction_torque = total.torque;
    integrate_rigid_body(body, step.gravity, step.dt);
    rotation = rotation_matrix(body.orientation);
    omega = angular_velocity(body);
    bodies[blockIdx.x] = body;
  }
  __syncthreads();
  for (std::uint32_t i = body.first + threadIdx.x; i < body.first + body.count; i += blockDim.x) {
    place_rigid_particle(body, rotation, omega, xyz(rest_offset[i]), state.position[i], state.velocity[i]);
  }
}

struct BodySumsCombine {
  __device__ BodySums operator()(const BodySums& a, const BodySums& b) const { return combine(a, b); }
};

struct BodyRange {
  std::uint32_t first, count;
};

// One block per body: the sums behind its logged state.
__global__ void body_sums_kernel(const BodyRange* ranges, const BodyParameters* bodies, CanonicalState state,
                                 BodySums* sums) {
  using BlockReduce = cub::BlockReduce<BodySums, kBlock>;
  __shared__ typename BlockReduce::TempStorage reduce_storage;
  const BodyRange range = ranges[blockIdx.x];
  const float mass = bodies[blockIdx.x].sph_mass;
  BodySums acc = zero_body_sums();
  for (std::uint32_t i = range.first + threadIdx.x; i < range.first + range.count; i += blockDim.x) {
    add_particle(acc, xyz(state.position[i]), xyz(state.velocity[i]), mass, xyz(state.interaction_force[i]));
  }
  const BodySums total = BlockReduce(reduce_storage).Reduce(acc, BodySumsCombine());
  if (threadIdx.x == 0) sums[blockIdx.x] = total;
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
  std::vector<std::string> phase_names() const override { return {"grid", "density", "forces_integrate", "rigid_bodies"}; }
  std::vector<double> last_phase_seconds() const override;

 private:
  static constexpr int kPhaseCount = 4;
  void record_step(cudaStream_t stream);
  SortedView sorted_view() const;
  CanonicalState canonical_state();
  std::uint32_t rigid_index(std::size_t body) const;

  ParticleSetup setup_;
  FloatScene scene_;
  std::string device_name_;
  std::uint32_t n_;
  std::vector<float> rigid_reach_;  // per movable rigid body: max |r0| over its particles [m]
  std::vector<std::array<Vec3, 2>> external_wrench_;  // per movable rigid body: host copy of F, tau

  // Canonical state.
  DeviceBuffer<Vec4> position_, velocity_, interaction_force_, rest_offset_;
  DeviceBuffer<std::uint32_t> body_;
  DeviceBuffer<std::uint8_t> fixed_;
  // Grid and cell-ordered copies.
  DeviceBuffer<std::uint32_t> keys_, sorted_keys_, identity_, sorted_id_, cell_start_, cell_end_;
  DeviceBuffer<Vec4> sorted_position_, sorted_velocity_;
  DeviceBuffer<VolumePressure> volume_pressure_;
  DeviceBuffer<unsigned char> sort_storage_;
  std::size_t sort_storage_bytes_ = 0;
  // Bodies.
  DeviceBuffer<BodyParameters> bodies_;
  DeviceBuffer<RigidBody> rigid_bodies_;
  DeviceBuffer<BodyRange> body_ranges_;
  DeviceBuffer<BodySums> body_sums_;

  cudaStream_t stream_ = nullptr;
  cudaGraph_t graph_ = nullptr;
  cudaGraphExec_t graph_exec_ = nullptr;
  std::array<cudaEvent_t, kPhaseCount + 1> events_{};
  double time_ = 0.0;
  bool stepped_ = false;
};

std::size_t sort_temp_bytes(std::uint32_t n, int bits) {
  std::size_t bytes = 0;
  cuda_check(cub::DeviceRadixSort::SortPairs(nullptr, bytes, static_cast<const std::uint32_t*>(nullptr),
                                             static_cast<std::uint32_t*>(nullptr),
                                             static_cast<const std::uint32_t*>(nullptr),
                                             static_cast<std::uint32_t*>(nullptr), n, 0, bits),
             "size the radix sort");
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
  const cudaError_t image = cudaFuncGetAttributes(&attributes, density_kernel);
  if (image != cudaSuccess) {
    cudaGetLastError();  // clear the sticky error of the failed query
    throw InputError("--backend cuda: the GPU " + name + " (compute capability " + std::to_string(properties.major) +
                     "." + std::to_string(properties.minor) + ") is not supported by this build (CUDA architectures " +
                     MSSPH_CUDA_ARCHITECTURES_TEXT + "): rebuild with -DCMAKE_CUDA_ARCHITECTURES=" +
                     std::to_string(properties.major) + std::to_string(properties.minor));
  }
}

// Every device allocation the backend makes for a scene.
std::size_t scene_bytes(const FloatScene& scene, std::size_t sort_bytes) {
  const std::size_t n = scene.position.size();
  const std::size_t canonical = 4 * sizeof(Vec4) + sizeof(std::uint32_t) + sizeof(std::uint8_t);
  const std::size_t grid = 4 * sizeof(std::uint32_t) + 2 * sizeof(Vec4) + sizeof(VolumePressure);
  const std::size_t cells = std::size_t{scene.grid.cell_count()} * 2 * sizeof(std::uint32_t);
  const std::size_t bodies = scene.bodies.size() * (sizeof(BodyParameters) + sizeof(BodyRange) + sizeof(BodySums)) +
                             scene.rigid_bodies.size() * sizeof(RigidBody);
  return n * (canonical + grid) + cells + bodies + sort_bytes;
}

CudaBackend::CudaBackend(ParticleSetup setup)
    : setup_(std::move(setup)), scene_(make_float_scene(setup_)), n_(static_cast<std::uint32_t>(setup_.size())) {
  require_usable_device(device_name_);
  for (const BodySetup& body : setup_.bodies) {
    if (body.kind == BodyKind::deformable) {
      throw InputError("body \"" + body.name + "\": deformable bodies are not available yet in the cuda backend");
    }
  }
  const int bits = static_cast<int>(scene_.grid.total_bits());
  sort_storage_bytes_ = sort_temp_bytes(n_, bits);
  const std::size_t needed = scene_bytes(scene_, sort_storage_bytes_);
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
  body_ = DeviceBuffer<std::uint32_t>(scene_.body);
  fixed_ = DeviceBuffer<std::uint8_t>(scene_.fixed);
  keys_ = DeviceBuffer<std::uint32_t>(n_);
  sorted_keys_ = DeviceBuffer<std::uint32_t>(n_);
  identity_ = DeviceBuffer<std::uint32_t>(n_);
  sorted_id_ = DeviceBuffer<std::uint32_t>(n_);
  cell_start_ = DeviceBuffer<std::uint32_t>(scene_.grid.cell_count());
  cell_end_ = DeviceBuffer<std::uint32_t>(scene_.grid.cell_count());
  sorted_position_ = DeviceBuffer<Vec4>(n_);
  sorted_velocity_ = DeviceBuffer<Vec4>(n_);
  volume_pressure_ = DeviceBuffer<VolumePressure>(std::vector<VolumePressure>(n_, VolumePressure{0, 0}));
  sort_storage_ = DeviceBuffer<unsigned char>(sort_storage_bytes_);
  bodies_ = DeviceBuffer<BodyParameters>(scene_.bodies);
  rigid_bodies_ = DeviceBuffer<RigidBody>(scene_.rigid_bodies);
  std::vector<BodyRange> ranges;
  for (const BodySetup& b : setup_.bodies) ranges.push_back({static_cast<std::uint32_t>(b.first), static_cast<std::uint32_t>(b.count)});
  body_ranges_ = DeviceBuffer<BodyRange>(ranges);
  body_sums_ = DeviceBuffer<BodySums>(setup_.bodies.size());
  for (const RigidBody& r : scene_.rigid_bodies) {
    float reach = 0.0f;
    for (std::uint32_t i = r.first; i < r.first + r.count; ++i) reach = std::max(reach, norm(xyz(scene_.rest_offset[i])));
    rigid_reach_.push_back(reach);
  }
  external_wrench_.resize(scene_.rigid_bodies.size());

  cuda_check(cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking), "create stream");
  for (cudaEvent_t& e : events_) cuda_check(cudaEventCreate(&e), "create event");
  identity_kernel<<<blocks_for(n_), kBlock, 0, stream_>>>(n_, identity_.data());
  cuda_check(cudaGetLastError(), "launch identity kernel");

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
                    CellRanges{scene_.grid, cell_start_.data(), cell_end_.data()},
                    sorted_position_.data(),
                    sorted_velocity_.data(),
                    sorted_id_.data(),
                    volume_pressure_.data()};
}

CanonicalState CudaBackend::canonical_state() {
  return CanonicalState{position_.data(), velocity_.data(), interaction_force_.data(), nullptr, body_.data(), fixed_.data()};
}

// Paper 3.2 as a kernel sequence: grid (keys, radix sort, cell ranges and cell-ordered copies),
// densities, forces with leap-frog integration, rigid-body dynamics. Events between the phases
// time them.
void CudaBackend::record_step(cudaStream_t stream) {
  const unsigned blocks = blocks_for(n_);
  const int bits = static_cast<int>(scene_.grid.total_bits());
  cuda_check(cudaEventRecord(events_[0], stream), "record event");
  cell_keys_kernel<<<blocks, kBlock, 0, stream>>>(position_.data(), n_, scene_.grid, keys_.data());
  cuda_check(cub::DeviceRadixSort::SortPairs(sort_storage_.data(), sort_storage_bytes_, keys_.data(), sorted_keys_.data(),
                                             identity_.data(), sorted_id_.data(), n_, 0, bits, stream),
             "radix sort");
  cuda_check(cudaMemsetAsync(cell_start_.data(), 0xff, cell_start_.bytes(), stream), "clear cells");
  cell_order_kernel<<<blocks, kBlock, 0, stream>>>(n_, sorted_keys_.data(), sorted_id_.data(), position_.data(),
                                                   velocity_.data(), body_.data(), sorted_position_.data(),
                                                   sorted_velocity_.data(), cell_start_.data(), cell_end_.data());
  cuda_check(cudaEventRecord(events_[1], stream), "record event");
  density_kernel<<<blocks, kBlock, 0, stream>>>(sorted_view(), volume_pressure_.data());
  cuda_check(cudaEventRecord(events_[2], stream), "record event");
  forces_kernel<<<blocks, kBlock, 0, stream>>>(sorted_view(), canonical_state());
  cuda_check(cudaEventRecord(events_[3], stream), "record event");
  if (!scene_.rigid_bodies.empty()) {
    rigid_bodies_kernel<<<static_cast<unsigned>(scene_.rigid_bodies.size()), kBlock, 0, stream>>>(
        rigid_bodies_.data(), canonical_state(), rest_offset_.data(), scene_.step);
  }
  cuda_check(cudaEventRecord(events_[4], stream), "record event");
  cuda_check(cudaGetLastError(), "launch step kernels");
}

void CudaBackend::step() {
  cuda_check(cudaGraphLaunch(graph_exec_, stream_), "launch step graph");
  time_ += setup_.dt;
  stepped_ = true;
}

std::vector<double> CudaBackend::last_phase_seconds() const {
  std::vector<double> seconds(kPhaseCount, 0.0);
  if (!stepped_) return seconds;
  cuda_check(cudaEventSynchronize(events_[kPhaseCount]), "wait for the step");
  for (int p = 0; p < kPhaseCount; ++p) {
    float ms = 0.0f;
    cuda_check(cudaEventElapsedTime(&ms, events_[static_cast<std::size_t>(p)], events_[static_cast<std::size_t>(p) + 1]), "read phase time");
    seconds[static_cast<std::size_t>(p)] = 1e-3 * ms;
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

// One small device-to-host copy: what a haptic tick needs. The fastest particle's speed is
// bounded by |v| + |omega| r_max instead of being summed over the particles.
BodyState CudaBackend::rigid_body_state(std::size_t body) {
  const std::uint32_t index = rigid_index(body);
  RigidBody rigid{};
  cuda_check(cudaMemcpyAsync(&rigid, rigid_bodies_.data() + index, sizeof rigid, cudaMemcpyDeviceToHost, stream_),
             "download rigid body");
  cuda_check(cudaStreamSynchronize(stream_), "download rigid body");
  BodySums sums = zero_body_sums();
  const double bound = norm(rigid.velocity) + norm(angular_velocity(rigid)) * rigid_reach_[index];
  sums.max_speed = bound * bound;
  return to_body_state(sums, &rigid, setup_.bodies[body]);
}

std::vector<BodyState> CudaBackend::body_states() {
  body_sums_kernel<<<static_cast<unsigned>(setup_.bodies.size()), kBlock, 0, stream_>>>(
      body_ranges_.data(), bodies_.data(), canonical_state(), body_sums_.data());
  cuda_check(cudaGetLastError(), "launch body sums");
  std::vector<BodySums> sums(setup_.bodies.size());
  cuda_check(cudaMemcpyAsync(sums.data(), body_sums_.data(), body_sums_.bytes(), cudaMemcpyDeviceToHost, stream_), "download body sums");
  std::vector<RigidBody> rigid(scene_.rigid_bodies.size());
  if (!rigid.empty()) {
    cuda_check(cudaMemcpyAsync(rigid.data(), rigid_bodies_.data(), rigid_bodies_.bytes(), cudaMemcpyDeviceToHost, stream_),
               "download rigid bodies");
  }
  cuda_check(cudaStreamSynchronize(stream_), "body states");
  std::vector<BodyState> states;
  for (std::size_t b = 0; b < setup_.bodies.size(); ++b) {
    const std::uint32_t r = scene_.bodies[b].rigid_index;
    BodyState s = to_body_state(sums[b], r == kNotRigid ? nullptr : &rigid[r], setup_.bodies[b]);
    s.max_speed = std::sqrt(sums[b].max_speed);
    states.push_back(s);
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
    out.position.insert(out.position.end(), {position[i].x, position[i].y, position[i].z});
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
  return scene_bytes(scene, sort_temp_bytes(static_cast<std::uint32_t>(setup.size()), static_cast<int>(scene.grid.total_bits())));
}

std::unique_ptr<Backend> make_cuda_backend(ParticleSetup setup) { return std::make_unique<CudaBackend>(std::move(setup)); }

}  // namespace mssph::kernels
