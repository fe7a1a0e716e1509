#include "dem/integrate/step_limit.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace suspend {

std::string StepLimitCounts::shares() const {
  const std::int64_t all = total();
  if (all == 0) return "";
  std::vector<std::size_t> order;
  for (std::size_t k = 0; k < counts_.size(); ++k)
    if (counts_[k] > 0) order.push_back(k);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return counts_[a] > counts_[b]; });
  std::string out;
  for (std::size_t k : order) {
    char share[64];
    std::snprintf(share, sizeof share, "%s%s %.3g%%", out.empty() ? "" : ", ", step_limit_name(static_cast<StepLimit>(k)),
                  100.0 * static_cast<double>(counts_[k]) / static_cast<double>(all));
    out += share;
  }
  return out;
}

}  // namespace suspend
