#pragma once
// One spelling for functions compiled both by nvcc for the GPU and by the host compiler for the
// `cpu` backend: the per-particle physics is written once and runs on both.
#if defined(__CUDACC__)
#define MSSPH_HD __host__ __device__ __forceinline__
#else
#define MSSPH_HD inline
#endif
