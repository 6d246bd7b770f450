# Every dependency comes from Debian 12's packages (scripts/setup.sh installs them).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)             # double-precision reference maths
find_package(HDF5 1.10 REQUIRED COMPONENTS C)            # run logs (C API)
find_package(CLI11 2.1 REQUIRED)                         # command line
find_package(nlohmann_json 3.11 REQUIRED)                # scene files
find_package(OpenMP REQUIRED COMPONENTS CXX)             # particle loops on the host
find_package(Threads REQUIRED)
if(MSSPH_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
find_package(benchmark REQUIRED)                         # `mssph bench` and the benchmark programs

# FindHDF5 (CMake 3.25) gives variables, not always an imported target: wrap them once.
if(NOT TARGET mssph_hdf5)
  add_library(mssph_hdf5 INTERFACE)
  target_include_directories(mssph_hdf5 SYSTEM INTERFACE ${HDF5_C_INCLUDE_DIRS} ${HDF5_INCLUDE_DIRS})
  target_link_libraries(mssph_hdf5 INTERFACE ${HDF5_C_LIBRARIES})
  target_compile_definitions(mssph_hdf5 INTERFACE ${HDF5_C_DEFINITIONS} H5_USE_110_API)
endif()

# nlohmann-json with JSON_DIAGNOSTICS: its own errors then carry the JSON path too.
add_library(mssph_json INTERFACE)
target_link_libraries(mssph_json INTERFACE nlohmann_json::nlohmann_json)
target_compile_definitions(mssph_json INTERFACE JSON_DIAGNOSTICS=1)
# GCC 12's middle end reports a false -Warray-bounds inside libstdc++'s std::map when inlining
# nlohmann-json's JSON_DIAGNOSTICS parent tracking (GCC bug 107138 family); later GCC is clean.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(mssph_json INTERFACE $<$<COMPILE_LANGUAGE:CXX>:-Wno-array-bounds>)
endif()

# Python for plots and the scene-schema check: Debian's own interpreter, which sees the
# python3-h5py, python3-matplotlib and python3-jsonschema packages (a pyenv python3 on PATH
# would not).
find_program(MSSPH_PYTHON NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT MSSPH_PYTHON)
  find_program(MSSPH_PYTHON NAMES python3)
endif()
