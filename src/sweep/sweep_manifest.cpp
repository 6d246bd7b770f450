#include "sweep/sweep_manifest.hpp"

#include "util/build_info.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace mssph::sweep {

nlohmann::json make_manifest(const SweepFile& sweep, const std::vector<SweepPoint>& points,
                             const ManifestContext& context) {
  nlohmann::json m;
  m["format"] = "mssph sweep 1";
  m["name"] = sweep.name;
  m["description"] = sweep.description;
  m["sweep_file"] = std::filesystem::absolute(sweep.source_file).lexically_normal().string();
  m["sweep"] = sweep.document;
  m["scene"] = std::filesystem::absolute(sweep.scene_path).lexically_normal().string();
  m["command_line_overrides"] = context.command_line_overrides;
  m["backend"] = context.backend;
  m["combine"] = sweep.combine == Combine::zip ? "zip" : "product";
  m["seeds"] = sweep.seeds;
  m["metrics"] = sweep.metrics;
  m["mssph_version"] = build_info().version;
  m["git_commit"] = build_info().git_commit;
  nlohmann::json parameters = nlohmann::json::array();
  for (const SweepParameter& p : sweep.parameters) {
    parameters.push_back({{"name", p.name}, {"path", p.path}, {"scale", to_string(p.scale)}, {"values", p.values}});
  }
  m["parameters"] = parameters;
  nlohmann::json list = nlohmann::json::array();
  for (const SweepPoint& point : points) {
    nlohmann::json values = nlohmann::json::object();
    for (const auto& [name, value] : point.parameters) values[name] = value;
    list.push_back({{"index", point.index},
                    {"hash", point.hash},
                    {"log", std::string(kPointsFolder) + "/" + point.log_name()},
                    {"parameters", values},
                    {"seed", point.seed ? nlohmann::json(*point.seed) : nlohmann::json(nullptr)},
                    {"overrides", point.overrides}});
  }
  m["points"] = list;
  return m;
}

void write_manifest(const std::string& directory, const nlohmann::json& manifest) {
  std::filesystem::create_directories(directory);
  const std::filesystem::path target = std::filesystem::path(directory) / kManifestName;
  // A name of its own per process and host: shards of one Slurm array may write at the same moment.
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  const std::filesystem::path partial =
      target.string() + "." + std::string(host) + "." + std::to_string(getpid()) + ".partial";
  {
    std::ofstream out(partial);
    out << manifest.dump(2) << "\n";
    out.close();
    if (!out) throw std::runtime_error("cannot write " + partial.string());
  }
  std::filesystem::rename(partial, target);
}

}  // namespace mssph::sweep
