// Probe (results/performance.md, "the neighbour grid as one cooperative kernel"): what an untaken
// conditional node, early-returning kernels and a cooperative kernel with a grid-wide barrier cost
// in a replayed CUDA graph. Not part of the build: nvcc -O3 -arch=sm_90 graph_probe.cu -o graph_probe
#include <cstdio>
#include <cuda_runtime.h>
#include <cooperative_groups.h>
namespace cg = cooperative_groups;
#define CK(x) do { cudaError_t e = (x); if (e != cudaSuccess) { printf("%s: %s\n", #x, cudaGetErrorString(e)); return 1; } } while (0)
struct alignas(16) V4 { float x, y, z, w; };
__global__ void gather(int n, const int* id, const V4* a, const V4* b, V4* sa, V4* sb, const V4* origin, unsigned* flag) {
  int s = blockIdx.x * blockDim.x + threadIdx.x;
  bool far = false;
  if (s < n) { int i = id[s]; V4 p = a[i]; sa[s] = p; sb[s] = b[i]; float dx = p.x - origin[s].x; far = dx * dx > 1e9f; }
  if (__syncthreads_or(far) && threadIdx.x == 0) atomicOr(flag, 1u);
}
__global__ void gather_set(int n, const int* id, const V4* a, const V4* b, V4* sa, V4* sb, const V4* origin, unsigned* flag, unsigned* done, cudaGraphConditionalHandle h) {
  int s = blockIdx.x * blockDim.x + threadIdx.x;
  bool far = false;
  if (s < n) { int i = id[s]; V4 p = a[i]; sa[s] = p; sb[s] = b[i]; float dx = p.x - origin[s].x; far = dx * dx > 1e9f; }
  __shared__ bool last;
  if (__syncthreads_or(far) && threadIdx.x == 0) atomicOr(flag, 1u);
  if (threadIdx.x == 0) { __threadfence(); last = atomicAdd(done, 1u) + 1u == gridDim.x; }
  __syncthreads();
  if (!last || threadIdx.x) return;
  __threadfence();
  unsigned f = atomicExch(flag, 0u);
  cudaGraphSetConditional(h, f ? 1u : 0u);
  *done = 0;
}
__global__ void gather_coop(int n, const int* id, const V4* a, const V4* b, V4* sa, V4* sb, const V4* origin, unsigned* flag, unsigned* out) {
  int s = blockIdx.x * blockDim.x + threadIdx.x;
  bool far = false;
  if (s < n) { int i = id[s]; V4 p = a[i]; sa[s] = p; sb[s] = b[i]; float dx = p.x - origin[s].x; far = dx * dx > 1e9f; }
  if (__syncthreads_or(far) && threadIdx.x == 0) atomicOr(flag, 1u);
  cg::this_grid().sync();
  if (*(volatile unsigned*)flag == 0) return;
  if (s == 0) *out = 1;
}
__global__ void early_exit(int n, const unsigned* flag, V4* x) { if (*flag == 0) return; int s = blockIdx.x * blockDim.x + threadIdx.x; if (s < n) x[s].w += 1.0f; }
__global__ void setter(unsigned* flag, cudaGraphConditionalHandle h) { unsigned f = atomicExch(flag, 0u); cudaGraphSetConditional(h, f ? 1u : 0u); }
__global__ void work(int n, V4* x) { int s = blockIdx.x * blockDim.x + threadIdx.x; if (s < n) { V4 p = x[s]; p.w += 1.0f; x[s] = p; } }
int main() {
  const int n = 46000, B = 256, G = (n + B - 1) / B;
  int* id; V4 *a, *b, *sa, *sb, *o; unsigned *flag, *done;
  CK(cudaMalloc(&id, n * 4)); CK(cudaMalloc(&a, n * 16)); CK(cudaMalloc(&b, n * 16)); CK(cudaMalloc(&sa, n * 16)); CK(cudaMalloc(&sb, n * 16)); CK(cudaMalloc(&o, n * 16));
  CK(cudaMalloc(&flag, 4)); CK(cudaMalloc(&done, 4)); CK(cudaMemset(flag, 0, 4)); CK(cudaMemset(done, 0, 4));
  CK(cudaMemset(id, 0, n * 4)); CK(cudaMemset(a, 0, n * 16)); CK(cudaMemset(b, 0, n * 16)); CK(cudaMemset(o, 0, n * 16));
  cudaStream_t st, body; CK(cudaStreamCreate(&st)); CK(cudaStreamCreate(&body));
  for (int variant = 0; variant < 8; ++variant) {
    cudaGraph_t g; cudaGraphExec_t ge;
    CK(cudaStreamBeginCapture(st, cudaStreamCaptureModeThreadLocal));
    cudaGraphConditionalHandle h{};
    if (variant >= 2 && variant <= 5) {
      cudaStreamCaptureStatus cs; cudaGraph_t cg; const cudaGraphNode_t* deps; size_t nd;
      CK(cudaStreamGetCaptureInfo(st, &cs, nullptr, &cg, &deps, nullptr, &nd));
      CK(cudaGraphConditionalHandleCreate(&h, cg, 0, cudaGraphCondAssignDefault));
    }
    if (variant == 0) { /* no front kernel */ }
    if (variant == 1) gather<<<G, B, 0, st>>>(n, id, a, b, sa, sb, o, flag);
    if (variant == 2) gather_set<<<G, B, 0, st>>>(n, id, a, b, sa, sb, o, flag, done, h);
    if (variant == 3) setter<<<1, 1, 0, st>>>(flag, h);
    if (variant == 4) { gather<<<G, B, 0, st>>>(n, id, a, b, sa, sb, o, flag); setter<<<1, 1, 0, st>>>(flag, h); }
    if (variant == 5) { for (int k = 0; k < 3; ++k) work<<<G, B, 0, st>>>(n, sb); gather_set<<<G, B, 0, st>>>(n, id, a, b, sa, sb, o, flag, done, h); }
    if (variant == 6) {
      cudaLaunchConfig_t cfg{}; cfg.gridDim = G; cfg.blockDim = B; cfg.stream = st;
      cudaLaunchAttribute at[1]; at[0].id = cudaLaunchAttributeCooperative; at[0].val.cooperative = 1; cfg.attrs = at; cfg.numAttrs = 1;
      CK(cudaLaunchKernelEx(&cfg, gather_coop, n, (const int*)id, (const V4*)a, (const V4*)b, sa, sb, (const V4*)o, flag, done));
    }
    if (variant == 7) { gather<<<G, B, 0, st>>>(n, id, a, b, sa, sb, o, flag); for (int k = 0; k < 4; ++k) early_exit<<<G, B, 0, st>>>(n, flag, sa); }
    if (variant >= 2 && variant <= 5) {
      cudaStreamCaptureStatus cs; cudaGraph_t cg; const cudaGraphNode_t* deps; size_t nd;
      CK(cudaStreamGetCaptureInfo(st, &cs, nullptr, &cg, &deps, nullptr, &nd));
      cudaGraphNodeParams p{}; p.type = cudaGraphNodeTypeConditional; p.conditional.handle = h; p.conditional.type = cudaGraphCondTypeIf; p.conditional.size = 1;
      cudaGraphNode_t node; CK(cudaGraphAddNode(&node, cg, deps, nullptr, nd, &p));
      CK(cudaStreamUpdateCaptureDependencies(st, &node, nullptr, 1, cudaStreamSetCaptureDependencies));
      CK(cudaStreamBeginCaptureToGraph(body, p.conditional.phGraph_out[0], nullptr, nullptr, 0, cudaStreamCaptureModeThreadLocal));
      for (int k = 0; k < 4; ++k) work<<<G, B, 0, body>>>(n, sa);
      cudaGraph_t bg; CK(cudaStreamEndCapture(body, &bg));
    }
    if (variant != 5) for (int k = 0; k < 3; ++k) work<<<G, B, 0, st>>>(n, sb);
    CK(cudaStreamEndCapture(st, &g));
    CK(cudaGraphInstantiate(&ge, g, 0));
    cudaEvent_t e0, e1; cudaEventCreate(&e0); cudaEventCreate(&e1);
    for (int k = 0; k < 200; ++k) CK(cudaGraphLaunch(ge, st));
    CK(cudaStreamSynchronize(st));
    float best = 1e9;
    for (int rep = 0; rep < 5; ++rep) {
      cudaEventRecord(e0, st);
      for (int k = 0; k < 2000; ++k) cudaGraphLaunch(ge, st);
      cudaEventRecord(e1, st); CK(cudaEventSynchronize(e1));
      float ms; cudaEventElapsedTime(&ms, e0, e1); if (ms < best) best = ms;
    }
    const char* names[] = {"3 work kernels", "gather + 3 work", "gather_set + cond(untaken) + 3 work", "setter(1 thread) + cond + 3 work", "gather + setter + cond + 3 work", "3 work + gather_set + cond at the end", "coop gather+grid sync + 3 work", "gather + 4 early-exit + 3 work"};
    printf("%-45s %.2f us per replay\n", names[variant], best * 1000 / 2000);
  }
  return 0;
}
