#pragma once
// A shard of a sweep: shard K of N runs the points whose index i has i % N == K, so N shards
// together run every point exactly once, and each shard's points spread over the whole sweep.
#include <cstddef>
#include <map>
#include <optional>
#include <string>

namespace mssph::sweep {

struct Shard {
  std::size_t index = 0;  // K, 0 <= K < N
  std::size_t count = 1;  // N
  bool contains(std::size_t point_index) const { return point_index % count == index; }
  std::string describe() const;  // "K/N"
};

// "K/N" from --shard; throws InputError naming the text when it is not one.
Shard parse_shard(const std::string& text);

// The shard of a Slurm array task, from its environment: SLURM_ARRAY_TASK_ID with
// SLURM_ARRAY_TASK_COUNT, or SLURM_ARRAY_TASK_MIN and _MAX (K = ID - MIN, N = MAX - MIN + 1)
// when the count is not set. nullopt outside an array job. Throws InputError when the variables
// are there but inconsistent. `environment` maps names to values (the process's in use).
std::optional<Shard> shard_from_slurm(const std::map<std::string, std::string>& environment);

// The variables above from the process's environment.
std::map<std::string, std::string> slurm_array_environment();

}  // namespace mssph::sweep
