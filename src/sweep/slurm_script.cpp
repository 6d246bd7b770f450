#include "sweep/slurm_script.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace mssph::sweep {
namespace {

std::string logs_folder(const SlurmOptions& o) { return o.directory + "/slurm/logs"; }

// The #SBATCH lines both jobs share: where they run and what the user added.
std::string common_directives(const SlurmOptions& o) {
  std::string text = "#SBATCH --ntasks=1\n";
  if (!o.partition.empty()) text += "#SBATCH --partition=" + o.partition + "\n";
  for (const std::string& option : o.sbatch_options) text += "#SBATCH " + option + "\n";
  return text;
}

void write_executable(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path);
  namespace fs = std::filesystem;
  fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec, fs::perm_options::add);
}

}  // namespace

std::string shell_quote(const std::string& word) {
  std::string out = "'";
  for (char c : word) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

std::string array_script_text(const SlurmOptions& o) {
  const std::string tasks = std::to_string(o.tasks);
  std::string text =
      "#!/bin/bash\n"
      "# mssph sweep " +
      o.sweep_name + ": " + tasks + " array tasks, task K running shard K/" + tasks +
      " of the\n"
      "# points. Written by `mssph sweep --emit-slurm`; submit it with submit.sh next to it, which adds the\n"
      "# merge job. A task skips points that already completed, so resubmitting the array, or part of it\n"
      "# (sbatch --array=3,7 " +
      "sweep_array.sbatch), reruns only what is missing.\n"
      "#SBATCH --job-name=mssph-" +
      o.sweep_name +
      "\n"
      "#SBATCH --array=0-" +
      std::to_string(o.tasks - 1) +
      (o.max_parallel ? std::string("%") + std::to_string(o.max_parallel) : std::string()) +
      "\n"
      "#SBATCH --output=" +
      logs_folder(o) + "/shard-%a.out\n" + common_directives(o);
  if (o.gpus_per_task > 0) text += "#SBATCH --gpus-per-task=" + std::to_string(o.gpus_per_task) + "\n";
  if (o.cpus_per_task > 0) text += "#SBATCH --cpus-per-task=" + std::to_string(o.cpus_per_task) + "\n";
  if (!o.time_limit.empty()) text += "#SBATCH --time=" + o.time_limit + "\n";
  text += "set -euo pipefail\n";
  text += "exec " + shell_quote(o.program) + " sweep " + shell_quote(o.sweep_file) + " --out " +
          shell_quote(o.directory) + " --backend " + shell_quote(o.backend) + " --shard \"${SLURM_ARRAY_TASK_ID}/" +
          tasks + "\"";
  for (const std::string& s : o.overrides) text += " --set " + shell_quote(s);
  if (o.retry_failed) text += " --retry-failed";
  return text + "\n";
}

std::string merge_script_text(const SlurmOptions& o) {
  return "#!/bin/bash\n"
         "# mssph sweep " +
         o.sweep_name +
         ": summary of whatever the array finished (submit.sh runs it after\n"
         "# the array). Missing points are listed; rerunning the array and this job fills them in.\n"
         "#SBATCH --job-name=mssph-" +
         o.sweep_name +
         "-merge\n"
         "#SBATCH --output=" +
         logs_folder(o) + "/merge.out\n" + common_directives(o) +
         "set -euo pipefail\n"
         "exec " +
         shell_quote(o.program) + " sweep merge " + shell_quote(o.directory) + "\n";
}

std::string submit_script_text(const SlurmOptions& o, const SlurmScripts& paths) {
  return "#!/bin/bash\n"
         "# Submits the sweep's array job, then its merge job, which waits for every array task to end\n"
         "# (afterany: a failed point must not cancel the summary of the others).\n"
         "set -euo pipefail\n"
         "array_job=$(sbatch --parsable " +
         shell_quote(paths.array_script) +
         ")\n"
         "array_job=${array_job%%;*}  # --parsable prints JOBID[;CLUSTER]\n"
         "merge_job=$(sbatch --parsable --dependency=afterany:${array_job} " +
         shell_quote(paths.merge_script) +
         ")\n"
         "merge_job=${merge_job%%;*}\n"
         "echo \"mssph sweep " +
         o.sweep_name + ": array job ${array_job} (" + std::to_string(o.tasks) + " tasks), merge job ${merge_job}\"\n";
}

SlurmScripts write_slurm_scripts(const SlurmOptions& o) {
  std::filesystem::create_directories(logs_folder(o));
  SlurmScripts paths;
  paths.array_script = o.directory + "/slurm/sweep_array.sbatch";
  paths.merge_script = o.directory + "/slurm/sweep_merge.sbatch";
  paths.submit_script = o.directory + "/slurm/submit.sh";
  write_executable(paths.array_script, array_script_text(o));
  write_executable(paths.merge_script, merge_script_text(o));
  write_executable(paths.submit_script, submit_script_text(o, paths));
  return paths;
}

}  // namespace mssph::sweep
