#include "slurm_cluster.hpp"

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

namespace mssph::test {
namespace {

using namespace std::chrono_literals;

// A program by name on PATH or in the sbin folders, where Debian puts the daemons; "" if absent.
std::string find_program(const std::string& name) {
  std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  path += ":/usr/sbin:/sbin:/usr/bin";
  std::istringstream folders(path);
  for (std::string folder; std::getline(folders, folder, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(folder) / name;
    if (!folder.empty() && access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return "";
}

// A TCP port nothing listens on now: the kernel's pick for port 0.
int free_port() {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t length = sizeof address;
  int port = 0;
  if (bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
      getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) == 0) {
    port = ntohs(address.sin_port);
  }
  close(fd);
  return port;
}

std::string short_hostname() {
  char name[256] = {};
  gethostname(name, sizeof name - 1);
  const std::string host = name;
  return host.substr(0, host.find('.'));
}

std::string tail(const std::string& text, std::size_t lines) {
  std::size_t at = text.size();
  for (std::size_t n = 0; n <= lines && at != std::string::npos && at > 0; ++n) at = text.rfind('\n', at - 1);
  return at == std::string::npos ? text : text.substr(at + 1);
}

}  // namespace

SlurmCluster::~SlurmCluster() { stop(); }

std::optional<std::string> SlurmCluster::start() {
  if (geteuid() != 0)
    return "slurmd must run as root to start jobs, and this test runs as uid " + std::to_string(geteuid());
  const std::string slurmctld = find_program("slurmctld");
  const std::string slurmd = find_program("slurmd");
  for (const char* client : {"sbatch", "squeue", "scontrol", "scancel", "sinfo"}) {
    if (find_program(client).empty())
      return std::string(client) + " not found: install slurm-wlm (scripts/setup.sh does)";
  }
  if (slurmctld.empty() || slurmd.empty())
    return "slurmctld or slurmd not found: install slurm-wlm (scripts/setup.sh does)";

  const std::string host = short_hostname();
  const std::string d = dir_.path().string();
  std::filesystem::create_directories(d + "/state");
  std::filesystem::create_directories(d + "/spool");
  conf_ = d + "/slurm.conf";
  const unsigned cpus = std::max(1u, std::thread::hardware_concurrency());
  std::ofstream(conf_) << "ClusterName=mssphtest\n"
                       << "SlurmctldHost=" << host << "(127.0.0.1)\n"
                       << "AuthType=auth/none\nCredType=cred/none\n"
                       << "SlurmUser=root\nSlurmdUser=root\n"
                       << "SlurmctldPort=" << free_port() << "\nSlurmdPort=" << free_port() << "\n"
                       << "StateSaveLocation=" << d << "/state\nSlurmdSpoolDir=" << d << "/spool\n"
                       << "SlurmctldPidFile=" << d << "/slurmctld.pid\nSlurmdPidFile=" << d << "/slurmd.pid\n"
                       << "SlurmctldLogFile=" << d << "/slurmctld.log\nSlurmdLogFile=" << d << "/slurmd.log\n"
                       << "ProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\n"
                       << "JobAcctGatherType=jobacct_gather/none\nAccountingStorageType=accounting_storage/none\n"
                       << "JobCompType=jobcomp/none\nSchedulerType=sched/builtin\n"
                       << "SelectType=select/cons_tres\nSelectTypeParameters=CR_Core\n"
                       << "ReturnToService=2\nMpiDefault=none\nMailProg=/bin/true\n"
                       << "NodeName=" << host << " NodeAddr=127.0.0.1 CPUs=" << cpus << " State=UNKNOWN\n"
                       << "PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP\n";
  setenv("SLURM_CONF", conf_.c_str(), 1);

  // -D: stay in the foreground, a child of this test; -i: ignore any saved state.
  controller_ = std::make_unique<ChildProcess>(std::vector<std::string>{slurmctld, "-D", "-i", "-f", conf_},
                                               dir_.path(), capture_ctld_.path());
  node_daemon_ = std::make_unique<ChildProcess>(std::vector<std::string>{slurmd, "-D", "-f", conf_}, dir_.path(),
                                                capture_d_.path());
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (std::chrono::steady_clock::now() < deadline) {
    if (!controller_->running() || !node_daemon_->running()) {
      return "a Slurm daemon exited at start-up:\n" + logs();
    }
    const ProcessResult state = client({"sinfo", "-h", "-o", "%T"});
    if (state.exit_code == 0 && state.out.find("idle") != std::string::npos) return std::nullopt;
    std::this_thread::sleep_for(250ms);
  }
  return "the node did not become idle within 60 s:\n" + logs();
}

ProcessResult SlurmCluster::client(const std::vector<std::string>& argv) const {
  std::vector<std::string> full = argv;
  full[0] = find_program(argv[0]);
  return run_process(full, dir_.path());
}

bool SlurmCluster::wait_until_idle(std::chrono::seconds limit) const {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < deadline) {
    const ProcessResult queue = client({"squeue", "-h"});
    if (queue.exit_code == 0 && queue.out.empty()) return true;
    std::this_thread::sleep_for(500ms);
  }
  return false;
}

std::string SlurmCluster::logs() const {
  const std::string d = dir_.path().string();
  return "slurmctld.log:\n" + tail(read_file(d + "/slurmctld.log"), 15) + "slurmd.log:\n" +
         tail(read_file(d + "/slurmd.log"), 15) + "slurmctld stderr:\n" + tail(read_file(capture_ctld_ / "stderr"), 5) +
         "slurmd stderr:\n" + tail(read_file(capture_d_ / "stderr"), 5);
}

void SlurmCluster::stop() {
  if (!controller_ && !node_daemon_) return;
  if (controller_ && controller_->running()) {
    // Jobs first, so no slurmstepd outlives the daemons; then both daemons at once.
    client({"scancel", "--full", "--user=root"});
    wait_until_idle(30s);
    client({"scontrol", "shutdown"});
  }
  for (auto* daemon : {&node_daemon_, &controller_}) {
    if (*daemon) (*daemon)->wait(20s);  // SIGKILL past the limit
    daemon->reset();
  }
  unsetenv("SLURM_CONF");
}

}  // namespace mssph::test
