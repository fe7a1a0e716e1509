#include "dem/pair_forces.hpp"

#include <array>

#include "core/capacity.hpp"

namespace suspend {

void compact_active_pairs(const std::vector<NeighbourPair>& list, const Particles& p, const Box& box,
                          double interaction_gap, std::vector<ActivePair>& active) {
  // Two passes over the same contiguous share of the list per thread: count, then fill at the offset of the
  // threads before; the result is the list order whatever the thread count, and sized exactly (no growth slack).
  const std::size_t np = list.size();
  constexpr int max_threads = 64;
  const int requested = np >= 4096 ? std::min(omp_get_max_threads(), max_threads) : 1;
  std::array<std::size_t, max_threads + 1> offset{};
  auto image = [&](const NeighbourPair& pr) { return box.minimum_image(p.position[pr.i], p.position[pr.j]); };
  auto within = [&](const NeighbourPair& pr, const MinimumImage& m) {
    const double reach = p.radius[pr.i] + p.radius[pr.j] + interaction_gap;
    return m.d.squaredNorm() < reach * reach;
  };
#pragma omp parallel num_threads(requested)
  {
    const int nthreads = omp_get_num_threads(), t = omp_get_thread_num();
    const std::size_t begin = np * t / nthreads, end = np * (t + 1) / nthreads;
    std::size_t count = 0;
    for (std::size_t k = begin; k < end; ++k) count += within(list[k], image(list[k])) ? 1 : 0;
    offset[t + 1] = count;
#pragma omp barrier
#pragma omp single
    {
      for (int u = 0; u < nthreads; ++u) offset[u + 1] += offset[u];
      resize_with_headroom(active, offset[nthreads]);
    }
    std::size_t out = offset[t];
    for (std::size_t k = begin; k < end; ++k) {
      const NeighbourPair& pr = list[k];
      const MinimumImage m = image(pr);
      if (!within(pr, m)) continue;
      active[out++] = {pr.i, pr.j, m.y_images, PairGeometry::from(m.d, p.radius[pr.i], p.radius[pr.j])};
    }
  }
}

}  // namespace suspend
