// One seeded generator type for the whole program; its state is saved in checkpoints so restarts are exact.
#pragma once
#include <cstdint>
#include <random>
#include <sstream>
#include <string>

namespace suspend {
using Rng = std::mt19937_64;

inline std::string serialize(const Rng& rng) {
  std::ostringstream s;
  s << rng;
  return s.str();
}
inline Rng deserialize_rng(const std::string& text) {
  Rng rng;
  std::istringstream s(text);
  s >> rng;
  return rng;
}
}  // namespace suspend
