// Probe (results/performance.md, "each pair once"): the density and a force-like sum taken over
// each pair once, the pair's term added to both particles through 64-bit fixed-point atomics (whose
// sums do not depend on the order the adds land in, so runs stay bit-identical), against the full
// walk that takes every pair twice. A jittered lattice of spacing h/2 (104^3 = 1,124,864
// particles, as the 1M fluid block), cells of h sorted by key, each row of three cells one range.
// A particle's half walk: the rest of its own row after it, and the rows (dy, dz) = (-1..1, +1)
// and (+1, 0); every pair lies in exactly one of its particles' halves. The float-atomic variant is
// not deterministic: it shows what the atomics cost apart from the fixed-point conversion.
// Not part of the build: nvcc -O3 -arch=sm_90 -std=c++17 pair_once_probe.cu -o pair_once_probe
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
struct View { const float4* pos; const uint32_t* start; int n; float h, h2, c; };

__device__ inline float spiky(const View& v, float r2) { float r = sqrtf(r2); float d = v.h - r; return v.c * d * d * d; }

template <class F>
__device__ inline void rows(const View& v, float4 x, bool half, uint32_t s, F&& f) {
  int cx = int(floorf(x.x)), cy = int(floorf(x.y)), cz = int(floorf(x.z));
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy) {
      bool own = dz == 0 && dy == 0;
      if (half && !own && !(dz == 1 || (dz == 0 && dy == 1))) continue;
      uint32_t b, e;
      uint32_t first = key(cx - 1, cy + dy, cz + dz), last = key(cx + 1, cy + dy, cz + dz);
      if (last == first + 2) { b = v.start[first]; e = v.start[last + 1]; if (half && own) b = s + 1; f(b, e); }
      else for (int dx = -1; dx <= 1; ++dx) { uint32_t k = key(cx + dx, cy + dy, cz + dz); b = v.start[k]; e = v.start[k + 1];
        if (half && own) b = max(b, s + 1); if (b < e) f(b, e); }
    }
}

// visit(t, d, r2) for each candidate t of the full (half = false) or half walk of sorted particle s
// at x: d = x - x_t, r2 = |d|^2.
template <class Visit>
__device__ inline void candidates(const View& v, float4 x, bool half, uint32_t s, Visit&& visit) {
  rows(v, x, half, s, [&](uint32_t b, uint32_t e) {
    for (uint32_t t = b; t < e; ++t) {
      const float4 y = v.pos[t];
      const float3 d = make_float3(x.x - y.x, x.y - y.y, x.z - y.z);
      visit(t, d, d.x * d.x + d.y * d.y + d.z * d.z);
    }
  });
}

