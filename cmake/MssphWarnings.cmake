# Warnings for every mssph C++ target: a clean build is part of the definition of done.
add_library(mssph_warnings INTERFACE)
target_compile_options(mssph_warnings INTERFACE
  $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion>
  $<$<COMPILE_LANGUAGE:CUDA>:-Xcompiler=-Wall,-Wextra>)
