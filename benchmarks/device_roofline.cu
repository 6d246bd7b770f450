// The card's own limits, for the roofline estimates beside the step times (results/current/):
// DRAM bandwidth (a streaming copy far larger than L2), FP32 rate (independent FMA chains) and the
// time a replayed graph spends per dependent kernel node that does no work (the floor of a step of
// N kernels is N times it). All report what they achieve, not the datasheet's peak.
#include <benchmark/benchmark.h>
#include <cuda_runtime.h>

namespace {

bool cuda_ok(cudaError_t e, benchmark::State& state) {
  if (e == cudaSuccess) return true;
  state.SkipWithError(cudaGetErrorString(e));
  return false;
}

__global__ void copy_kernel(const float4* __restrict__ in, float4* __restrict__ out, std::size_t n) {
  for (std::size_t i = blockIdx.x * std::size_t{blockDim.x} + threadIdx.x; i < n;
       i += std::size_t{gridDim.x} * blockDim.x) {
    out[i] = in[i];
  }
}

// 8 independent chains of 2048 FMAs per thread: 2 flops each.
constexpr int kChains = 8;
constexpr int kFmaPerChain = 2048;

__global__ void fma_kernel(float* out, float seed) {
  float acc[kChains];
  for (int c = 0; c < kChains; ++c) acc[c] = seed + static_cast<float>(threadIdx.x + c);
  for (int k = 0; k < kFmaPerChain; ++k) {
#pragma unroll
    for (int c = 0; c < kChains; ++c) acc[c] = fmaf(acc[c], 0.999999f, 1e-7f);
  }
  float sum = 0.0f;
  for (int c = 0; c < kChains; ++c) sum += acc[c];
  if (sum == 12345.0f) out[0] = sum;  // keeps the chains alive; never true for these inputs
}

__global__ void empty_kernel() {}

double elapsed_seconds(cudaEvent_t start, cudaEvent_t stop) {
  float ms = 0.0f;
  cudaEventElapsedTime(&ms, start, stop);
  return 1e-3 * ms;
}

void BM_dram_copy(benchmark::State& state) {
  const std::size_t bytes = std::size_t{1} << 30;  // 1 GiB each way, far larger than any GPU's L2
  const std::size_t n = bytes / sizeof(float4);
  float4 *in = nullptr, *out = nullptr;
  if (!cuda_ok(cudaMalloc(&in, bytes), state) || !cuda_ok(cudaMalloc(&out, bytes), state)) return;
  cudaMemset(in, 0, bytes);
  cudaEvent_t start, stop;
  cudaEventCreate(&start);
  cudaEventCreate(&stop);
  for (auto _ : state) {
    cudaEventRecord(start);
    copy_kernel<<<4096, 256>>>(in, out, n);
    cudaEventRecord(stop);
    cudaEventSynchronize(stop);
    state.SetIterationTime(elapsed_seconds(start, stop));
  }
  state.counters["bytes_per_second"] =
      benchmark::Counter(2.0 * static_cast<double>(bytes), benchmark::Counter::kIsIterationInvariantRate);
  cudaFree(in);
  cudaFree(out);
  cudaEventDestroy(start);
  cudaEventDestroy(stop);
}

void BM_fp32_fma(benchmark::State& state) {
  int sms = 0;
  cudaDeviceGetAttribute(&sms, cudaDevAttrMultiProcessorCount, 0);
  const unsigned blocks = static_cast<unsigned>(sms) * 16;
  float* out = nullptr;
  if (!cuda_ok(cudaMalloc(&out, sizeof(float)), state)) return;
  cudaEvent_t start, stop;
  cudaEventCreate(&start);
  cudaEventCreate(&stop);
  for (auto _ : state) {
    cudaEventRecord(start);
    fma_kernel<<<blocks, 256>>>(out, 1.0f);
    cudaEventRecord(stop);
    cudaEventSynchronize(stop);
    state.SetIterationTime(elapsed_seconds(start, stop));
  }
  const double flops = 2.0 * kChains * kFmaPerChain * 256.0 * blocks;
  state.counters["flops_per_second"] = benchmark::Counter(flops, benchmark::Counter::kIsIterationInvariantRate);
  cudaFree(out);
  cudaEventDestroy(start);
  cudaEventDestroy(stop);
}

// A graph of kNodes empty kernels, each depending on the one before, as a step's graph chains its
// passes; state.range(0) blocks of 256 threads each (1, or as many as a 30k-particle pass).
constexpr int kNodes = 64;

// Captures kNodes dependent empty kernels of `blocks` blocks each on `stream` into `graph`.
bool capture_empty_chain(cudaStream_t stream, unsigned blocks, cudaGraph_t* graph, benchmark::State& state) {
  if (!cuda_ok(cudaStreamBeginCapture(stream, cudaStreamCaptureModeThreadLocal), state)) return false;
  for (int k = 0; k < kNodes; ++k) empty_kernel<<<blocks, 256, 0, stream>>>();
  return cuda_ok(cudaStreamEndCapture(stream, graph), state);
}

void BM_graph_node(benchmark::State& state) {
  const unsigned blocks = static_cast<unsigned>(state.range(0));
  cudaStream_t stream = nullptr;
  cudaGraph_t graph = nullptr;
  cudaGraphExec_t exec = nullptr;
  cudaEvent_t start = nullptr, stop = nullptr;
  const bool ready = cuda_ok(cudaStreamCreateWithFlags(&stream, cudaStreamNonBlocking), state) &&
                     capture_empty_chain(stream, blocks, &graph, state) &&
                     cuda_ok(cudaGraphInstantiate(&exec, graph, 0), state) && cuda_ok(cudaEventCreate(&start), state) &&
                     cuda_ok(cudaEventCreate(&stop), state) &&
                     cuda_ok(cudaGraphLaunch(exec, stream), state) &&  // the first replay uploads the graph
                     cuda_ok(cudaStreamSynchronize(stream), state);
  if (ready) {
    for (auto _ : state) {
      cudaEventRecord(start, stream);
      cudaGraphLaunch(exec, stream);
      cudaEventRecord(stop, stream);
      cudaEventSynchronize(stop);
      state.SetIterationTime(elapsed_seconds(start, stop));
    }
    // Includes the graph's own launch once per kNodes nodes: an upper bound on a node's cost.
    state.counters["seconds_per_node"] =
        benchmark::Counter(kNodes, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  }
  if (stop) cudaEventDestroy(stop);
  if (start) cudaEventDestroy(start);
  if (exec) cudaGraphExecDestroy(exec);
  if (graph) cudaGraphDestroy(graph);
  if (stream) cudaStreamDestroy(stream);
}

}  // namespace

BENCHMARK(BM_graph_node)->Name("device/graph_node")->Arg(1)->Arg(118)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_dram_copy)->Name("device/dram_copy")->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_fp32_fma)->Name("device/fp32_fma")->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
