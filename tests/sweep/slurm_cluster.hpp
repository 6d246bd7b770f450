#pragma once
// A throwaway single-node Slurm cluster on localhost for one test: slurmctld and slurmd from
// Debian's slurm-wlm, run in the foreground as children of the test, with a slurm.conf, state,
// spool and logs in a temporary folder, auth/none (no munge key to manage) and no cgroups
// (proctrack/linuxproc, task/none), so it runs in a container as root. Stopped, with any job
// left cancelled, when the object goes away.
#include "child_process.hpp"
#include "temp_dir.hpp"

#include <memory>
#include <optional>
#include <string>

namespace mssph::test {

class SlurmCluster {
 public:
  SlurmCluster() = default;
  ~SlurmCluster();
  SlurmCluster(const SlurmCluster&) = delete;
  SlurmCluster& operator=(const SlurmCluster&) = delete;

  // Starts both daemons and waits for the node to be idle. Returns why not when Slurm cannot be
  // started on this machine (not root, slurm-wlm missing, a daemon that exits or never reports
  // the node), with the daemons' log tails; nullopt when the cluster is up.
  std::optional<std::string> start();

  // The environment the client commands need (SLURM_CONF); set by start() in this process.
  const std::string& conf_path() const { return conf_; }
  // Runs a client command (sbatch, squeue, ...) to its end.
  ProcessResult client(const std::vector<std::string>& argv) const;
  // True once squeue lists no job; false after `limit`.
  bool wait_until_idle(std::chrono::seconds limit) const;
  std::string logs() const;  // the daemons' log tails, for failure messages

  // Cancels every job, shuts the daemons down and reaps them (SIGKILL after 20 s).
  void stop();

 private:
  TempDir dir_;
  TempDir capture_ctld_;
  TempDir capture_d_;
  std::string conf_;
  std::unique_ptr<ChildProcess> controller_;
  std::unique_ptr<ChildProcess> node_daemon_;
};

}  // namespace mssph::test