__global__ void full_density(View v, float* out) {
  uint32_t s = blockIdx.x * blockDim.x + threadIdx.x; if (s >= v.n) return;
  float sum = 0;
  candidates(v, v.pos[s], false, s, [&](uint32_t, float3, float r2) { if (r2 < v.h2) sum += spiky(v, r2); });
  out[s] = sum;
}
// The half walk with its own sum only (wrong sums: the scattered halves are dropped): what the
// walk costs without the atomics.
__global__ void half_density_no_scatter(View v, float* out) {
  uint32_t s = blockIdx.x * blockDim.x + threadIdx.x; if (s >= v.n) return;
  float own = spiky(v, 0.f);
  candidates(v, v.pos[s], true, s, [&](uint32_t, float3, float r2) { if (r2 < v.h2) own += spiky(v, r2); });
  out[s] = own;
}
__global__ void half_density_fixed(View v, unsigned long long* acc, float scale) {
  uint32_t s = blockIdx.x * blockDim.x + threadIdx.x; if (s >= v.n) return;
  unsigned long long own = (unsigned long long)(spiky(v, 0.f) * scale);
  candidates(v, v.pos[s], true, s, [&](uint32_t t, float3, float r2) {
    if (r2 < v.h2) { const unsigned long long q = (unsigned long long)(spiky(v, r2) * scale); own += q; atomicAdd(acc + t, q); }
  });
  atomicAdd(acc + s, own);
}
__global__ void half_density_float(View v, float* acc) {
  uint32_t s = blockIdx.x * blockDim.x + threadIdx.x; if (s >= v.n) return;
  float own = spiky(v, 0.f);
  candidates(v, v.pos[s], true, s, [&](uint32_t t, float3, float r2) {
    if (r2 < v.h2) { const float q = spiky(v, r2); own += q; atomicAdd(acc + t, q); }
  });
  atomicAdd(acc + s, own);
}
// The same with the adds aggregated within the warp first: lanes of one cell walk the same rows in
// step, so at each turn the lanes aiming at one candidate (__match_any_sync) add their 32-bit
// fixed-point terms (__reduce_add_sync, exact: integers) and their lowest lane issues one atomic.
__global__ void half_density_fixed_warp(View v, unsigned long long* acc, float scale) {
  uint32_t s = blockIdx.x * blockDim.x + threadIdx.x; if (s >= v.n) return;
  unsigned long long own = (unsigned long long)(spiky(v, 0.f) * scale);
  candidates(v, v.pos[s], true, s, [&](uint32_t t, float3, float r2) {
    const unsigned q = r2 < v.h2 ? (unsigned)(spiky(v, r2) * scale) : 0u;
    own += q;
    const unsigned group = __match_any_sync(__activemask(), t);
    const unsigned total = __reduce_add_sync(group, q);
    if (total != 0 && (threadIdx.x & 31) == __ffs(group) - 1) atomicAdd(acc + t, (unsigned long long)total);
  });
  atomicAdd(acc + s, own);
}
__global__ void convert(const unsigned long long* acc, float inv, float* out, int n) {
  int s = blockIdx.x * blockDim.x + threadIdx.x; if (s < n) out[s] = float(double(acc[s]) * inv);
}
// Force-like: a 3-vector pair term.
__device__ inline float3 fpair(const View& v, float dx, float dy, float dz, float r2) {
  float r = sqrtf(r2); float d = v.h - r; float k = v.c * d * d / fmaxf(r, 1e-6f); return make_float3(k * dx, k * dy, k * dz);
}
__global__ void full_force(View v, float4* out) {
  uint32_t s = blockIdx.x * blockDim.x + threadIdx.x; if (s >= v.n) return;
  float3 f = make_float3(0, 0, 0);
  candidates(v, v.pos[s], false, s, [&](uint32_t t, float3 d, float r2) {
    if (r2 < v.h2 && t != s) { const float3 q = fpair(v, d.x, d.y, d.z, r2); f.x += q.x; f.y += q.y; f.z += q.z; }
  });
  out[s] = make_float4(f.x, f.y, f.z, 0);
}
__global__ void half_force_fixed(View v, long long* acc, float scale) {
  uint32_t s = blockIdx.x * blockDim.x + threadIdx.x; if (s >= v.n) return;
  long long f[3] = {0, 0, 0};
  unsigned long long* a = reinterpret_cast<unsigned long long*>(acc);
  candidates(v, v.pos[s], true, s, [&](uint32_t t, float3 d, float r2) {
    if (r2 >= v.h2) return;
    const float3 q = fpair(v, d.x, d.y, d.z, r2);
    const long long fixed[3] = {llrintf(q.x * scale), llrintf(q.y * scale), llrintf(q.z * scale)};
    for (int c = 0; c < 3; ++c) { f[c] += fixed[c]; atomicAdd(a + 3 * t + c, (unsigned long long)(-fixed[c])); }
  });
  for (int c = 0; c < 3; ++c) atomicAdd(a + 3 * s + c, (unsigned long long)f[c]);
}
__global__ void convert3(const long long* acc, float inv, float4* out, int n) {
  int s = blockIdx.x * blockDim.x + threadIdx.x; if (s < n) out[s] = make_float4(float(double(acc[3*s]) * inv), float(double(acc[3*s+1]) * inv), float(double(acc[3*s+2]) * inv), 0);
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
  std::iota(order.begin(), order.end(), 0); std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return keys[a] < keys[b]; });
  std::vector<float4> ps(n); for (int i = 0; i < n; ++i) ps[i] = p[order[i]];
  std::vector<uint32_t> start(kCells * kCells * kCells + 1, 0); for (int i = 0; i < n; ++i) start[keys[i] + 1]++;
  for (size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  float4* dpos; uint32_t* dstart; float *dout, *dout2, *dfacc; unsigned long long* dacc; long long* dacc3; float4 *df, *df2;
  CK(cudaMalloc(&dpos, n * 16)); CK(cudaMalloc(&dstart, start.size() * 4)); CK(cudaMalloc(&dout, n * 4)); CK(cudaMalloc(&dout2, n * 4));
  CK(cudaMalloc(&dfacc, n * 4)); CK(cudaMalloc(&dacc, n * 8)); CK(cudaMalloc(&dacc3, n * 24)); CK(cudaMalloc(&df, n * 16)); CK(cudaMalloc(&df2, n * 16));
  CK(cudaMemcpy(dpos, ps.data(), n * 16, cudaMemcpyHostToDevice)); CK(cudaMemcpy(dstart, start.data(), start.size() * 4, cudaMemcpyHostToDevice));
  View v{dpos, dstart, n, h, h * h, float(15.0 / (M_PI * h * h * h * h * h * h))};
  const int B = 128, G = (n + B - 1) / B;
  const float scale = ldexpf(1.0f, 36), fscale = ldexpf(1.0f, 36);
  float t_full = time_us([&] { full_density<<<G, B>>>(v, dout); });
  float t_fixed = time_us([&] { cudaMemsetAsync(dacc, 0, n * 8); half_density_fixed<<<G, B>>>(v, dacc, scale); convert<<<G, B>>>(dacc, 1.0f / scale, dout2, n); });
  float t_fixed_only = time_us([&] { half_density_fixed<<<G, B>>>(v, dacc, scale); });
  float t_float = time_us([&] { cudaMemsetAsync(dfacc, 0, n * 4); half_density_float<<<G, B>>>(v, dfacc); });
  const float wscale = ldexpf(1.0f, 20);  // W(0) = 4.8: a term below 2^23, a warp's 32 terms below 2^28
  float t_warp = time_us([&] { cudaMemsetAsync(dacc, 0, n * 8); half_density_fixed_warp<<<G, B>>>(v, dacc, wscale); convert<<<G, B>>>(dacc, 1.0f / wscale, dout2, n); });
  float t_no_scatter = time_us([&] { half_density_no_scatter<<<G, B>>>(v, dfacc); });
  CK(cudaDeviceSynchronize());
  std::vector<float> a(n), b(n); cudaMemcpy(a.data(), dout, n * 4, cudaMemcpyDeviceToHost);
  cudaMemsetAsync(dacc, 0, n * 8); half_density_fixed<<<G, B>>>(v, dacc, scale); convert<<<G, B>>>(dacc, 1.0f / scale, dout2, n);
  cudaMemcpy(b.data(), dout2, n * 4, cudaMemcpyDeviceToHost);
  cudaMemsetAsync(dacc, 0, n * 8); half_density_fixed_warp<<<G, B>>>(v, dacc, wscale); convert<<<G, B>>>(dacc, 1.0f / wscale, dout2, n);
  std::vector<float> c(n); cudaMemcpy(c.data(), dout2, n * 4, cudaMemcpyDeviceToHost);
  double mdw = 0; for (int i = 0; i < n; ++i) mdw = std::max(mdw, std::fabs(double(a[i]) - c[i]) / std::fabs(double(a[i])));
  double md = 0; for (int i = 0; i < n; ++i) md = std::max(md, std::fabs(double(a[i]) - b[i]) / std::fabs(double(a[i])));
  float t_ffull = time_us([&] { full_force<<<G, B>>>(v, df); });
  float t_ffixed = time_us([&] { cudaMemsetAsync(dacc3, 0, n * 24); half_force_fixed<<<G, B>>>(v, dacc3, fscale); convert3<<<G, B>>>(dacc3, 1.0f / fscale, df2, n); });
  float t_conv = time_us([&] { convert<<<G, B>>>(dacc, 1.0f / scale, dout2, n); });
  float t_memset = time_us([&] { cudaMemsetAsync(dacc, 0, n * 8); });
  CK(cudaDeviceSynchronize());
  std::vector<float4> fa(n), fb(n); cudaMemcpy(fa.data(), df, n * 16, cudaMemcpyDeviceToHost); cudaMemcpy(fb.data(), df2, n * 16, cudaMemcpyDeviceToHost);
  double mf = 0, fmag = 0; for (int i = 0; i < n; ++i) { fmag = std::max(fmag, (double)std::fabs(fa[i].x)); mf = std::max(mf, std::fabs(double(fa[i].x) - fb[i].x)); }
  cudaDeviceProp prop; cudaGetDeviceProperties(&prop, 0);
  printf("device %s, particles %d\n", prop.name, n);
  printf("density full walk        %8.1f us\n", t_full);
  printf("density half, fixed64    %8.1f us (memset+walk+convert); walk alone %8.1f; convert %6.1f; memset %6.1f; max rel diff %.2e\n", t_fixed, t_fixed_only, t_conv, t_memset, md);
  printf("density half, float atom %8.1f us (memset+walk)\n", t_float);
  printf("density half, fixed64, adds aggregated in the warp %8.1f us (memset+walk+convert); max rel diff %.2e\n", t_warp, mdw);
  printf("density half, no scatter %8.1f us (the walk alone, own sum only)\n", t_no_scatter);
  printf("force-like full walk     %8.1f us\n", t_ffull);
  printf("force-like half, 3xfixed %8.1f us (memset+walk+convert); max abs diff x %.2e of max %.2e\n", t_ffixed, mf, fmag);
  return 0;
}
