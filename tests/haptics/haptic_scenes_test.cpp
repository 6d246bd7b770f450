// The shipped haptic scenes (configs/tap.json, squeeze.json, stir.json) on the reference backend
// at a coarse 4 cm spacing, cut short after the motion each is about: what the user would feel
// must follow from the physics of the medium touched.
#include "haptics_cli_support.hpp"
#include "temp_dir.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>

namespace mssph::test {
namespace {

constexpr double kGravity = 9.81;  // the scenes' |g| [m/s^2]

// One scene's run log, read back.
struct SceneRun {
  h5::Handle file;
  std::vector<double> time;
  std::vector<Eigen::Vector3d> proxy_position, proxy_velocity, interaction, coupling, rendered;
  double proxy_mass = 0.0;

  // Mean of f(tick) over the ticks with t in [from, to].
  double mean(double from, double to, const std::function<double(std::size_t)>& f) const {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < time.size(); ++i) {
      if (time[i] < from || time[i] > to) continue;
      sum += f(i);
      ++count;
    }
    EXPECT_GT(count, 0u) << "no tick in [" << from << ", " << to << "]";
    return count ? sum / static_cast<double>(count) : 0.0;
  }
};

class HapticScene : public ::testing::Test {
 protected:
  // Runs configs/<scene>.json at 4 cm spacing for `duration` seconds and reads its log back.
  SceneRun run(const std::string& scene, double duration, std::vector<std::string> extra = {}) {
    const std::string out = (dir_ / (scene + std::to_string(runs_++) + ".h5")).string();
    std::vector<std::string> args{"run",
                                  MSSPH_SOURCE_DIR "/configs/" + scene + ".json",
                                  "--out",
                                  out,
                                  "-q",
                                  "--set",
                                  "simulation/particle_spacing=0.04",
                                  "--set",
                                  "simulation/duration=" + std::to_string(duration)};
    for (std::string& e : extra) args.push_back(std::move(e));
    const ProcessResult r = run_mssph(args, dir_.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_THAT(r.err, ::testing::Not(::testing::HasSubstr("warning: proxy"))) << "the scene's gains are stable";

    SceneRun s;
    s.file = open_read_only(out);
    const hid_t f = s.file.id();
    EXPECT_EQ(h5::read_string_attribute(f, "status"), "completed");
    s.time = read_doubles(f, "/haptics/time");
    s.proxy_position = read_vec3(f, "/haptics/proxy/position");
    s.proxy_velocity = read_vec3(f, "/haptics/proxy/linear_velocity");
    s.interaction = read_vec3(f, "/haptics/interaction/force");
    s.coupling = read_vec3(f, "/haptics/coupling/force");
    s.rendered = read_vec3(f, "/haptics/rendered/force");
    const std::string body = h5::read_string_attribute(open_object(f, "/haptics").id(), "proxy_body");
    s.proxy_mass = h5::read_double_attribute(open_object(f, "/bodies/" + body).id(), "mass");

    // Every tick at 1 kHz, each with one proxy state query (dt = 0.25 ms: four steps per tick).
    const auto ticks = static_cast<long long>(std::llround(duration * 1000.0)) + 1;
    EXPECT_EQ(read_integer_attribute(open_object(f, "/haptics").id(), "ticks"), ticks);
    EXPECT_EQ(read_integer_attribute(open_object(f, "/haptics").id(), "proxy_state_queries"), ticks);
    EXPECT_EQ(s.time.size(), static_cast<std::size_t>(ticks));
    EXPECT_LE(haptics_attribute(f, "peak_rendered_force_N"), 30.0);  // the Virtuose's limit
    // A passive coupling: see CouplingGains.StableDefaultsRunPassivelyWithoutWarnings.
    const double balance = haptics_attribute(f, "energy_balance_J");
    EXPECT_LT(balance, 0.0);
    EXPECT_LE(haptics_attribute(f, "max_injected_energy_J"), 1e-3 * -balance);
    for (const char* attribute : {"simulation_rate_Hz", "haptic_rate_Hz", "real_time_factor"}) {
      EXPECT_GT(haptics_attribute(f, attribute), 0.0) << attribute;
    }
    return s;
  }

  TempDir dir_;
  int runs_ = 0;
};

TEST_F(HapticScene, TapOnARigidBlockIsFeltAsTheBlocksReaction) {
  const SceneRun tap = run("tap", 0.75);  // hold the sphere, press it onto the block, hold the press
  const double weight = tap.proxy_mass * kGravity;

  // Before the contact the hand carries the hanging sphere: the device renders its weight,
  // downwards. 10 %: the sphere still swings a little on the coupling from the start.
  const double hanging = tap.mean(0.15, 0.2, [&](std::size_t i) { return tap.rendered[i].z(); });
  EXPECT_NEAR(hanging, -weight, 0.1 * weight);

  // The hand goes 8 cm past the block's top face: unimpeded, the sphere would end at z = 0.32 m.
  // The block stops it within a particle spacing of touching (0.40 m), and pushes the hand back
  // up: with the hand and the coupling springs in series, ~20 N.
  double lowest = 1.0;
  for (const Eigen::Vector3d& p : tap.proxy_position) lowest = std::min(lowest, p.z());
  EXPECT_GT(lowest, 0.36);
  const double pressed = tap.mean(0.6, 0.75, [&](std::size_t i) { return tap.rendered[i].z(); });
  RecordProperty("rendered_force_while_pressing_N", std::to_string(pressed));
  EXPECT_GT(pressed, 10.0);

  // Resting on the block, the sphere is in equilibrium (paper eq. 8 with the device term): the
  // block's SPH reaction carries its weight plus the coupling's push. The contact force sampled
  // at ticks scatters by ~1 N, so the mean over 150 ticks holds the balance to a few percent.
  const double reaction = tap.mean(0.6, 0.75, [&](std::size_t i) { return tap.interaction[i].z(); });
  const double load = tap.mean(0.6, 0.75, [&](std::size_t i) { return weight - tap.coupling[i].z(); });
  RecordProperty("block_reaction_N", std::to_string(reaction));
  RecordProperty("weight_plus_push_N", std::to_string(load));
  EXPECT_NEAR(reaction, load, 0.05 * load);
}

TEST_F(HapticScene, SqueezingASofterBlockSinksTheSphereDeeper) {
  // The hand presses the sphere 8 cm past the block's face and holds; the same with a block ten
  // times stiffer (E = 500 kPa: c_p = 26 m/s, still within 0.25 h / c_p = 0.77 ms at h = 8 cm).
  const SceneRun soft = run("squeeze", 0.8);
  const SceneRun stiff = run("squeeze", 0.8, {"--set", "materials/soft_tissue/young_modulus=5e5"});
  const auto depth = [](const SceneRun& s) {
    return s.mean(0.7, 0.8, [&](std::size_t i) { return s.proxy_position[i].z(); });
  };
  const double pressed = soft.mean(0.7, 0.8, [&](std::size_t i) { return soft.rendered[i].z(); });
  RecordProperty("rendered_force_while_pressing_N", std::to_string(pressed));
  RecordProperty("extra_depth_in_soft_block_m", std::to_string(depth(stiff) - depth(soft)));
  EXPECT_GT(pressed, 10.0);  // felt: ~17 N from the hand and coupling springs in series
  // Hertz (d = (3 F / (4 E* sqrt(R)))^(2/3), F = 17 N, R = 0.2 m) puts the soft block's
  // indentation 4.9 mm deeper than the stiff one's; at 4 cm spacing the difference comes out
  // smaller, but far above the scatter of the resting height (0.1 mm over the 100 ticks).
  EXPECT_GT(depth(stiff) - depth(soft), 1e-3);
}

TEST_F(HapticScene, StirringALiquidIsFeltAsDragAndBuoyancy) {
  const SceneRun stir = run("stir", 1.0);  // dip the rod (0.5 s), then half a turn of stirring
  const auto horizontal = [](const Eigen::Vector3d& v) { return Eigen::Vector3d(v.x(), v.y(), 0.0); };

  // The liquid takes energy from the moving rod: its horizontal force opposes the rod's motion.
  // A drag force points against the velocity (cosine -1); -0.5 leaves room for the pressure
  // noise of a rod one particle across and for its wake.
  const double power =
      stir.mean(0.6, 1.0, [&](std::size_t i) { return horizontal(stir.interaction[i]).dot(stir.proxy_velocity[i]); });
  const double force = stir.mean(0.6, 1.0, [&](std::size_t i) { return horizontal(stir.interaction[i]).norm(); });
  const double speed = stir.mean(0.6, 1.0, [&](std::size_t i) { return horizontal(stir.proxy_velocity[i]).norm(); });
  RecordProperty("drag_power_W", std::to_string(power));
  EXPECT_LT(power, -0.5 * force * speed);

  // Archimedes: the rod (4 x 4 cm) dips ~8.5 cm below the surface (z = 0.16 m): 1.3 N up. 30 %:
  // at 4 cm spacing the immersed depth is known to about half a spacing.
  const double tip = stir.mean(0.6, 1.0, [&](std::size_t i) { return stir.proxy_position[i].z() - 0.16; });
  const double immersed = 0.16 - tip;  // the rod is 32 cm long; the liquid's surface is at 0.16 m
  const double buoyancy = 1000.0 * kGravity * 0.04 * 0.04 * immersed;
  const double lift = stir.mean(0.6, 1.0, [&](std::size_t i) { return stir.interaction[i].z(); });
  RecordProperty("buoyancy_N", std::to_string(lift));
  RecordProperty("archimedes_N", std::to_string(buoyancy));
  EXPECT_NEAR(lift, buoyancy, 0.3 * buoyancy);

  // And the hand feels the stirring: the device renders a horizontal force while the rod moves.
  EXPECT_GT(stir.mean(0.6, 1.0, [&](std::size_t i) { return horizontal(stir.rendered[i]).norm(); }), 0.5);
}

}  // namespace
}  // namespace mssph::test
