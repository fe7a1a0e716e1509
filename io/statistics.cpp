#include "io/statistics.hpp"

#include <cmath>
#include <numeric>

namespace suspend::io {

MeanWithError block_average(const std::vector<double>& x, std::size_t min_blocks) {
  MeanWithError r;
  r.samples = x.size();
  if (x.empty()) return r;
  r.mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
  if (x.size() < 2) return r;
  struct Level {
    double sem, noise;
    std::size_t block;
  };
  std::vector<Level> levels;
  std::vector<double> blocks = x;
  for (std::size_t block = 1; blocks.size() >= 2 && (levels.empty() || blocks.size() >= min_blocks); block *= 2) {
    const double nb = static_cast<double>(blocks.size());
    const double m = std::accumulate(blocks.begin(), blocks.end(), 0.0) / nb;
    double s2 = 0.0;
    for (double b : blocks) s2 += (b - m) * (b - m);
    const double sem = std::sqrt(s2 / (nb - 1.0) / nb);
    levels.push_back({sem, sem / std::sqrt(2.0 * (nb - 1.0)), block});
    std::vector<double> next(blocks.size() / 2);
    for (std::size_t k = 0; k < next.size(); ++k) next[k] = 0.5 * (blocks[2 * k] + blocks[2 * k + 1]);
    blocks.swap(next);
  }
  r.converged = false;
  std::size_t pick = levels.size() - 1;
  for (std::size_t k = 0; k + 1 < levels.size(); ++k)
    if (levels[k + 1].sem <= levels[k].sem + levels[k].noise) {
      pick = levels[k + 1].sem > levels[k].sem ? k + 1 : k;
      r.converged = true;
      break;
    }
  r.sem = levels[pick].sem;
  r.block_size = levels[pick].block;
  return r;
}

}  // namespace suspend::io
