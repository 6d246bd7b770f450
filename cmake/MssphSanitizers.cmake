# Instrumented builds, each in its own build directory (see CMakePresets.json):
#   MSSPH_SANITIZE=ON  AddressSanitizer + UndefinedBehaviorSanitizer on every target, any
#                      undefined behaviour fatal, for running the test suite under them;
#   MSSPH_FUZZ=ON      Clang only: the same sanitizers plus libFuzzer's coverage instrumentation,
#                      and the fuzz targets of tests/fuzz.
option(MSSPH_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(MSSPH_FUZZ "Build the libFuzzer targets (Clang), with ASan and UBSan" OFF)

if(MSSPH_SANITIZE OR MSSPH_FUZZ)
  set(mssph_sanitizers -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  if(MSSPH_FUZZ)
    if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
      message(FATAL_ERROR "MSSPH_FUZZ needs Clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
    endif()
    list(APPEND mssph_sanitizers -fsanitize=fuzzer-no-link)
  endif()
  add_compile_options("$<$<COMPILE_LANGUAGE:CXX,C>:${mssph_sanitizers}>")
  add_link_options(-fsanitize=address,undefined)
endif()
