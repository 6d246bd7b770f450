#pragma once
// One spelling for functions compiled both by nvcc for the GPU and by the host compiler for the
// `cpu` backend: the per-particle physics is written once and runs on both.
#if defined(__CUDACC__)
#define MSSPH_HD __host__ __device__ __forceinline__
#else
#define MSSPH_HD inline
#endif

// Unrolls the loop that follows `n` times in device code, so a thread can have the loads of several
// trips in flight at once; the host compiler decides for itself.
#define MSSPH_PRAGMA(text) _Pragma(#text)
#if defined(__CUDA_ARCH__)
#define MSSPH_DEVICE_UNROLL(n) MSSPH_PRAGMA(unroll n)
#else
#define MSSPH_DEVICE_UNROLL(n)
#endif
