#pragma once
// Host threads for the OpenMP loops of the start-up checks and the reference and cpu backends
// (--threads N).
#include <string>

namespace mssph {

// The CPUs this process may run on (its affinity mask, which taskset, cpusets and batch systems
// set), at least 1.
int usable_cpus();

// The CPUs this process may use that other work leaves free: usable_cpus() less the 1-minute load
// average (runnable threads, rounded), at least 1. /proc/loadavg unreadable: usable_cpus().
int free_cpus();

// What a run uses without --threads: $OMP_NUM_THREADS when set (the user's or the batch
// system's choice), else free_cpus(). OpenMP threads beyond the CPUs actually free wait for each
// other at the end of every loop, which costs far more than they gain (measured in
// results/decisions/049-openmp-on-a-busy-host.md); several concurrent runs should each be given
// their share with --threads.
int default_thread_count();
// Where default_thread_count() came from, for the start-up line: "OMP_NUM_THREADS" or "free CPUs:
// 2 usable, load average 1.3".
std::string default_thread_source();

// OpenMP reads OMP_WAIT_POLICY once, as its runtime loads, before main(). Unless the user set it,
// this sets it to "passive" (a thread that waits for the others sleeps instead of spinning, so a
// busy machine's other work does not stall the run) and executes this program again with the
// same arguments; it returns when the policy is already set, or when the exec fails (the run then
// goes on with the runtime's default).
void wait_passively_unless_told(char** argv);

// Sets the OpenMP thread count of later parallel loops.
void set_thread_count(int threads);

}  // namespace mssph
