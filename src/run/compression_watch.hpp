#pragma once
// Watches deformable bodies for compression beyond what their material model describes
// (config/elastic_model.hpp): at every logged sample it records each deformable body's smallest
// volume ratio J = det F and how many particles are at or below the model's lowest valid J, warns
// once per body (body, time, value) on stderr, and at the end writes, per body, the fraction of
// logged samples that had any particle outside the valid range.
#include "backend/backend.hpp"
#include "backend/state_arrays.hpp"
#include "io/run_log.hpp"
#include "model/particle_setup.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace mssph {

class CompressionWatch {
 public:
  CompressionWatch(RunLog& log, const ParticleSetup& setup);

  // One logged sample of every body (in body order) at simulated time `time` [s].
  void record(const std::vector<BodyState>& states, double time);

  // Writes the summary attributes of /bodies/<name> and returns the largest fraction over the
  // deformable bodies (0 without any).
  double finish();

  // "block 12.3 %, jelly 0.4 %" for the bodies that left their valid range; "" when none did.
  std::string summary() const;

  // Checkpoints: each body's sample counts and whether it was warned about.
  StateArrays save_state() const;
  void restore_state(const StateArrays& state);

 private:
  struct Watched {
    std::size_t body = 0;
    std::string name;
    std::string model;
    double lowest_valid = 0.0;
    std::size_t min_series = 0, count_series = 0;
    std::size_t samples = 0, samples_outside = 0;
    bool warned = false;
    double fraction() const {
      return samples == 0 ? 0.0 : static_cast<double>(samples_outside) / static_cast<double>(samples);
    }
  };
  RunLog& log_;
  std::vector<Watched> watched_;
};

}  // namespace mssph
