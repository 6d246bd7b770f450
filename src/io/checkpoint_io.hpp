#pragma once
// Checkpoints inside a run log (`mssph run --checkpoint-interval`, `--restart`): two slots,
// /checkpoint/a and /checkpoint/b, written in turn, so that a run killed while writing one still
// has the other. A slot holds a whole state (backend/state_arrays.hpp) under state/, one dataset of
// its own type per array, and the row count of every time series at that step (series_rows,
// whose `series` attribute names the datasets, one per line). Its `step` attribute is -1 while it
// is being written and the checkpoint's step once it is whole and flushed.
#include "backend/state_arrays.hpp"
#include "util/hdf5_handle.hpp"

#include <map>
#include <optional>
#include <string>

namespace mssph {

struct Checkpoint {
  long long step = 0;  // steps done
  double time = 0.0;   // simulated time [s]
  StateArrays state;
  std::map<std::string, hsize_t> series_rows;  // time series dataset path -> rows at the step
};

// Writes `checkpoint` into the slot that does not hold the latest whole checkpoint, flushing the
// file before the slot is marked whole.
void write_checkpoint(hid_t file, const Checkpoint& checkpoint);

// The latest whole checkpoint of the file, if any.
std::optional<Checkpoint> read_latest_checkpoint(hid_t file);
// Its step alone (reading no arrays), -1 when the file holds none.
long long latest_checkpoint_step(hid_t file);

// Bytes the arrays of `state` take, to reserve disk space before writing them.
long long state_bytes(const StateArrays& state);

}  // namespace mssph
