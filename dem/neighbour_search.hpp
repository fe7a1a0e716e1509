// Fixed-radius near-neighbour search (paper 000, section 2.1, Figs. 4-5).
// Counting-sort cell list with the symmetric half stencil: 13 of the 26 neighbour cells are scanned from each cell,
// so every unordered pair is visited once. Lees-Edwards aware: cells in the top row see the bottom row through the
// sheared image, which can straddle four x cells instead of three.
// A pair (i, j) is listed when its surface gap |r_ij| - (a_i + a_j) is below gap_cutoff (lengths in a_1).
// The full stencil (all 26 neighbours, every pair met twice; Hoetzlein's scheme before paper 000's symmetric
// search) is kept for the benchmark that measures what the half stencil saves; both give the same list.
//
// Parallel: particles are binned and cells scanned by all OpenMP threads, each collecting its own pairs; the
// result is then ordered by (i, j) with a counting sort on i, so the list is the same for any thread count.
// Scratch buffers are members: no allocation once the largest particle and pair counts have been seen.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "core/box.hpp"
#include "core/vec.hpp"

namespace suspend {

struct NeighbourPair {
  std::uint32_t i, j;
  friend bool operator==(const NeighbourPair&, const NeighbourPair&) = default;
};

enum class Stencil { half, full };

class CellListSearch {
 public:
  CellListSearch() = default;
  explicit CellListSearch(Stencil stencil) : stencil_(stencil) {}

  // Lists every pair with gap below gap_cutoff, each once with i < j, sorted by (i, j) so that downstream
  // accumulation order, and therefore the result bit pattern, does not depend on how cells were visited.
  void find_pairs(const std::vector<Vec3>& position, const std::vector<double>& radius, const Box& box,
                  double gap_cutoff, std::vector<NeighbourPair>& pairs);

  // Number of cells per axis used in the last search (0 when it fell back to all pairs for a tiny box).
  const std::array<int, 3>& cells() const { return n_; }

 private:
  Stencil stencil_ = Stencil::half;
  std::array<int, 3> n_{0, 0, 0};
  std::vector<std::uint32_t> cell_of_, start_, order_, fill_, row_;
  std::vector<std::vector<NeighbourPair>> found_;  // per thread
};

// O(N^2) reference used by tests and by boxes too small for three cells per axis.
void find_pairs_brute_force(const std::vector<Vec3>& position, const std::vector<double>& radius, const Box& box,
                            double gap_cutoff, std::vector<NeighbourPair>& pairs);

}  // namespace suspend
