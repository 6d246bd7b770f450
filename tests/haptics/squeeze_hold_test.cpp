// What the hand feels while it holds the proxy pressed into the soft block of configs/squeeze.json
// (the hold phase, 0.6 s to 1.0 s of the script): a steady push, not a buzz. The contact force
// on the proxy and the force the device renders may change from one haptic tick (1 ms) to the
// next only by what a steady press explains, and the proxy may not bounce off the block.
//
// At 4 cm spacing (the CI's), on the float32 cpu backend, 0.8 s: the window 0.65 s to 0.8 s
// starts once the hand has stopped and the approach transient has passed.
#include "h5_read.hpp"
#include "run/scene_run.hpp"
#include "temp_dir.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace mssph {
namespace {

constexpr double kWindowStart = 0.65;  // [s]
constexpr double kWindowEnd = 0.8;     // [s]

struct HoldPhase {
  double max_rendered_jump = 0.0;  // max |rendered force - previous tick's| [N]
  double max_contact_jump = 0.0;   // max |interaction force - previous tick's| [N]
  double mean_contact = 0.0;       // mean |interaction force| [N]
  double min_contact = 1e300;      // min |interaction force| [N]
};

HoldPhase measure_hold(const std::vector<std::string>& extra) {
  test::TempDir dir;
  cli::SceneRunRequest request;
  request.scene_path = std::string(MSSPH_SOURCE_DIR) + "/configs/squeeze.json";
  request.overrides = {"simulation/particle_spacing=0.04", "simulation/duration=" + std::to_string(kWindowEnd)};
  request.overrides.insert(request.overrides.end(), extra.begin(), extra.end());
  request.backend = "cpu";
  request.output = (dir / "squeeze.h5").string();
  request.quiet = true;
  const cli::SceneRunResult result = cli::run_scene(request);
  EXPECT_EQ(result.exit_code, 0) << result.error;

  const h5::Handle file = test::open_read_only(result.output);
  const std::vector<double> time = test::read_doubles(file.id(), "/haptics/time");
  const std::vector<double> jump = test::read_doubles(file.id(), "/haptics/force_jump");
  const std::vector<double> contact = test::read_doubles(file.id(), "/haptics/interaction/force");
  HoldPhase hold;
  std::size_t samples = 0;
  for (std::size_t k = 1; k < time.size(); ++k) {
    if (time[k] < kWindowStart || time[k] > kWindowEnd) continue;
    hold.max_rendered_jump = std::max(hold.max_rendered_jump, jump[k]);
    double step = 0.0, magnitude = 0.0;
    for (std::size_t a = 0; a < 3; ++a) {
      step += std::pow(contact[3 * k + a] - contact[3 * (k - 1) + a], 2);
      magnitude += std::pow(contact[3 * k + a], 2);
    }
    hold.max_contact_jump = std::max(hold.max_contact_jump, std::sqrt(step));
    hold.mean_contact += std::sqrt(magnitude);
    hold.min_contact = std::min(hold.min_contact, std::sqrt(magnitude));
    ++samples;
  }
  EXPECT_GT(samples, 100u);
  hold.mean_contact /= static_cast<double>(samples);
  return hold;
}

TEST(SqueezeHold, TheHeldPressIsSteadyFromTickToTick) {
  const HoldPhase hold = measure_hold({});
  RecordProperty("max_rendered_force_jump_N", std::to_string(hold.max_rendered_jump));
  RecordProperty("max_contact_force_jump_N", std::to_string(hold.max_contact_jump));
  RecordProperty("mean_contact_force_N", std::to_string(hold.mean_contact));
  RecordProperty("min_contact_force_N", std::to_string(hold.min_contact));
  std::cout << "hold phase: rendered force jump per tick up to " << hold.max_rendered_jump
            << " N, contact force jump up to " << hold.max_contact_jump << " N, contact force " << hold.min_contact
            << " N to mean " << hold.mean_contact << " N\n";
  // With the hand still, the contact force on the proxy balances the coupling's pull (the hand's
  // and the coupling's springs in series, ~17 N) and the proxy's weight (3 N): a steady press
  // changes from tick to tick only as the block creeps. The 3 N bound per 1 ms tick (15 % of the
  // press) is the rendered force's below, so that the steadiness the hand feels does not rest on
  // the coupling and the device filtering a buzz (measured: 1.34 N with the block's pressure read
  // from its contact layer's density; 35 N with its own body's neighbours counted live, the
  // proxy bouncing off the block, results/decisions/005-contact-layer-density.md).
  EXPECT_LT(hold.max_contact_jump, 3.0);
  // The proxy stays on the block: never near contact loss (a bouncing proxy drops to 0 N).
  EXPECT_GT(hold.min_contact, 0.5 * hold.mean_contact);
  // What the hand feels: the rendered force may change by at most 3 N from one 1 ms tick to the
  // next (a margin over the 2.5 N that the coupling spring and the device's mass let through of
  // the bouncing proxy's 0 to 90 N; measured now 0.075 N; not a formula).
  EXPECT_LT(hold.max_rendered_jump, 3.0);
  EXPECT_GT(hold.mean_contact, 10.0);  // the proxy is pressed onto the block, not hovering
}

}  // namespace
}  // namespace mssph
