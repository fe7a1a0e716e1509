#include "dem/hydro/equal_sphere_remainder.hpp"

#include <algorithm>
#include <cmath>

#include "dem/hydro/equal_sphere_table.hpp"

namespace suspend::hydro {

const EqualSphereRemainder& EqualSphereRemainder::instance() {
  static const EqualSphereRemainder table;
  return table;
}

EqualSphereRemainder::EqualSphereRemainder() {
  // Table columns: s', XA YA YB XC YC XG YG YH ("11"), the same ("12").
  constexpr std::array<double ResistanceScalars::*, 16> column{
      &ResistanceScalars::x11a, &ResistanceScalars::y11a, &ResistanceScalars::y11b, &ResistanceScalars::x11c,
      &ResistanceScalars::y11c, &ResistanceScalars::x11g, &ResistanceScalars::y11g, &ResistanceScalars::y11h,
      &ResistanceScalars::x12a, &ResistanceScalars::y12a, &ResistanceScalars::y12b, &ResistanceScalars::x12c,
      &ResistanceScalars::y12c, &ResistanceScalars::x12g, &ResistanceScalars::y12g, &ResistanceScalars::y12h};
  const LubricationCoefficients equal = LubricationCoefficients::for_ratio(1.0);
  for (const auto& row : equal_sphere_resistance_table) {
    const double xi = row[0] - 2.0;
    ResistanceScalars model = lubrication_scalars(equal, xi, std::log(1.0 / xi));
    add_stokes_drag(model);
    ResistanceScalars r{};
    r.xi = xi;
    for (std::size_t k = 0; k < column.size(); ++k) r.*column[k] = row[k + 1] - model.*column[k];
    xi_.push_back(xi);
    remainder_.push_back(r);
  }
}

ResistanceScalars EqualSphereRemainder::at(double xi) const {
  const auto it = std::upper_bound(xi_.begin(), xi_.end(), xi);
  std::size_t k1 = static_cast<std::size_t>(it - xi_.begin());
  std::size_t k0 = k1 == 0 ? 0 : k1 - 1;
  if (k1 >= xi_.size()) k1 = k0 = xi_.size() - 1;
  double w = 0.0;
  if (k1 != k0) w = (xi - xi_[k0]) / (xi_[k1] - xi_[k0]);
  ResistanceScalars r{};
  for (auto f : tabulated_functions) r.*f = (1.0 - w) * remainder_[k0].*f + w * remainder_[k1].*f;
  return r;
}

void EqualSphereRemainder::add_to(double xi, ResistanceScalars& s) const {
  const ResistanceScalars r = at(xi);
  for (auto f : tabulated_functions) s.*f += r.*f;
}

}  // namespace suspend::hydro
