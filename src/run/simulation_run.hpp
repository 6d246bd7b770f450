#pragma once
// Drives a backend through a scene's duration: logs body states and per-phase timings to the run
// log at the scene's log rate, runs the haptic loop of a scene with a proxy (src/haptics), writes
// snapshots, watches for blow-ups, reports progress, and marks the log completed or failed.
#include "backend/backend.hpp"
#include "config/scene.hpp"
#include "io/run_log.hpp"
#include "model/particle_setup.hpp"

#include <optional>
#include <string>

namespace mssph {

struct RunOptions {
  bool quiet = false;
  // Write the haptic device's trajectory here (.csv or .h5) when the run completes; "" for none.
  std::string record_device;
  bool phase_timing = false;  // log /timing/phases (Backend::set_phase_timing)
  // Wall-clock seconds between checkpoints (RunLog::write_checkpoint); 0 for none. SIGINT,
  // SIGTERM and SIGHUP write one either way before the run stops.
  double checkpoint_interval = 0.0;
  bool replace_recording = false;  // --force: the recording may replace an existing regular file
};

struct RunSummary {
  std::size_t steps = 0;
  double simulated_time = 0.0;                // [s]
  double wall_seconds = 0.0;                  // [s] the stepping loop alone
  std::string force_body;                     // the body whose peak force is reported (the proxy, if any)
  double peak_force = 0.0;                    // max |interaction force| on force_body [N]
  std::optional<double> peak_rendered_force;  // max |force| the haptic device rendered [N]; runs with a proxy
  // Deformable bodies compressed beyond their material model's valid range (src/run/compression_watch.hpp):
  // the largest fraction of logged samples over the bodies [-], and "block 12.3 %, ..." ("" if none).
  double fraction_outside_valid_range = 0.0;
  std::string outside_valid_range;
  // Bodies that lost particles out of the simulation domain (sim/lost_mass_watch.hpp):
  // "block 2 particles (0.03 %), ..." ("" if none).
  std::string left_domain;
  // Why the device recording of the completed run was not written, and what that loses; "" when
  // it was written or none was asked for (HapticsRun::recording_error).
  std::string recording_error;
};

// Runs to the end of the scene. On a blow-up the log is marked "failed: ..." and the
// SimulationFailure propagates. A log reopened for a restart (RunLog::restart_point) continues
// from its checkpoint: `backend` must be fresh, of the setup and backend kind that wrote it; a
// checkpoint that does not fit throws InputError naming the log, before the log is changed.
RunSummary run_simulation(const Scene& scene, const ParticleSetup& setup, Backend& backend, RunLog& log,
                          const RunOptions& options);

}  // namespace mssph
