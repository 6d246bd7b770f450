#include "util/build_info.hpp"

namespace mssph {

const BuildInfo& build_info() {
  static const BuildInfo info {
    MSSPH_VERSION,
#include "git_commit.inc"
        , MSSPH_BUILD_TYPE,
#if defined(__clang__)
        "clang " __clang_version__,
#elif defined(__GNUC__)
        "g++ " __VERSION__,
#else
        "unknown",
#endif
        MSSPH_WITH_CUDA_BACKEND != 0, MSSPH_CUDA_ARCHITECTURES,
  };
  return info;
}

}  // namespace mssph
