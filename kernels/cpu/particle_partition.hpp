#pragma once
// The host's particle loops split by cost: one contiguous range of sorted particles per OpenMP
// thread, each range holding about the same share of an estimated cost. OpenMP's static schedule
// gives every thread as many particles, but a particle's sums cost in proportion to its list, and a
// boundary particle takes no force sum: in cell order the layers of a container above its fluid are
// walls only, and the thread given them would idle through part of the force pass. Ranges keep
// each thread's particles, and their neighbours, together in memory, which a dynamic schedule's
// interleaved chunks do not.
#include <omp.h>

#include <cstdint>
#include <vector>

namespace mssph::kernels {

class ParticlePartition {
 public:
  // Splits particles [0, n) into `parts` contiguous ranges (at least one): part k ends at the
  // first particle whose running cost reaches k + 1 parts' share of the total (cost(s) >= 0 for
  // particle s), so no part exceeds its share by more than one particle's cost.
  template <class Cost>
  void assign(std::uint32_t n, std::uint32_t parts, Cost&& cost) {
    parts = parts > 0 ? parts : 1u;  // no parts would leave every particle out
    begin_.assign(static_cast<std::size_t>(parts) + 1, n);
    begin_[0] = 0;
    std::uint64_t total = 0;
    for (std::uint32_t s = 0; s < n; ++s) total += cost(s);
    std::uint64_t running = 0;
    std::uint32_t next_part = 1;
    for (std::uint32_t s = 0; s < n && next_part < parts; ++s) {
      running += cost(s);
      // running * parts >= total * k: part k - 1's share reached (integers, so no rounding).
      while (next_part < parts && running * parts >= total * next_part) begin_[next_part++] = s + 1;
    }
  }

  std::uint32_t parts() const { return static_cast<std::uint32_t>(begin_.size()) - 1; }
  std::uint32_t begin(std::uint32_t part) const { return begin_[part]; }
  std::uint32_t end(std::uint32_t part) const { return begin_[part + 1]; }

  // Calls body(s) for every particle of every part, the parts shared among the threads of one
  // parallel region: with as many threads as parts (the usual case, see for_current_threads), one
  // part each; with fewer (a nested region, OMP_DYNAMIC), still every part, once.
  template <class Body>
  void for_each(Body&& body) const {
    const std::uint32_t count = parts();
#pragma omp parallel num_threads(static_cast <int>(count))
    {
      const auto threads = static_cast<std::uint32_t>(omp_get_num_threads());
      for (auto part = static_cast<std::uint32_t>(omp_get_thread_num()); part < count; part += threads) {
        for (std::uint32_t s = begin(part); s < end(part); ++s) body(s);
      }
    }
  }

  // One part per thread of the host's parallel regions, as the OpenMP settings give them now.
  static std::uint32_t for_current_threads() { return static_cast<std::uint32_t>(omp_get_max_threads()); }

 private:
  std::vector<std::uint32_t> begin_{0, 0};  // part k is [begin_[k], begin_[k + 1])
};

}  // namespace mssph::kernels
