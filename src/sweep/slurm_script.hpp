#pragma once
// `mssph sweep ... --emit-slurm`: batch scripts that run a sweep on a Slurm cluster. One array
// task per shard, each an ordinary `mssph sweep ... --shard K/N` (so a task resumes: it skips the
// points already completed), and a merge job that runs after the whole array, whatever its tasks'
// exit codes, and builds the summary from what finished.
#include <cstddef>
#include <string>
#include <vector>

namespace mssph::sweep {

struct SlurmOptions {
  std::string program;     // absolute path of the mssph binary the tasks run
  std::string sweep_file;  // absolute
  std::string directory;   // absolute output folder
  std::string sweep_name;
  std::string backend;
  std::vector<std::string> overrides;  // the command line's --set
  bool retry_failed = false;
  std::size_t tasks = 1;         // array size = shard count
  std::size_t max_parallel = 0;  // array throttle (%M); 0 for none
  std::string partition;         // "" for the cluster's default
  int gpus_per_task = 0;
  int cpus_per_task = 0;
  std::string time_limit;                   // sbatch --time, "" for the partition's default
  std::vector<std::string> sbatch_options;  // extra "#SBATCH <option>" lines for both jobs
};

struct SlurmScripts {
  std::string array_script;   // DIR/slurm/sweep_array.sbatch
  std::string merge_script;   // DIR/slurm/sweep_merge.sbatch
  std::string submit_script;  // DIR/slurm/submit.sh: submits both, the merge depending on the array
};

// The texts, without writing them.
std::string array_script_text(const SlurmOptions& options);
std::string merge_script_text(const SlurmOptions& options);
std::string submit_script_text(const SlurmOptions& options, const SlurmScripts& paths);

// Writes the three scripts (executable) and creates DIR/slurm/logs for the jobs' output.
SlurmScripts write_slurm_scripts(const SlurmOptions& options);

// A word for a POSIX shell: single-quoted, embedded quotes escaped.
std::string shell_quote(const std::string& word);

}  // namespace mssph::sweep
