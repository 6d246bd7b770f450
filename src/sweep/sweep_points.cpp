#include "sweep/sweep_points.hpp"

#include "config/scene_loader.hpp"
#include "util/errors.hpp"

#include <cstdint>
#include <cstdio>
#include <map>
#include <stdexcept>

namespace mssph::sweep {
namespace {

std::string override_path(const std::string& assignment) {
  std::string path = assignment.substr(0, assignment.find('='));
  if (!path.empty() && path.front() == '/') path.erase(0, 1);
  return path;
}

// The values of each parameter at one point: index i of every list for zip, the mixed-radix
// digits of the combination number for product (the last parameter varies fastest).
std::vector<std::vector<std::size_t>> combinations(const SweepFile& sweep) {
  std::vector<std::vector<std::size_t>> out;
  const std::size_t n = sweep.parameters.size();
  if (sweep.combine == Combine::zip) {
    for (std::size_t i = 0; i < sweep.parameters.front().values.size(); ++i) out.emplace_back(n, i);
    return out;
  }
  std::size_t total = 1;
  for (const SweepParameter& p : sweep.parameters) total *= p.values.size();
  for (std::size_t c = 0; c < total; ++c) {
    std::vector<std::size_t> digits(n);
    std::size_t rest = c;
    for (std::size_t k = n; k-- > 0;) {
      digits[k] = rest % sweep.parameters[k].values.size();
      rest /= sweep.parameters[k].values.size();
    }
    out.push_back(std::move(digits));
  }
  return out;
}

}  // namespace

std::string SweepPoint::describe() const {
  std::vector<std::string> words;
  for (const auto& [name, value] : parameters) words.push_back(name + "=" + value.dump());
  if (seed) words.push_back("seed=" + std::to_string(*seed));
  std::string text;
  for (const std::string& w : words) {
    if (!text.empty()) text += ' ';
    text += w;
  }
  return text;
}

std::string SweepPoint::log_name() const { return "point-" + hash + ".h5"; }

std::vector<SweepPoint> expand_points(const SweepFile& sweep, const std::vector<std::string>& command_line_overrides) {
  std::vector<std::optional<long long>> seeds;
  for (long long s : sweep.seeds) seeds.emplace_back(s);
  if (seeds.empty()) seeds.emplace_back(std::nullopt);

  std::vector<SweepPoint> points;
  for (const std::vector<std::size_t>& combination : combinations(sweep)) {
    for (const std::optional<long long>& seed : seeds) {
      SweepPoint point;
      point.index = points.size();
      point.overrides = sweep.fixed_overrides;
      point.overrides.insert(point.overrides.end(), command_line_overrides.begin(), command_line_overrides.end());
      for (std::size_t k = 0; k < sweep.parameters.size(); ++k) {
        const SweepParameter& p = sweep.parameters[k];
        const nlohmann::json& value = p.values[combination[k]];
        point.parameters.emplace_back(p.name, value);
        point.overrides.push_back(p.path + "=" + value.dump());
      }
      if (seed) point.overrides.push_back(std::string(kSeedPath) + "=" + std::to_string(*seed));
      point.seed = seed;
      points.push_back(std::move(point));
    }
  }
  return points;
}

void validate_points(const SweepFile& sweep, const std::vector<std::string>& command_line_overrides,
                     std::vector<SweepPoint>& points) {
  for (const std::string& o : command_line_overrides) {
    const std::string path = override_path(o);
    for (const SweepParameter& p : sweep.parameters) {
      if (p.path == path) {
        throw InputError("--set " + o + ": " + path + " is swept by " + sweep.source_file + " " + p.pointer +
                         "; a --set would be overwritten at every point");
      }
    }
    if (path == kSeedPath && !sweep.seeds.empty()) {
      throw InputError("--set " + o + ": " + sweep.source_file + " repeats each point with its own seeds");
    }
  }
  std::map<std::string, std::size_t> seen;  // hash -> index of the first point with it
  for (SweepPoint& point : points) {
    try {
      point.hash = point_hash(load_scene(sweep.scene_path, point.overrides).document);
    } catch (const InputError& e) {
      throw InputError(sweep.source_file + ": point " + std::to_string(point.index) + " (" + point.describe() +
                       ") is rejected by the scene loader: " + e.what());
    }
    // Distinct values give distinct scenes (the file admits no duplicates), so equal names could
    // only be a collision of the 64-bit hash: two points would then share one log.
    const auto [it, inserted] = seen.emplace(point.hash, point.index);
    if (!inserted) {
      throw std::runtime_error(sweep.source_file + ": points " + std::to_string(it->second) + " (" +
                               points[it->second].describe() + ") and " + std::to_string(point.index) + " (" +
                               point.describe() + ") hash to the same name point-" + point.hash);
    }
  }
}

std::string point_hash(const nlohmann::json& scene_document) { return fnv1a_64_hex(scene_document.dump()); }

std::string fnv1a_64_hex(std::string_view bytes) {
  // FNV-1a, 64 bits (Fowler, Noll, Vo; offset basis and prime from the published parameters).
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

}  // namespace mssph::sweep
