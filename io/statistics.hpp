// Steady-state averages with honest error bars: the standard error of the mean of a correlated time series by
// block averaging (Flyvbjerg & Petersen, J. Chem. Phys. 91, 461 (1989)). Blocks are doubled until the blocked
// means are uncorrelated; the estimate is the largest standard error over levels that still have at least
// `min_blocks` blocks (a plateau, taken from above so error bars are never too small).
#pragma once
#include <cstddef>
#include <vector>

namespace suspend::io {

struct MeanWithError {
  double mean = 0.0;
  double sem = 0.0;       // standard error of the mean
  std::size_t samples = 0;
  std::size_t block_size = 1;  // block length at which the error was taken
  bool converged = true;       // false if no plateau was found (the error bar is then a lower bound)
};

MeanWithError block_average(const std::vector<double>& x, std::size_t min_blocks = 16);

}  // namespace suspend::io
