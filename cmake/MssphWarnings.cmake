# Warnings for every mssph C++ target: a clean build is part of the definition of done, and CI
# (scripts/test.sh) builds with MSSPH_WARNINGS_AS_ERRORS=ON so that a new warning fails it.
option(MSSPH_WARNINGS_AS_ERRORS "Treat compiler warnings as errors" OFF)
add_library(mssph_warnings INTERFACE)
target_compile_options(mssph_warnings INTERFACE
  $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion>
  $<$<COMPILE_LANGUAGE:CUDA>:-Xcompiler=-Wall,-Wextra>)
if(MSSPH_WARNINGS_AS_ERRORS)
  target_compile_options(mssph_warnings INTERFACE
    $<$<COMPILE_LANGUAGE:CXX>:-Werror> $<$<COMPILE_LANGUAGE:CUDA>:-Werror=all-warnings -Xcompiler=-Werror>)
endif()
