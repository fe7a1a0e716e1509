#include "core/range.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/error.hpp"

namespace suspend {

std::string exact(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  for (int prec = 1; prec <= 17; ++prec) {
    char shorter[64];
    std::snprintf(shorter, sizeof shorter, "%.*g", prec, v);
    if (std::strtod(shorter, nullptr) == v) return shorter;
  }
  return buf;
}

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  const bool above = lo_open ? v > lo : v >= lo;
  const bool below = hi_open ? v < hi : v <= hi;
  return above && below;
}

std::string Range::describe() const {
  const bool lo_inf = std::isinf(lo), hi_inf = std::isinf(hi);
  if (lo_inf && hi_inf) return "a finite number";
  if (hi_inf) return std::string(lo_open ? "> " : ">= ") + exact(lo);
  if (lo_inf) return std::string(hi_open ? "< " : "<= ") + exact(hi);
  return std::string("in ") + (lo_open ? "(" : "[") + exact(lo) + ", " + exact(hi) + (hi_open ? ")" : "]");
}

void require(double v, const Range& range, std::string_view key) {
  if (!range.contains(v)) throw InputError(std::string(key) + " = " + exact(v) + " must be " + range.describe());
}

}  // namespace suspend
