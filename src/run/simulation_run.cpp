#include "simulation_run.hpp"

#include "compression_watch.hpp"
#include "haptics/haptics_run.hpp"
#include "interrupt.hpp"
#include "io/checkpoint_io.hpp"
#include "lost_mass_watch.hpp"
#include "progress.hpp"
#include "util/errors.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <sstream>

namespace mssph {
namespace {

// The datasets of one body under /bodies/<name>.
struct BodySeries {
  std::size_t centre_of_mass, linear_momentum, angular_momentum, kinetic_energy, max_speed;
  std::size_t interaction_force, interaction_torque;
  std::size_t orientation = 0, angular_velocity = 0;  // rigid bodies
  bool rigid = false;
};

std::size_t steps_per(double interval, double dt) {
  return interval <= 0.0 ? 1 : std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(interval / dt)));
}

std::vector<BodySeries> add_body_series(RunLog& log, const ParticleSetup& setup) {
  std::vector<BodySeries> out;
  const std::vector<std::string> xyz{"x", "y", "z"};
  for (const BodySetup& body : setup.bodies) {
    const std::string g = "/bodies/" + body.name;
    log.set_attribute(g, "kind", std::string(to_string(body.kind)));
    log.set_attribute(g, "particle_count", static_cast<long long>(body.count));
    log.set_attribute(g, "lattice_sites", static_cast<long long>(body.lattice_sites));
    log.set_attribute(g, "first_particle", static_cast<long long>(body.first));
    BodySeries s;
    s.centre_of_mass = log.add_series(g + "/centre_of_mass", 3, "m", "centre of mass", xyz);
    s.linear_momentum = log.add_series(g + "/linear_momentum", 3, "kg m/s", "linear momentum", xyz);
    s.angular_momentum =
        log.add_series(g + "/angular_momentum", 3, "kg m^2/s", "angular momentum about the centre of mass", xyz);
    s.kinetic_energy = log.add_series(g + "/kinetic_energy", 1, "J", "kinetic energy");
    s.max_speed = log.add_series(g + "/max_speed", 1, "m/s", "fastest particle's speed");
    s.interaction_force =
        log.add_series(g + "/interaction_force", 3, "N",
                       "sum of forces from other bodies on this body's particles (paper eq. 7, 8)", xyz);
    s.interaction_torque =
        log.add_series(g + "/interaction_torque", 3, "N m",
                       "torque of the interaction forces about the centre of mass (paper eq. 9)", xyz);
    if (body.moves_as_rigid_body()) {
      s.rigid = true;
      log.set_attribute(g, "mass", body.mass);
      s.orientation = log.add_series(g + "/orientation", 4, "1", "orientation quaternion", {"qx", "qy", "qz", "qw"});
      s.angular_velocity = log.add_series(g + "/angular_velocity", 3, "rad/s", "angular velocity, world frame", xyz);
    }
    out.push_back(s);
  }
  return out;
}

void append_vec3(RunLog& log, std::size_t series, const Eigen::Vector3d& v) {
  const double row[3] = {v.x(), v.y(), v.z()};
  log.append(series, row);
}

void append_scalar(RunLog& log, std::size_t series, double v) { log.append(series, std::span<const double>(&v, 1)); }

// The particle of `body` that shows the blow-up in a snapshot: the first with a non-finite
// position or velocity, else the fastest.
std::size_t blow_up_particle(const ParticleSnapshot& snap, const BodySetup& body) {
  std::size_t worst = body.first;
  double worst_speed = -1.0;
  for (std::size_t i = body.first; i < body.first + body.count; ++i) {
    const Eigen::Vector3f x(&snap.position[3 * i]), v(&snap.velocity[3 * i]);
    if (!x.allFinite() || !v.allFinite()) return i;
    if (v.norm() > worst_speed) {
      worst_speed = v.norm();
      worst = i;
    }
  }
  return worst;
}

