#pragma once
// Programmatic dependent launch (compute capability 9.0): a step kernel launched by
// launch_after_previous may be scheduled while the kernel before it in the stream still runs, onto
// the multiprocessors that kernel's finished blocks free, instead of after its last block ends and
// the launch's own latency. A step kernel calls follow_previous_kernel before it reads what the
// kernel just before it writes: that waits until that kernel has finished and its writes are
// visible, so each kernel reads what it read before, and lets the kernel after it be scheduled in
// turn. A kernel that follows one that waited first is therefore scheduled only once the kernels
// two and more launches before it have finished, and before its wait it may load what only those
// wrote (rigid_bodies.cu's kernels load so; forces_kernel, step_kernels.cu, sums so after the
// elastic pass). A kernel that neither reads what the kernels still running before it write nor
// writes what they read may do all its work first: it lets the next kernel be scheduled at its
// start and waits at its end (rotation_stress_kernel, step_kernels.cu), so the kernel after it
// still finds every earlier kernel finished when its own wait returns.
#include "cuda_check.hpp"

#include <utility>

namespace mssph::kernels {

// Below compute capability 9.0 a launch never overlaps the one before it, and there is nothing to
// wait for nor to let go.
__device__ inline void wait_for_previous_kernel() {
#if defined(__CUDA_ARCH__) && __CUDA_ARCH__ >= 900
  cudaGridDependencySynchronize();
#endif
}
__device__ inline void let_next_kernel_be_scheduled() {
#if defined(__CUDA_ARCH__) && __CUDA_ARCH__ >= 900
  cudaTriggerProgrammaticLaunchCompletion();
#endif
}

// Called by every thread of a step kernel before it reads what the kernel before it writes.
__device__ inline void follow_previous_kernel() {
  wait_for_previous_kernel();
  let_next_kernel_be_scheduled();
}

// Launches kernel(args...) on `stream`, allowed to be scheduled before the kernel before it ends.
template <class... Params, class... Args>
void launch_after_previous(void (*kernel)(Params...), dim3 blocks, dim3 threads, cudaStream_t stream, const char* what,
                           Args&&... args) {
  cudaLaunchAttribute overlap{};
  overlap.id = cudaLaunchAttributeProgrammaticStreamSerialization;
  overlap.val.programmaticStreamSerializationAllowed = 1;
  cudaLaunchConfig_t config{};
  config.gridDim = blocks;
  config.blockDim = threads;
  config.stream = stream;
  config.attrs = &overlap;
  config.numAttrs = 1;
  cuda_check(cudaLaunchKernelEx(&config, kernel, std::forward<Args>(args)...), what);
}

}  // namespace mssph::kernels
