// The order of the resistance matrix's block rows (dem/integrate/resistance_solver.hpp): particles by the cell of a
// grid they lie in (z, then y, then x), those of one cell in index order. Neighbours then get nearby rows, and the
// blocks a Gauss-Seidel sweep reads for consecutive rows lie close in memory: with rows in the particles' own
// (random) order the sweeps of 2000 spheres read their 1.7 MB of blocks at random and outgrow the 2 MB L2 cache
// (docs/performance.md, "Cost against system size"). The order changes rounding only, never the solution beyond the
// solver's tolerance; it depends on positions alone, so results do not depend on the thread count.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/vec.hpp"

namespace suspend {

// row_of[i]: the row of particle i; cell: the grid spacing (a_1), enlarged so that there are at most about 2 cells
// per particle. count: scratch.
inline void cell_order(const std::vector<Vec3>& x, double cell, std::vector<std::uint32_t>& row_of,
                       std::vector<std::uint32_t>& count) {
  const std::size_t n = x.size();
  row_of.resize(n);
  if (n == 0) return;
  Vec3 lo = x[0], hi = x[0];
  for (const Vec3& v : x) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const Vec3 extent = (hi - lo).cwiseMax(Vec3::Constant(1e-12));
  cell = std::max(cell, std::cbrt(extent.prod() / (2.0 * static_cast<double>(n))));
  std::array<std::size_t, 3> dims{};
  for (int a = 0; a < 3; ++a) dims[a] = static_cast<std::size_t>(extent[a] / cell) + 1;
  auto key = [&](const Vec3& v) {
    std::array<std::size_t, 3> c{};
    for (int a = 0; a < 3; ++a) c[a] = std::min(dims[a] - 1, static_cast<std::size_t>((v[a] - lo[a]) / cell));
    return (c[2] * dims[1] + c[1]) * dims[0] + c[0];
  };
  count.assign(dims[0] * dims[1] * dims[2] + 1, 0);
  for (const Vec3& v : x) ++count[key(v) + 1];
  for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
  for (std::size_t i = 0; i < n; ++i) row_of[i] = count[key(x[i])]++;  // stable: index order within a cell
}

}  // namespace suspend
