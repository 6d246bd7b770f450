// The run log's account of compression (src/run/compression_watch.hpp): a soft St Venant-
// Kirchhoff cube thrown onto the ground is crushed past its model's valid range; the log records
// each deformable body's smallest det F and the count past the range at every sample, with units
// and descriptions, the warning (once, with body, time and value) and the fraction of the run
// outside. A stiff cube on the same path stays inside.
#include "h5_read.hpp"
#include "run/scene_run.hpp"
#include "temp_dir.hpp"
#include "util/hdf5_handle.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

namespace mssph {
namespace {

// A 6 x 6 x 6 cube (dx = 1 cm) 1 mm over a ground slab, moving down at 3 m/s. With E = 2 kPa its
// p-wave speed is 1.6 m/s, so the impact strain v / c_p is of order 1: far past det F = 1/sqrt(3).
// With E = 2 MPa (c_p = 52 m/s) the strain is ~6 %.
std::string write_scene(const test::TempDir& dir, double young_modulus) {
  const nlohmann::json scene = {{"name", "thrown_cube"},
                                {"simulation",
                                 {{"dt", 5e-5},
                                  {"duration", 0.02},
                                  {"gravity", {0.0, 0.0, 0.0}},
                                  {"particle_spacing", 0.01},
                                  {"max_speed", 50.0}}},
                                {"bodies",
                                 {{"ground",
                                   {{"kind", "boundary"},
                                    {"shape", {{"type", "box"}, {"size", {0.2, 0.2, 0.02}}}},
                                    {"position", {0.0, 0.0, -0.01}},
                                    {"rest_density", 1000.0},
                                    {"pressure_stiffness", 500.0}}},
                                  {"cube",
                                   {{"kind", "deformable"},
                                    {"shape", {{"type", "box"}, {"size", {0.06, 0.06, 0.06}}}},
                                    {"position", {0.0, 0.0, 0.031}},
                                    {"velocity", {0.0, 0.0, -3.0}},
                                    {"rest_density", 1000.0},
                                    {"pressure_stiffness", 500.0},
                                    {"young_modulus", young_modulus},
                                    {"poisson_ratio", 0.3},
                                    {"model", "stvk"}}}}},
                                {"output", {{"log_interval", 5e-4}}}};
  const std::string path = (dir / ("cube_" + std::to_string(young_modulus) + ".json")).string();
  std::ofstream(path) << scene.dump(2);
  return path;
}

struct CompressionLog {
  std::vector<double> min_volume_ratio, compressed_count;
  double fraction = -1.0;
  std::string min_units, count_units, count_description, warning;
};

CompressionLog run_and_read(const test::TempDir& dir, double young_modulus) {
  cli::SceneRunRequest request;
  request.scene_path = write_scene(dir, young_modulus);
  request.backend = "cpu";
  request.output = (dir / ("cube_" + std::to_string(young_modulus) + ".h5")).string();
  request.quiet = true;
  const cli::SceneRunResult result = cli::run_scene(request);
  EXPECT_EQ(result.exit_code, 0) << result.error;
  const h5::Handle file = test::open_read_only(result.output);
  CompressionLog log;
  log.min_volume_ratio = test::read_doubles(file.id(), "/bodies/cube/min_volume_ratio");
  log.compressed_count = test::read_doubles(file.id(), "/bodies/cube/compressed_count");
  const h5::Handle cube = test::open_object(file.id(), "/bodies/cube");
  log.fraction = h5::read_double_attribute(cube.id(), "fraction_outside_valid_range");
  if (test::has_attribute(cube.id(), "compression_warning")) {
    log.warning = h5::read_string_attribute(cube.id(), "compression_warning");
  }
  log.min_units =
      h5::read_string_attribute(test::open_object(file.id(), "/bodies/cube/min_volume_ratio").id(), "units");
  log.count_units =
      h5::read_string_attribute(test::open_object(file.id(), "/bodies/cube/compressed_count").id(), "units");
  log.count_description =
      h5::read_string_attribute(test::open_object(file.id(), "/bodies/cube/compressed_count").id(), "description");
  EXPECT_EQ(h5::read_double_attribute(test::open_object(file.id(), "/").id(), "fraction_outside_valid_range"),
            log.fraction);
  return log;
}

TEST(CompressionLog, ACrushedStVenantKirchhoffCubeIsRecordedWarnedAndSummedUp) {
  test::TempDir dir;
  const CompressionLog soft = run_and_read(dir, 2e3);
  ASSERT_EQ(soft.min_volume_ratio.size(), 40u);  // 0.02 s at 0.5 ms
  ASSERT_EQ(soft.compressed_count.size(), 40u);
  EXPECT_EQ(soft.min_units, "1");
  EXPECT_EQ(soft.count_units, "1");
  EXPECT_NE(soft.count_description.find("0.577"), std::string::npos) << soft.count_description;
  const double lowest = *std::min_element(soft.min_volume_ratio.begin(), soft.min_volume_ratio.end());
  EXPECT_LT(lowest, 0.577);
  // The fraction is the share of samples with a particle counted.
  const auto outside =
      std::count_if(soft.compressed_count.begin(), soft.compressed_count.end(), [](double c) { return c > 0; });
  EXPECT_GT(outside, 0);
  EXPECT_DOUBLE_EQ(soft.fraction, static_cast<double>(outside) / 40.0);
  // The warning names the body, the time and the value.
  EXPECT_NE(soft.warning.find("\"cube\""), std::string::npos) << soft.warning;
  EXPECT_NE(soft.warning.find("t = "), std::string::npos) << soft.warning;
  EXPECT_NE(soft.warning.find("det F = "), std::string::npos) << soft.warning;

  const CompressionLog stiff = run_and_read(dir, 2e6);
  EXPECT_GT(*std::min_element(stiff.min_volume_ratio.begin(), stiff.min_volume_ratio.end()), 0.8);
  EXPECT_EQ(stiff.fraction, 0.0);
  EXPECT_TRUE(stiff.warning.empty());
}

}  // namespace
}  // namespace mssph
