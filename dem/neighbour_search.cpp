#include "dem/neighbour_search.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace suspend {

namespace {
bool within(const Box& box, const Vec3& ri, const Vec3& rj, double reach) {
  return box.minimum_image(ri, rj).d.squaredNorm() < reach * reach;
}
int mod(int a, int n) { return ((a % n) + n) % n; }
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
  const int ncell = n_[0] * n_[1] * n_[2];
  auto index = [&](int ix, int iy, int iz) { return (ix * n_[1] + iy) * n_[2] + iz; };

  // Counting sort of particles by cell.
  cell_of_.resize(np);
  start_.assign(ncell + 1, 0);
  for (std::size_t p = 0; p < np; ++p) {
    std::array<int, 3> c;
    for (int a = 0; a < 3; ++a) c[a] = std::min(n_[a] - 1, std::max(0, static_cast<int>(position[p][a] / w[a])));
    cell_of_[p] = index(c[0], c[1], c[2]);
    ++start_[cell_of_[p] + 1];
  }
  for (int c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
  order_.resize(np);
  {
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t p = 0; p < np; ++p) order_[fill[cell_of_[p]]++] = static_cast<std::uint32_t>(p);
  }

  pairs.clear();
  auto scan = [&](int home, int other) {
    for (std::uint32_t s = start_[home]; s < start_[home + 1]; ++s) {
      const std::uint32_t p = order_[s];
      const std::uint32_t t0 = (home == other) ? s + 1 : start_[other];
      for (std::uint32_t t = t0; t < start_[other + 1]; ++t) {
        const std::uint32_t q = order_[t];
        if (within(box, position[p], position[q], radius[p] + radius[q] + gap_cutoff))
          pairs.push_back({std::min(p, q), std::max(p, q)});
      }
    }
  };

  std::vector<int> targets;
  targets.reserve(16);
  const double shift = box.shear_offset() / w.x();  // Lees-Edwards offset in cell widths
  for (int ix = 0; ix < n_[0]; ++ix)
    for (int iy = 0; iy < n_[1]; ++iy)
      for (int iz = 0; iz < n_[2]; ++iz) {
        const int home = index(ix, iy, iz);
        targets.clear();
        targets.push_back(home);
        // dy = 0 half plane: (dx, dz) = (+1, 0) and (any, +1).
        targets.push_back(index(mod(ix + 1, n_[0]), iy, iz));
        for (int dx = -1; dx <= 1; ++dx) targets.push_back(index(mod(ix + dx, n_[0]), iy, mod(iz + 1, n_[2])));
        // dy = +1 plane: nine cells, or across the top face the sheared image, which spans up to four x cells.
        const bool crosses = (iy == n_[1] - 1);
        const int jy = crosses ? 0 : iy + 1;
        const int x_lo = crosses ? static_cast<int>(std::floor(ix - 1 - shift)) : ix - 1;
        const int x_hi = crosses ? static_cast<int>(std::floor(ix + 2 - shift)) : ix + 1;
        for (int jx = x_lo; jx <= x_hi; ++jx)
          for (int dz = -1; dz <= 1; ++dz) targets.push_back(index(mod(jx, n_[0]), jy, mod(iz + dz, n_[2])));
        // With three cells per axis the sheared window can wrap onto itself: visit each cell once.
        std::sort(targets.begin() + 1, targets.end());
        targets.erase(std::unique(targets.begin() + 1, targets.end()), targets.end());
        scan(home, home);
        for (std::size_t k = 1; k < targets.size(); ++k)
          if (targets[k] != home) scan(home, targets[k]);
      }
  std::sort(pairs.begin(), pairs.end(),
            [](const NeighbourPair& a, const NeighbourPair& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
}

}  // namespace suspend