// A blow-up names the step, body, particle, its position and velocity, and the CFL numbers of
// that velocity against the time step: acoustic dt (c + |v|) / h (stable below 0.25, the bound the
// start-up warnings use, docs/model.md) and advective dt |v| / h.
void check_for_blow_up(const std::vector<BodyState>& states, const ParticleSetup& setup, Backend& backend,
                       std::size_t step) {
  for (std::size_t b = 0; b < states.size(); ++b) {
    const BodyState& s = states[b];
    const bool finite = std::isfinite(s.max_speed) && s.centre_of_mass.allFinite() && s.interaction_force.allFinite();
    if (finite && s.max_speed <= setup.max_speed) continue;
    const BodySetup& body = setup.bodies[b];
    const ParticleSnapshot snap = backend.snapshot();
    const std::size_t i = blow_up_particle(snap, body);
    const Eigen::Vector3f x(&snap.position[3 * i]), v(&snap.velocity[3 * i]);
    const double speed = v.norm();
    const double c = std::sqrt(body.material.pressure_stiffness);
    std::ostringstream message;
    message << "blow-up at step " << step << ", t = " << backend.time() << " s: body \"" << body.name << "\" ";
    if (!finite) {
      message << "has non-finite state (NaN or infinity)";
    } else {
      message << "has a particle at " << s.max_speed << " m/s, beyond simulation/max_speed = " << setup.max_speed
              << " m/s";
    }
    message << "; particle " << i << " at (" << x.x() << ", " << x.y() << ", " << x.z() << ") m, velocity (" << v.x()
            << ", " << v.y() << ", " << v.z()
            << ") m/s; CFL numbers: acoustic dt (c + |v|) / h = " << setup.dt * (c + speed) / setup.smoothing_length
            << " (stable below 0.25), advective dt |v| / h = " << setup.dt * speed / setup.smoothing_length
            << "; reduce dt or stiffness (see the start-up warnings)";
    throw SimulationFailure(message.str());
  }
}

}  // namespace

