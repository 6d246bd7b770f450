// Probe (results/performance.md, "the grid's wrap along x moved beside the scene"): the one-lane
// density walk of the kernels written plainly, one thread per particle, on a jittered lattice of
// spacing h/2 (104^3 = 1,124,864 particles, as the 1M fluid block) that lies wholly inside the
// grid's period, so that no row of cells wraps. Cells of h, sorted by key, each cell's lower half
// along x first; walks over whole rows (full) and trimmed by half a cell as the kernels' one-lane
// walks are (trimmed), the pair's distance from sqrtf or, as in the kernels, from rsqrtf.
// Not part of the build: nvcc -O3 -arch=sm_90 -std=c++17 walk_probe.cu -o walk_probe
#include <cuda_runtime.h>
#include <algorithm>
#include <cstdio>
#include <cstdint>
#include <vector>
#include <numeric>
#include <cmath>

#define CK(x) do { cudaError_t e = (x); if (e != cudaSuccess) { printf("%s: %s\n", #x, cudaGetErrorString(e)); return 1; } } while (0)

constexpr int kBits = 6, kCells = 1 << kBits;
__host__ __device__ inline uint32_t key(int cx, int cy, int cz) {
  return (uint32_t(cx) & (kCells - 1)) | ((uint32_t(cy) & (kCells - 1)) << kBits) | ((uint32_t(cz) & (kCells - 1)) << (2 * kBits));
}
struct View { const float4* pos; const uint32_t* start; int n; float h, h2, c; const uint32_t* middle; };

// The spiky number density's pair term from r^2, the distance from sqrtf or, as in the kernels
// (SmoothingKernels::pair_distance), from one rsqrtf.
template <bool Rsqrt>
__device__ inline float spiky(const View& v, float r2) {
  const float r = Rsqrt ? r2 * (r2 > 1e-24f ? rsqrtf(r2) : 0.f) : sqrtf(r2);
  const float d = v.h - r;
  return v.c * d * d * d;
}

// f(begin, end) for each range of sorted particles around x: a row of three cells along x, or each
// cell of a row that wraps; Trimmed: a walk from the upper half of its cell (by 1/64 of a cell)
// leaves out the lower half of the cell below it along x, and the other way round, as the kernels'
// one-lane walks do (CellRanges::for_each_range).
template <bool Trimmed, class F>
__device__ inline void ranges(const View& v, float4 x, F&& f) {
  const int cx = int(floorf(x.x)), cy = int(floorf(x.y)), cz = int(floorf(x.z));
  const float fraction = x.x - floorf(x.x);
  const int side = !Trimmed ? 0 : fraction >= 0.5f + 1.0f / 64 ? 1 : fraction < 0.5f - 1.0f / 64 ? -1 : 0;
  const auto begin_below = [&](uint32_t k) { return side > 0 ? v.middle[k] : v.start[k]; };
  const auto end_above = [&](uint32_t k) { return side < 0 ? v.middle[k] : v.start[k + 1]; };
  for (int dz = -1; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      const uint32_t first = key(cx - 1, cy + dy, cz + dz), last = key(cx + 1, cy + dy, cz + dz);
      if (last == first + 2) {
        f(begin_below(first), end_above(last));
      } else {
        for (int dx = -1; dx <= 1; ++dx) {
          const uint32_t k = key(cx + dx, cy + dy, cz + dz);
          f(dx < 0 ? begin_below(k) : v.start[k], dx > 0 ? end_above(k) : v.start[k + 1]);
        }
      }
    }
  }
}

// One thread per particle: its number density over the candidates of its walk.
template <bool Trimmed, bool Rsqrt>
__global__ void density(View v, float* out) {
  const uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
  if (s >= v.n) return;
  const float4 x = v.pos[s];
  float sum = 0;
  ranges<Trimmed>(v, x, [&](uint32_t b, uint32_t e) {
    for (uint32_t t = b; t < e; ++t) {
      const float4 y = v.pos[t];
      const float dx = x.x - y.x, dy = x.y - y.y, dz = x.z - y.z;
      const float r2 = dx * dx + dy * dy + dz * dz;
      if (r2 < v.h2) sum += spiky<Rsqrt>(v, r2);
    }
  });
  out[s] = sum;
}

template <class F> float time_us(F&& f, int reps = 60) {
  cudaEvent_t a, b; cudaEventCreate(&a); cudaEventCreate(&b); std::vector<float> t;
  for (int i = 0; i < 5; ++i) f();
  for (int i = 0; i < reps; ++i) { cudaEventRecord(a); f(); cudaEventRecord(b); cudaEventSynchronize(b); float ms; cudaEventElapsedTime(&ms, a, b); t.push_back(ms * 1000); }
  std::sort(t.begin(), t.end()); return t[t.size() / 2];
}

