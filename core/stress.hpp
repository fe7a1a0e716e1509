// Bulk stress split by origin (docs/units.md, Conventions): papers plot each contribution separately.
#pragma once
#include <array>
#include <cstddef>
#include <string_view>

#include "core/vec.hpp"

namespace suspend {

enum class Contribution : std::size_t {
  hydrodynamic,        // Stokes/FCM far-field and the imposed-flow term
  lubrication,         // pairwise lubrication or sub-grid corrections
  contact_normal,      // normal contact springs and dashpots, Hertz repulsion
  contact_tangential,  // tangential (frictional) and rolling springs
  repulsion,           // electrostatic and soft-core repulsion
  adhesion,            // constant adhesion and van der Waals attraction
  count
};
inline constexpr std::size_t contribution_count = static_cast<std::size_t>(Contribution::count);

inline constexpr std::array<std::string_view, contribution_count> contribution_names = {
    "hydrodynamic", "lubrication", "contact_normal", "contact_tangential", "repulsion", "adhesion"};

// Sigma in units of eta_0 gammadot_ref (the case's reference rate): one symmetric tensor per contribution.
struct StressTensors {
  std::array<Mat3, contribution_count> part;
  StressTensors() { clear(); }
  void clear() {
    for (auto& m : part) m.setZero();
  }
  Mat3& operator[](Contribution c) { return part[static_cast<std::size_t>(c)]; }
  const Mat3& operator[](Contribution c) const { return part[static_cast<std::size_t>(c)]; }
  Mat3 total() const {
    Mat3 t = Mat3::Zero();
    for (const auto& m : part) t += m;
    return t;
  }
};

// Rheological observables of a stress tensor (paper 000, text after eq. 9).
struct Rheology {
  double shear, n1, n2, pressure;
};
inline Rheology rheology_of(const Mat3& s) {
  return {s(0, 1), s(0, 0) - s(1, 1), s(1, 1) - s(2, 2), -s.trace() / 3.0};
}

}  // namespace suspend
