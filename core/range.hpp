// An allowed interval for a number, open or closed at each end: what a parameter may be. The case reader
// (io/schema_reader.hpp) checks values against it and names it in its messages; the contact laws state their
// parameters' ranges with it when they read themselves (dem/contact/).
#pragma once
#include <limits>
#include <string>
#include <string_view>

namespace suspend {

struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range non_negative() { return {0.0, std::numeric_limits<double>::infinity(), false, false}; }
  static Range closed(double a, double b) { return {a, b, false, false}; }
  static Range open_closed(double a, double b) { return {a, b, true, false}; }
  static Range open(double a, double b) { return {a, b, true, true}; }
  bool contains(double v) const;
  std::string describe() const;  // "> 0", "in [0, 1]": for messages
};

// A double printed so that it reads back to the same bits, as briefly as possible (0.1, not 0.10000000000000001).
std::string exact(double v);

// Throws InputError "KEY = V must be RANGE" unless range contains v: the check of a parameter set in code.
void require(double v, const Range& range, std::string_view key);

}  // namespace suspend
