// libFuzzer target: any bytes as a scene file. Bad input must end in InputError (what `mssph run`
// reports with exit code 2); any other exception, crash, leak or undefined behaviour (with the
// sanitizers this target is built with) is a bug. An accepted scene then goes through the
// resource estimate and its checks, which run before anything is allocated.
#include "config/scene_loader.hpp"
#include "run/run_estimate.hpp"
#include "util/errors.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const mssph::Scene scene = mssph::parse_scene_text(text, "fuzz.json");
    for (const char* backend : {"reference", "cpu", "cuda"}) {
      const mssph::cli::RunEstimate estimate = mssph::cli::estimate_run(scene, backend);
      mssph::cli::check_run_fits(scene, backend, estimate, 1e9, 1e9);
    }
  } catch (const mssph::InputError&) {
    // The expected outcome for almost every input.
  }
  return 0;
}