RunSummary run_simulation(const Scene& scene, const ParticleSetup& setup, Backend& backend, RunLog& log,
                          const RunOptions& options) {
  const double dt = scene.simulation.dt;
  const std::size_t total_steps = static_cast<std::size_t>(std::llround(scene.simulation.duration / dt));
  const std::size_t log_every = steps_per(scene.output.log_interval, dt);
  const std::size_t snapshot_every =
      scene.output.snapshot_interval > 0.0 ? steps_per(scene.output.snapshot_interval, dt) : 0;
  // Blow-ups are looked for at least this often even when logging is sparse.
  const std::size_t check_every = std::min<std::size_t>(log_every, 100);

  std::vector<int> body_of_particle(setup.body.begin(), setup.body.end());
  log.write_array("/particles/body", body_of_particle, "1",
                  "body index of each particle (order of /particles body_names)");
  std::vector<std::string> body_names;
  for (const BodySetup& b : setup.bodies) body_names.push_back(b.name);
  log.set_attribute("/particles", "body_names", body_names);
  log.set_attribute("/", "particle_count", static_cast<long long>(setup.size()));
  log.set_attribute("/", "dt", dt);

  const std::size_t time_series = log.add_series("/time", 1, "s", "simulated time of each logged sample");
  const std::vector<BodySeries> body_series = add_body_series(log, setup);
  const std::size_t step_time_series =
      log.add_series("/timing/step_wall_time", 1, "s",
                     "host wall-clock time of each step (a GPU step returns once queued; its "
                     "device time per phase is in /timing/phases, with --phase-timing)");
  std::optional<std::size_t> phase_series;
  backend.set_phase_timing(options.phase_timing);
  if (options.phase_timing) {
    const std::vector<std::string> phases = backend.phase_names();
    log.set_attribute("/timing", "phase_names", phases);
    phase_series =
        log.add_series("/timing/phases", phases.size(), "s", "wall-clock time of each phase of each step", phases);
  }

  std::size_t force_body = setup.bodies.size();
  if (scene.proxy) {
    for (std::size_t b = 0; b < setup.bodies.size(); ++b) {
      if (setup.bodies[b].name == scene.proxy->body) force_body = b;
    }
  }

  CompressionWatch compression(log, setup);
  LostMassWatch lost_mass(log, setup);
  std::optional<HapticsRun> haptics;
  if (scene.proxy) haptics.emplace(scene, setup, log, options.record_device, options.replace_recording);

  RunSummary summary;
  summary.force_body = force_body < setup.bodies.size() ? setup.bodies[force_body].name : "";

  // The stepping loop's wall-clock time, over every process that ran it (a restarted run's
  // checkpoint carries its earlier processes').
  double earlier_wall_seconds = 0.0;
  const auto start = std::chrono::steady_clock::now();
  const auto wall_seconds = [&] {
    return earlier_wall_seconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };

  // Checkpoints: every part of the run that carries state from one step to the next.
  const auto save_state = [&] {
    StateArrays state;
    state.add_part("backend", backend.save_state());
    if (haptics) state.add_part("haptics", haptics->save_state());
    state.add_part("compression", compression.save_state());
    state.add_part("lost_mass", lost_mass.save_state());
    state.put_scalar("run/peak_force", summary.peak_force);
    state.put_scalar("run/wall_seconds", wall_seconds());
    return state;
  };
  std::size_t first_step = 1;
  if (const Checkpoint* restart = log.restart_point()) {
    try {
      backend.restore_state(restart->state.part("backend"));
      if (haptics) haptics->restore_state(restart->state.part("haptics"));
      compression.restore_state(restart->state.part("compression"));
      lost_mass.restore_state(restart->state.part("lost_mass"));
      summary.peak_force = restart->state.scalar("run/peak_force");
      earlier_wall_seconds = restart->state.scalar("run/wall_seconds");
    } catch (const InputError& e) {
      throw InputError("--restart " + log.path() + ": the checkpoint of step " + std::to_string(restart->step) +
                       " does not fit the scene and backend: " + e.what());
    }
    summary.steps = static_cast<std::size_t>(restart->step);
    first_step = summary.steps + 1;
  }
  std::size_t checkpoint_step = summary.steps;  // the latest checkpoint's
  // The grid builds of the steps this process runs, for the log's rate (Backend::neighbour_grid_builds).
  const std::optional<std::uint64_t> grid_builds_at_start = backend.neighbour_grid_builds();
  const std::size_t steps_at_start = summary.steps;

  ProgressReporter progress(total_steps, dt, options.quiet, summary.steps);
  auto last_flush = std::chrono::steady_clock::now();
  auto last_checkpoint = last_flush;

  const auto write_snapshot = [&](std::size_t step) {
    const ParticleSnapshot snap = backend.snapshot();
    log.add_snapshot(static_cast<long long>(step), backend.time(),
                     SnapshotFields{snap.position, snap.velocity, snap.density, snap.pressure});
  };

  try {
    if (snapshot_every > 0 && first_step == 1) write_snapshot(0);
    for (std::size_t step = first_step; step <= total_steps; ++step) {
      const auto step_start = std::chrono::steady_clock::now();
      if (haptics) haptics->before_step(backend, step - 1);  // ticks of this step, and its coupling wrench
      backend.step();
      const double step_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - step_start).count();
      append_scalar(log, step_time_series, step_seconds);
      if (phase_series) log.append(*phase_series, backend.last_phase_seconds());

      const bool log_now = step % log_every == 0 || step == total_steps;
      if (log_now || step % check_every == 0) {
        const std::vector<BodyState> states = backend.body_states();
        lost_mass.check(states, backend.time());  // before the blow-up check: a lost particle is not one
        check_for_blow_up(states, setup, backend, step);
        if (force_body < states.size()) {
          summary.peak_force = std::max(summary.peak_force, states[force_body].interaction_force.norm());
        }
        if (log_now) {
          append_scalar(log, time_series, backend.time());
          compression.record(states, backend.time());
          lost_mass.record(states);
          for (std::size_t b = 0; b < states.size(); ++b) {
            const BodyState& s = states[b];
            const BodySeries& series = body_series[b];
            append_vec3(log, series.centre_of_mass, s.centre_of_mass);
            append_vec3(log, series.linear_momentum, s.linear_momentum);
            append_vec3(log, series.angular_momentum, s.angular_momentum);
            append_scalar(log, series.kinetic_energy, s.kinetic_energy);
            append_scalar(log, series.max_speed, s.max_speed);
            append_vec3(log, series.interaction_force, s.interaction_force);
            append_vec3(log, series.interaction_torque, s.interaction_torque);
            if (series.rigid) {
              const double q[4] = {s.orientation.x(), s.orientation.y(), s.orientation.z(), s.orientation.w()};
              log.append(series.orientation, q);
              append_vec3(log, series.angular_velocity, s.angular_velocity);
            }
          }
        }
      }
      if (snapshot_every > 0 && step % snapshot_every == 0) write_snapshot(step);

      const auto now = std::chrono::steady_clock::now();
      if (std::chrono::duration<double>(now - last_flush).count() > scene.output.flush_interval) {
        log.flush();
        last_flush = now;
      }
      summary.steps = step;
      progress.update(step);
      const int signal = interrupt_signal();
      const bool checkpoint_due =
          options.checkpoint_interval > 0.0 && step < total_steps &&
          std::chrono::duration<double>(now - last_checkpoint).count() >= options.checkpoint_interval;
      if (signal || checkpoint_due) {
        log.write_checkpoint(static_cast<long long>(step), backend.time(), save_state());
        checkpoint_step = step;
        last_checkpoint = std::chrono::steady_clock::now();
      }
      if (signal) {
        std::ostringstream reason;
        reason << signal_name(signal) << " after step " << step << " of " << total_steps << ", t = " << backend.time()
               << " s";
        if (checkpoint_step == step) reason << "; checkpoint written: continue with mssph run --restart";
        throw RunInterrupted(reason.str(), signal);
      }
    }
  } catch (const std::exception& failure) {
    // Any failure inside the loop (blow-up, interruption, I/O) is recorded before it propagates,
    // as far as the disk allows: a write error must not hide the original failure.
    try {
      log.set_attribute("/", "steps", static_cast<long long>(summary.steps));
      compression.finish();
      lost_mass.finish();
    } catch (const std::exception&) {
    }
    if (haptics) {
      haptics->finish_failed(summary.steps, wall_seconds());
    }
    if (dynamic_cast<const RunInterrupted*>(&failure)) {
      log.finish_interrupted(failure.what());
    } else {
      log.finish_failed(failure.what());
    }
    throw;
  }
  summary.wall_seconds = wall_seconds();
  summary.simulated_time = backend.time();
  if (haptics) {
    haptics->finish(backend, summary.steps, summary.wall_seconds);
    summary.peak_rendered_force = haptics->peak_rendered_force();
    summary.recording_error = haptics->recording_error();
  }

  summary.fraction_outside_valid_range = compression.finish();
  summary.outside_valid_range = compression.summary();
  summary.left_domain = lost_mass.finish();
  log.set_attribute("/", "steps", static_cast<long long>(summary.steps));
  log.set_attribute("/", "simulated_time", summary.simulated_time);
  log.set_attribute("/", "wall_time", summary.wall_seconds);
  if (grid_builds_at_start && summary.steps > steps_at_start) {
    const auto builds = static_cast<double>(*backend.neighbour_grid_builds() - *grid_builds_at_start);
    log.set_attribute("/", "neighbour_grid_builds_per_step",
                      builds / static_cast<double>(summary.steps - steps_at_start));
  }
  if (!summary.force_body.empty()) {
    log.set_attribute("/", "peak_force_body", summary.force_body);
    log.set_attribute("/", "peak_interaction_force", summary.peak_force);
  }
  log.finish_completed();
  return summary;
}

}  // namespace mssph