int main() {
  const int m = 104; const float h = 1.0f, dx = 0.5f; const int n = m * m * m;
  std::vector<float4> p(n); uint32_t seed = 12345;
  auto rnd = [&] { seed = seed * 1664525u + 1013904223u; return (seed >> 8) * (1.0f / 16777216.0f) - 0.5f; };
  for (int k = 0, i = 0; k < m; ++k) for (int j = 0; j < m; ++j) for (int l = 0; l < m; ++l, ++i)
    p[i] = make_float4(4.0f + (l + 0.5f) * dx + 0.1f * dx * rnd(), 4.0f + (j + 0.5f) * dx + 0.1f * dx * rnd(), 4.0f + (k + 0.5f) * dx + 0.1f * dx * rnd(), 0);
  std::vector<uint32_t> keys(n), order(n); for (int i = 0; i < n; ++i) keys[i] = key(int(floorf(p[i].x)), int(floorf(p[i].y)), int(floorf(p[i].z)));
  std::vector<uint32_t> upper(n); for (int i = 0; i < n; ++i) upper[i] = (p[i].x - floorf(p[i].x)) >= 0.5f;
  std::iota(order.begin(), order.end(), 0); std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return keys[a] * 2ull + upper[a] < keys[b] * 2ull + upper[b]; });
  std::vector<float4> ps(n); for (int i = 0; i < n; ++i) ps[i] = p[order[i]];
  std::vector<uint32_t> start(kCells * kCells * kCells + 1, 0); for (int i = 0; i < n; ++i) start[keys[i] + 1]++;
  for (size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  std::vector<uint32_t> middle(start.begin(), start.end() - 1); for (int i = 0; i < n; ++i) if (!upper[i]) middle[keys[i]]++;
  float4* dpos; uint32_t* dstart; float *dout, *dout2;
  CK(cudaMalloc(&dpos, n * 16)); CK(cudaMalloc(&dstart, start.size() * 4)); CK(cudaMalloc(&dout, n * 4)); CK(cudaMalloc(&dout2, n * 4));
  uint32_t* dmiddle; CK(cudaMalloc(&dmiddle, middle.size() * 4)); CK(cudaMemcpy(dmiddle, middle.data(), middle.size() * 4, cudaMemcpyHostToDevice));
  CK(cudaMemcpy(dpos, ps.data(), n * 16, cudaMemcpyHostToDevice)); CK(cudaMemcpy(dstart, start.data(), start.size() * 4, cudaMemcpyHostToDevice));
  View v{dpos, dstart, n, h, h * h, float(15.0 / (M_PI * h * h * h * h * h * h)), dmiddle};
  const int B = 128, G = (n + B - 1) / B;
  float* dout3; CK(cudaMalloc(&dout3, n * 4));
  float t_full = time_us([&] { density<false, false><<<G, B>>>(v, dout); });
  float t_full_r = time_us([&] { density<false, true><<<G, B>>>(v, dout); });
  float t_trim = time_us([&] { density<true, false><<<G, B>>>(v, dout2); });
  float t_trim_r = time_us([&] { density<true, true><<<G, B>>>(v, dout3); });
  CK(cudaDeviceSynchronize());
  std::vector<float> a(n), b(n), c(n);
  density<false, false><<<G, B>>>(v, dout); density<true, false><<<G, B>>>(v, dout2); density<true, true><<<G, B>>>(v, dout3);
  cudaMemcpy(a.data(), dout, n * 4, cudaMemcpyDeviceToHost); cudaMemcpy(b.data(), dout2, n * 4, cudaMemcpyDeviceToHost); cudaMemcpy(c.data(), dout3, n * 4, cudaMemcpyDeviceToHost);
  double mb = 0, mc = 0; for (int i = 0; i < n; ++i) { mb = std::max(mb, std::fabs(double(a[i]) - b[i]) / a[i]); mc = std::max(mc, std::fabs(double(a[i]) - c[i]) / a[i]); }
  long long cand_full = 0, cand_trim = 0;
  for (int i = 0; i < n; i += 97) { /* sampled candidate counts */
    float4 x = ps[i]; int cx = int(floorf(x.x)), cy = int(floorf(x.y)), cz = int(floorf(x.z)); float fr = x.x - floorf(x.x);
    int side = fr >= 0.5f + 1.0f / 64 ? 1 : fr < 0.5f - 1.0f / 64 ? -1 : 0;
    for (int dz = -1; dz <= 1; ++dz) for (int dy = -1; dy <= 1; ++dy) { uint32_t f0 = key(cx - 1, cy + dy, cz + dz), l0 = key(cx + 1, cy + dy, cz + dz);
      cand_full += start[l0 + 1] - start[f0]; cand_trim += (side < 0 ? middle[l0] : start[l0 + 1]) - (side > 0 ? middle[f0] : start[f0]); } }
  cudaDeviceProp prop; cudaGetDeviceProperties(&prop, 0);
  printf("device %s, particles %d; candidates a particle (sampled): full %.1f, trimmed %.1f\n", prop.name, n, cand_full / double((n + 96) / 97), cand_trim / double((n + 96) / 97));
  printf("density full walk, sqrtf       %8.1f us\n", t_full);
  printf("density full walk, rsqrtf      %8.1f us\n", t_full_r);
  printf("density trimmed walk, sqrtf    %8.1f us (max rel diff to full %.1e)\n", t_trim, mb);
  printf("density trimmed walk, rsqrtf   %8.1f us (max rel diff to full %.1e)\n", t_trim_r, mc);
  return 0;
}
