#include "instruction_counts.hpp"

#include "util/child_process.hpp"

#include <valgrind/callgrind.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace mssph::bench {
namespace {

std::vector<std::pair<std::string, CountedWorkload>>& workloads() {
  static std::vector<std::pair<std::string, CountedWorkload>> all;
  return all;
}

// The simulated caches, fixed so that the miss counts do not depend on the machine that counts.
const std::vector<std::string> kCacheModel{"--I1=32768,8,64", "--D1=32768,8,64", "--LL=8388608,16,64"};

// What Callgrind's dump file for one region says: its label (name|units) and event totals.
struct Dump {
  std::string label;
  std::map<std::string, double> events;
};

Dump read_dump(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read Callgrind's dump " + path.string());
  Dump dump;
  std::vector<std::string> names;
  const std::string trigger = "desc: Trigger: Client Request: ";
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(trigger, 0) == 0) dump.label = line.substr(trigger.size());
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "events:") {
      for (std::string name; words >> name;) names.push_back(name);
    } else if (key == "summary:") {
      for (const std::string& name : names) words >> dump.events[name];
    }
  }
  if (dump.label.empty() || !dump.events.count("Ir")) {
    throw std::runtime_error("Callgrind's dump " + path.string() + " has no client-request label or no Ir summary");
  }
  return dump;
}

InstructionCount count_of(const Dump& dump) {
  const std::size_t bar = dump.label.rfind('|');
  const double units = bar == std::string::npos ? 0.0 : std::stod(dump.label.substr(bar + 1));
  if (!(units > 0.0)) throw std::runtime_error("Callgrind dump label \"" + dump.label + "\" has no unit count");
  const auto event = [&](const char* name) {
    const auto it = dump.events.find(name);
    return it == dump.events.end() ? 0.0 : it->second;
  };
  return {dump.label.substr(0, bar), event("Ir") / units, (event("ILmr") + event("DLmr") + event("DLmw")) / units};
}

}  // namespace

void CountedRegion::measure(std::size_t units, const std::function<void()>& unit) const {
  const std::string label = name_ + "|" + std::to_string(units);
  CALLGRIND_START_INSTRUMENTATION;
  CALLGRIND_ZERO_STATS;
  for (std::size_t k = 0; k < units; ++k) unit();
  CALLGRIND_DUMP_STATS_AT(label.c_str());
  CALLGRIND_STOP_INSTRUMENTATION;
}

void add_counted_workload(const std::string& name, CountedWorkload workload) {
  workloads().emplace_back(name, std::move(workload));
}

std::size_t run_counted_workloads(const std::string& filter) {
  const std::regex pattern(filter);
  std::size_t ran = 0;
  for (const auto& [name, workload] : workloads()) {
    if (!std::regex_search(name, pattern)) continue;
    workload(CountedRegion(name));
    ++ran;
  }
  return ran;
}

std::vector<InstructionCount> count_instructions(const std::vector<std::string>& program_arguments,
                                                 const std::string& work_dir) {
  const std::filesystem::path out = std::filesystem::path(work_dir) / "callgrind.out";
  std::vector<std::string> argv{"valgrind",         "-q",
                                "--tool=callgrind", "--instr-atstart=no",
                                "--cache-sim=yes",  "--callgrind-out-file=" + out.string()};
  argv.insert(argv.end(), kCacheModel.begin(), kCacheModel.end());
  argv.insert(argv.end(), program_arguments.begin(), program_arguments.end());
  const int code = run_program(argv);
  if (code == 127) throw std::runtime_error("cannot start valgrind (install Debian's valgrind package)");
  if (code != 0) throw std::runtime_error("the counting run under valgrind exited " + std::to_string(code));
  std::vector<InstructionCount> counts;
  for (int part = 1; std::filesystem::exists(out.string() + "." + std::to_string(part)); ++part) {
    counts.push_back(count_of(read_dump(out.string() + "." + std::to_string(part))));
  }
  return counts;
}

void add_counts_to_benchmark_file(const std::string& path, const std::vector<InstructionCount>& counts) {
  nlohmann::json file;
  {
    std::ifstream in(path);
    file = nlohmann::json::parse(in);
  }
  std::map<std::string, const InstructionCount*> by_name;
  for (const InstructionCount& c : counts) by_name[c.name] = &c;
  const std::string suffix = "/manual_time";
  for (nlohmann::json& entry : file["benchmarks"]) {
    std::string name = entry.value("run_name", entry.value("name", ""));
    if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
      name.resize(name.size() - suffix.size());
    }
    const auto it = by_name.find(name);
    if (it == by_name.end()) continue;
    entry["instructions_per_step"] = it->second->instructions_per_unit;
    entry["ll_misses_per_step"] = it->second->ll_misses_per_unit;
  }
  std::string model;
  for (const std::string& c : kCacheModel) model += (model.empty() ? "" : " ") + c;
  file["context"]["mssph_instruction_counter"] = "valgrind --tool=callgrind --cache-sim=yes " + model;
  std::ofstream out(path, std::ios::trunc);
  out << file.dump(2) << "\n";
  if (!out.flush()) throw std::runtime_error("writing the instruction counts into " + path + " failed");
}

}  // namespace mssph::bench
