#include "dem/neighbour_search.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "core/capacity.hpp"

namespace suspend {

namespace {
bool within(const Box& box, const Vec3& ri, const Vec3& rj, double reach) {
  return box.minimum_image(ri, rj).d.squaredNorm() < reach * reach;
}
int mod(int a, int n) { return ((a % n) + n) % n; }
constexpr std::size_t parallel_particles = 1024;  // below this, threads cost more than they save
}  // namespace

void find_pairs_brute_force(const std::vector<Vec3>& position, const std::vector<double>& radius, const Box& box,
                            double gap_cutoff, std::vector<NeighbourPair>& pairs) {
  pairs.clear();
  const auto n = static_cast<std::uint32_t>(position.size());
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j)
      if (within(box, position[i], position[j], radius[i] + radius[j] + gap_cutoff)) pairs.push_back({i, j});
}

void CellListSearch::find_pairs(const std::vector<Vec3>& position, const std::vector<double>& radius,
                                const Box& box, double gap_cutoff, std::vector<NeighbourPair>& pairs) {
  const std::size_t np = position.size();
  const double a_max = np ? *std::max_element(radius.begin(), radius.end()) : 1.0;
  const double reach_max = 2.0 * a_max + gap_cutoff;
  const Vec3& L = box.length();
  for (int a = 0; a < 3; ++a) n_[a] = static_cast<int>(std::floor(L[a] / reach_max));
  if (n_[0] < 3 || n_[1] < 3 || n_[2] < 3) {
    n_ = {0, 0, 0};
    find_pairs_brute_force(position, radius, box, gap_cutoff, pairs);
    return;
  }
  const Vec3 w(L.x() / n_[0], L.y() / n_[1], L.z() / n_[2]);
  const std::array<int, 3> nc = n_;
  const int ncell = nc[0] * nc[1] * nc[2];
  auto index = [nc](int ix, int iy, int iz) { return (ix * nc[1] + iy) * nc[2] + iz; };

  // Counting sort of particles by cell.
  cell_of_.resize(np);
  const std::ptrdiff_t nps = static_cast<std::ptrdiff_t>(np);
#pragma omp parallel for schedule(static) if (np > parallel_particles)
  for (std::ptrdiff_t p = 0; p < nps; ++p) {
    std::array<int, 3> c;
    for (int a = 0; a < 3; ++a) c[a] = std::min(nc[a] - 1, std::max(0, static_cast<int>(position[p][a] / w[a])));
    cell_of_[p] = static_cast<std::uint32_t>(index(c[0], c[1], c[2]));
  }
  start_.assign(ncell + 1, 0);
  for (std::size_t p = 0; p < np; ++p) ++start_[cell_of_[p] + 1];
  for (int c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
  order_.resize(np);
  fill_.assign(start_.begin(), start_.end() - 1);
  for (std::size_t p = 0; p < np; ++p) order_[fill_[cell_of_[p]]++] = static_cast<std::uint32_t>(p);

  // Cells in parallel; every pair goes to the list of the thread that met it (p < q: the full stencil meets each
  // pair from both sides and keeps one).
  const bool full = stencil_ == Stencil::full;
  const double shift = box.shear_offset() / w.x();  // Lees-Edwards offset in cell widths
  const int nthreads = omp_get_max_threads();
  found_.resize(nthreads);
#pragma omp parallel num_threads(nthreads)
  {
    std::vector<NeighbourPair>& mine = found_[omp_get_thread_num()];
    mine.clear();
    auto scan = [&](std::uint32_t home, std::uint32_t other) {
      for (std::uint32_t s = start_[home]; s < start_[home + 1]; ++s) {
        const std::uint32_t p = order_[s];
        const Vec3 rp = position[p];
        const double ap = radius[p];
        const std::uint32_t t0 = (home == other && !full) ? s + 1 : start_[other];
        for (std::uint32_t t = t0; t < start_[other + 1]; ++t) {
          const std::uint32_t q = order_[t];
          if (full && q <= p) continue;
          if (within(box, rp, position[q], ap + radius[q] + gap_cutoff)) {
            reserve_one_more(mine);
            mine.push_back({std::min(p, q), std::max(p, q)});
          }
        }
      }
    };
    std::array<int, 40> targets;
#pragma omp for schedule(dynamic, 16)
    for (int home = 0; home < ncell; ++home) {
      const int iz = home % nc[2], iy = (home / nc[2]) % nc[1], ix = home / (nc[1] * nc[2]);
      int count = 0;
      targets[count++] = home;
      // A row of cells at y offset dy: nine cells, or across a y face the sheared image (up to four x cells).
      auto add_row = [&](int dy) {
        int jy = iy + dy;
        int x_lo = ix - 1, x_hi = ix + 1;
        if (jy == nc[1]) {  // the bottom row seen through the top face, displaced by +offset
          jy = 0;
          x_lo = static_cast<int>(std::floor(ix - 1 - shift));
          x_hi = static_cast<int>(std::floor(ix + 2 - shift));
        } else if (jy < 0) {  // the top row seen through the bottom face, displaced by -offset
          jy = nc[1] - 1;
          x_lo = static_cast<int>(std::floor(ix - 1 + shift));
          x_hi = static_cast<int>(std::floor(ix + 2 + shift));
        }
        for (int jx = x_lo; jx <= x_hi; ++jx)
          for (int dz = -1; dz <= 1; ++dz) targets[count++] = index(mod(jx, nc[0]), jy, mod(iz + dz, nc[2]));
      };
      if (full) {
        add_row(-1);
        for (int dx = -1; dx <= 1; ++dx)
          for (int dz = -1; dz <= 1; ++dz)
            if (dx != 0 || dz != 0) targets[count++] = index(mod(ix + dx, nc[0]), iy, mod(iz + dz, nc[2]));
      } else {
        // dy = 0 half plane: (dx, dz) = (+1, 0) and (any, +1).
        targets[count++] = index(mod(ix + 1, nc[0]), iy, iz);
        for (int dx = -1; dx <= 1; ++dx) targets[count++] = index(mod(ix + dx, nc[0]), iy, mod(iz + 1, nc[2]));
      }
      add_row(+1);
      // With three cells per axis the windows can wrap onto themselves: visit each cell once.
      std::sort(targets.begin() + 1, targets.begin() + count);
      const int unique = static_cast<int>(std::unique(targets.begin() + 1, targets.begin() + count) - targets.begin());
      const auto h = static_cast<std::uint32_t>(home);
      scan(h, h);
      for (int k = 1; k < unique; ++k)
        if (targets[k] != home) scan(h, static_cast<std::uint32_t>(targets[k]));
    }
  }

  // Order by (i, j): counting sort on i, then each row (a few dozen partners at most) by j.
  row_.assign(np + 1, 0);
  std::size_t total = 0;
  for (const auto& list : found_) {
    total += list.size();
    for (const NeighbourPair& pr : list) ++row_[pr.i + 1];
  }
  for (std::size_t i = 0; i < np; ++i) row_[i + 1] += row_[i];
  resize_with_headroom(pairs, total);
  fill_.assign(row_.begin(), row_.end() - 1);
  for (const auto& list : found_)
    for (const NeighbourPair& pr : list) pairs[fill_[pr.i]++] = pr;
#pragma omp parallel for schedule(static) if (np > parallel_particles)
  for (std::ptrdiff_t i = 0; i < nps; ++i)
    std::sort(pairs.begin() + row_[i], pairs.begin() + row_[i + 1],
              [](const NeighbourPair& a, const NeighbourPair& b) { return a.j < b.j; });
}

}  // namespace suspend
