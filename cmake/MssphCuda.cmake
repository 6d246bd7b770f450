# MSSPH_CUDA=AUTO builds the CUDA backend when nvcc is found; ON requires it; OFF skips it.
# The host build of the same kernels (--backend cpu) is always built.
set(MSSPH_WITH_CUDA OFF)
if(NOT MSSPH_CUDA STREQUAL "OFF")
  include(CheckLanguage)
  check_language(CUDA)
  if(CMAKE_CUDA_COMPILER)
    if(NOT DEFINED CMAKE_CUDA_ARCHITECTURES)
      set(CMAKE_CUDA_ARCHITECTURES 90 CACHE STRING "CUDA architectures (90: H100/H200)")
    endif()
    enable_language(CUDA)
    find_package(CUDAToolkit REQUIRED)
    set(CMAKE_CUDA_STANDARD 17)  # CMake 3.25 cannot ask nvcc for C++20; the .cu files need only 17
    set(CMAKE_CUDA_STANDARD_REQUIRED ON)
    set(MSSPH_WITH_CUDA ON)
  elseif(MSSPH_CUDA STREQUAL "ON")
    message(FATAL_ERROR "MSSPH_CUDA=ON but no CUDA compiler (nvcc) was found")
  endif()
endif()
