#pragma once
// Host threads for the OpenMP loops of the reference and cpu backends (--threads N).
#include <string>

namespace mssph {

// The CPUs this process may run on (its affinity mask, which taskset, cpusets and batch systems
// set), at least 1.
int usable_cpus();

// What a run uses without --threads: $OMP_NUM_THREADS when set (the user's or the batch
// system's choice), else usable_cpus(). One run per machine then uses every CPU it may; several
// concurrent runs should each be given their share with --threads (they slow each other down
// far more than in proportion when the OpenMP threads of all of them exceed the CPUs).
int default_thread_count();
// Where default_thread_count() came from, for the start-up line: "OMP_NUM_THREADS" or
// "usable CPUs".
std::string default_thread_source();

// Sets the OpenMP thread count of later parallel loops.
void set_thread_count(int threads);

}  // namespace mssph
