#pragma once
// The benchmark suite of mssph, shared by `mssph bench` and the mssph_backend_benchmarks
// program. Names are stable so that baselines stay comparable across commits:
//   step/<backend>/<medium>/<particles>   one simulation step (fluid, rigid, deformable, mixed)
//   haptic_tick/<backend>                 one coupling evaluation plus the proxy read-back
//   scene/<backend>/<scene name>          one step of a scene file (`mssph bench SCENE.json`)
//   calibration/cpu                       a fixed workload that times the machine (machine_calibration.hpp)
// (Google Benchmark appends "/manual_time" to the step and scene names: they are timed by the
// clock around each batch of steps, after the device finished it.)
#include <string>
#include <vector>

namespace mssph::bench {

// The backends the suite runs by default: every built backend except the float64 reference,
// and cuda only when a GPU is visible.
std::vector<std::string> default_benchmark_backends();

// Registers step/ and haptic_tick/ for each backend, and calibration/cpu.
void register_suite(const std::vector<std::string>& backends);

// Registers scene/<backend>/<name> for the scene file (with --set overrides). Throws InputError
// for a bad scene, before anything runs.
void register_scene_benchmark(const std::string& scene_path, const std::vector<std::string>& overrides,
                              const std::string& backend);

// Adds the machine and build to the output's context: CPU model and cores, GPU and driver, build
// type, git commit, compiler, version, and the step-delay test hook when set.
void add_machine_context();

}  // namespace mssph::bench
