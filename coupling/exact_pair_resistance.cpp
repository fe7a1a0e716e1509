#include "coupling/exact_pair_resistance.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "coupling/equal_sphere_table.hpp"
#include "coupling/pair_tensors.hpp"

namespace suspend::coupling {
namespace {

hydro::ResistanceScalars model(const hydro::LubricationCoefficients& c, double xi, double log_inv_xi) {
  hydro::ResistanceScalars s = hydro::lubrication_scalars(c, xi, log_inv_xi);
  hydro::add_stokes_drag(s);
  return s;
}
hydro::ResistanceScalars model(const hydro::LubricationCoefficients& c, double xi) {
  return model(c, xi, std::log(1.0 / xi));
}

}  // namespace

ExactPairResistance::ExactPairResistance(double a_i, double a_j, const hydro::LubricationParams& lubrication)
    : a_i_(a_i),
      a_j_(a_j),
      lubrication_(lubrication),
      from_i_(hydro::LubricationCoefficients::for_ratio(a_j / a_i)),
      from_j_(hydro::LubricationCoefficients::for_ratio(a_i / a_j)) {
  if (!(a_i > 0.0) || !(a_j > 0.0)) throw InputError("coupling: pair radii must be > 0");
  if (lubrication.regularization == 0.0 && lubrication.inner_cutoff <= 0.0)
    throw InputError("lubrication.inner_cutoff must be > 0 (or lubrication.regularization > 0) for the sub-grid "
                     "correction: overlapping pairs would have infinite resistance");
  if (std::abs(a_j / a_i - 1.0) > 1e-12) return;
  // Table columns: s', XA YA YB XC YC XG YG YH ("11"), the same ("12").
  constexpr std::array<double hydro::ResistanceScalars::*, 16> column{
      &hydro::ResistanceScalars::x11a, &hydro::ResistanceScalars::y11a, &hydro::ResistanceScalars::y11b,
      &hydro::ResistanceScalars::x11c, &hydro::ResistanceScalars::y11c, &hydro::ResistanceScalars::x11g,
      &hydro::ResistanceScalars::y11g, &hydro::ResistanceScalars::y11h, &hydro::ResistanceScalars::x12a,
      &hydro::ResistanceScalars::y12a, &hydro::ResistanceScalars::y12b, &hydro::ResistanceScalars::x12c,
      &hydro::ResistanceScalars::y12c, &hydro::ResistanceScalars::x12g, &hydro::ResistanceScalars::y12g,
      &hydro::ResistanceScalars::y12h};
  for (const auto& row : equal_sphere_resistance_table) {
    const double xi = row[0] - 2.0;
    const hydro::ResistanceScalars m = model(from_i_, xi);
    hydro::ResistanceScalars r{};
    r.xi = xi;
    for (std::size_t k = 0; k < column.size(); ++k) r.*column[k] = row[k + 1] - m.*column[k];
    remainder_xi_.push_back(xi);
    remainder_.push_back(r);
  }
}

double ExactPairResistance::scaled_gap(double gap) const {
  return 2.0 * std::fmax(gap, lubrication_.inner_cutoff) / (a_i_ + a_j_) + lubrication_.regularization;
}

void ExactPairResistance::scalars(double gap, hydro::ResistanceScalars& from_i,
                                  hydro::ResistanceScalars& from_j) const {
  const double xi = scaled_gap(gap);
  const double log_inv_xi = std::log(1.0 / xi);  // (what lubrication_scalars(c, xi) takes: the same bits)
  from_i = model(from_i_, xi, log_inv_xi);
  if (remainder_xi_.empty()) {
    from_j = model(from_j_, xi, log_inv_xi);
    return;
  }
  from_j = from_i;  // tabulated = equal spheres: the same coefficients from either side
  // Linear interpolation of the bounded remainder in xi, held constant outside the table.
  const auto it = std::upper_bound(remainder_xi_.begin(), remainder_xi_.end(), xi);
  std::size_t k1 = static_cast<std::size_t>(it - remainder_xi_.begin());
  std::size_t k0 = k1 == 0 ? 0 : k1 - 1;
  if (k1 >= remainder_xi_.size()) k1 = k0 = remainder_xi_.size() - 1;
  double w = 0.0;
  if (k1 != k0) w = (xi - remainder_xi_[k0]) / (remainder_xi_[k1] - remainder_xi_[k0]);
  for (auto f : correction_functions) {
    const double r = (1.0 - w) * remainder_[k0].*f + w * remainder_[k1].*f;
    from_i.*f += r;
    from_j.*f += r;  // equal spheres: the same functions from either side
  }
}

}  // namespace suspend::coupling
