// The O(1) remainder of the pairwise model for equal spheres: exact - (Stokes drag + singular terms), for the
// sixteen functions of the exact table (A, B, C, G, H; equal_sphere_table.hpp, Jeffrey & Onishi 1984 / Townsend).
// Bounded at contact (X11A -0.0046, Y11B +0.239, ...; docs/lubrication.md section 3), so it is interpolated
// linearly in xi between the table's gaps (xi = 1e-5 ... 2.5) and held at the end values outside them.
// Used by the exact sub-grid target of the FCM coupling and by the pairwise option
// `hydrodynamics.lubrication.functions: exact_relative` (lubrication.hpp).
#pragma once
#include <array>
#include <vector>

#include "dem/hydro/resistance_functions.hpp"

namespace suspend::hydro {

// The sixteen scalars of the exact table, in ResistanceScalars.
inline constexpr std::array<double ResistanceScalars::*, 16> tabulated_functions{
    &ResistanceScalars::x11a, &ResistanceScalars::x12a, &ResistanceScalars::y11a, &ResistanceScalars::y12a,
    &ResistanceScalars::y11b, &ResistanceScalars::y12b, &ResistanceScalars::x11c, &ResistanceScalars::x12c,
    &ResistanceScalars::y11c, &ResistanceScalars::y12c, &ResistanceScalars::x11g, &ResistanceScalars::x12g,
    &ResistanceScalars::y11g, &ResistanceScalars::y12g, &ResistanceScalars::y11h, &ResistanceScalars::y12h};

class EqualSphereRemainder {
 public:
  // Built once from the table (38 gaps).
  static const EqualSphereRemainder& instance();

  // Adds the remainder at scaled gap xi to every tabulated function of s.
  void add_to(double xi, ResistanceScalars& s) const;
  // The interpolated remainder at xi (M functions and xi left zero).
  ResistanceScalars at(double xi) const;

 private:
  EqualSphereRemainder();
  std::vector<double> xi_;
  std::vector<ResistanceScalars> remainder_;
};

}  // namespace suspend::hydro
