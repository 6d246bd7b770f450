#include "sweep/shard.hpp"

#include "util/errors.hpp"

#include <cstdlib>
#include <regex>

namespace mssph::sweep {
namespace {

std::optional<long long> read_count(const std::string& text) {
  static const std::regex number("[0-9]{1,12}");
  if (!std::regex_match(text, number)) return std::nullopt;
  return std::stoll(text);
}

const char* const kSlurmArrayVariables[] = {"SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_COUNT", "SLURM_ARRAY_TASK_MIN",
                                            "SLURM_ARRAY_TASK_MAX"};

}  // namespace

std::string Shard::describe() const { return std::to_string(index) + "/" + std::to_string(count); }

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  const auto k = slash == std::string::npos ? std::nullopt : read_count(text.substr(0, slash));
  const auto n = slash == std::string::npos ? std::nullopt : read_count(text.substr(slash + 1));
  if (!k || !n || *n < 1 || *k >= *n) {
    throw InputError("--shard " + text + ": expected K/N with 0 <= K < N, e.g. --shard 0/4 for the first of 4 shards");
  }
  return Shard{static_cast<std::size_t>(*k), static_cast<std::size_t>(*n)};
}

std::optional<Shard> shard_from_slurm(const std::map<std::string, std::string>& environment) {
  const auto get = [&](const char* name) -> std::optional<std::string> {
    const auto it = environment.find(name);
    if (it == environment.end() || it->second.empty()) return std::nullopt;
    return it->second;
  };
  const auto id_text = get("SLURM_ARRAY_TASK_ID");
  if (!id_text) return std::nullopt;
  const auto fail = [&](const std::string& why) -> Shard {
    std::string values;
    for (const char* name : kSlurmArrayVariables)
      values += std::string(" ") + name + "=" + get(name).value_or("(unset)");
    throw InputError("cannot shard this Slurm array task:" + values + ": " + why + "; pass --shard K/N");
  };
  const auto id = read_count(*id_text);
  if (!id) return fail("the task id is not a number");
  const auto min = get("SLURM_ARRAY_TASK_MIN") ? read_count(*get("SLURM_ARRAY_TASK_MIN")) : std::optional<long long>(0);
  if (!min || *id < *min) return fail("the task id is below the array's first index");
  std::optional<long long> count;
  if (const auto c = get("SLURM_ARRAY_TASK_COUNT")) {
    count = read_count(*c);
  } else if (const auto max = get("SLURM_ARRAY_TASK_MAX")) {
    if (const auto m = read_count(*max)) count = *m - *min + 1;
  }
  if (!count || *count < 1)
    return fail("neither SLURM_ARRAY_TASK_COUNT nor SLURM_ARRAY_TASK_MIN/_MAX give the array's size");
  if (*id - *min >= *count) return fail("the task id is beyond the array's size (an array with a step?)");
  return Shard{static_cast<std::size_t>(*id - *min), static_cast<std::size_t>(*count)};
}

std::map<std::string, std::string> slurm_array_environment() {
  std::map<std::string, std::string> out;
  for (const char* name : kSlurmArrayVariables) {
    if (const char* v = std::getenv(name)) out[name] = v;
  }
  return out;
}

}  // namespace mssph::sweep
