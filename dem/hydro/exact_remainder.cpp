#include "dem/hydro/exact_remainder.hpp"

#include <algorithm>
#include <cmath>

#include "dem/hydro/equal_sphere_table.hpp"
#include "dem/hydro/unequal_sphere_table.hpp"

namespace suspend::hydro {

ExactRemainder::ExactRemainder(double lambda, std::span<const Row> rows)
    : lambda_(lambda), coefficients_(LubricationCoefficients::for_ratio(lambda)) {
  constexpr std::array<double ResistanceScalars::*, 22> column{
      &ResistanceScalars::x11a, &ResistanceScalars::y11a, &ResistanceScalars::y11b, &ResistanceScalars::x11c,
      &ResistanceScalars::y11c, &ResistanceScalars::x11g, &ResistanceScalars::y11g, &ResistanceScalars::y11h,
      &ResistanceScalars::x12a, &ResistanceScalars::y12a, &ResistanceScalars::y12b, &ResistanceScalars::x12c,
      &ResistanceScalars::y12c, &ResistanceScalars::x12g, &ResistanceScalars::y12g, &ResistanceScalars::y12h,
      &ResistanceScalars::x11m, &ResistanceScalars::y11m, &ResistanceScalars::z11m, &ResistanceScalars::x12m,
      &ResistanceScalars::y12m, &ResistanceScalars::z12m};
  for (const Row& row : rows) {
    const double xi = row[0] - 2.0;
    ResistanceScalars model = lubrication_scalars(coefficients_, xi, std::log(1.0 / xi));
    add_stokes_drag(model);
    ResistanceScalars r{};
    r.xi = xi;
    for (std::size_t k = 0; k < column.size(); ++k) r.*column[k] = row[k + 1] - model.*column[k];
    xi_.push_back(xi);
    remainder_.push_back(r);
  }
}

const ExactRemainder* ExactRemainder::for_ratio(double lambda) {
  static const ExactRemainder equal(1.0, equal_sphere_resistance_table);
  static const ExactRemainder large(1.4, resistance_table_lambda_1_4);
  static const ExactRemainder small(1.0 / 1.4, resistance_table_lambda_1_over_1_4);
  for (const ExactRemainder* t : {&equal, &large, &small})
    if (std::abs(lambda / t->lambda() - 1.0) <= 1e-9) return t;
  return nullptr;
}

std::string ExactRemainder::shipped_ratios() { return "1, 1.4 and 1/1.4"; }

double ExactRemainder::interpolation(double xi, std::size_t& k0, std::size_t& k1) const {
  const auto it = std::upper_bound(xi_.begin(), xi_.end(), xi);
  k1 = static_cast<std::size_t>(it - xi_.begin());
  k0 = k1 == 0 ? 0 : k1 - 1;
  if (k1 >= xi_.size()) k1 = k0 = xi_.size() - 1;
  return k1 != k0 ? (xi - xi_[k0]) / (xi_[k1] - xi_[k0]) : 0.0;
}

ResistanceScalars ExactRemainder::at(double xi) const {
  std::size_t k0 = 0, k1 = 0;
  const double w = interpolation(xi, k0, k1);
  ResistanceScalars r{};
  for (auto f : tabulated_functions) r.*f = (1.0 - w) * remainder_[k0].*f + w * remainder_[k1].*f;
  return r;
}

ResistanceScalars ExactRemainder::exact(double xi, double log_inv_xi) const {
  ResistanceScalars s = lubrication_scalars(coefficients_, xi, log_inv_xi);
  add_stokes_drag(s);
  add_to(xi, s);
  return s;
}

ResistanceScalars ExactRemainder::exact_with_stresslet(double xi, double log_inv_xi) const {
  ResistanceScalars s = exact(xi, log_inv_xi);
  std::size_t k0 = 0, k1 = 0;
  const double w = interpolation(xi, k0, k1);
  for (auto f : tabulated_stresslet_functions) s.*f += (1.0 - w) * remainder_[k0].*f + w * remainder_[k1].*f;
  return s;
}

void ExactRemainder::add_to(double xi, ResistanceScalars& s) const {
  const ResistanceScalars r = at(xi);
  for (auto f : tabulated_functions) s.*f += r.*f;
}

}  // namespace suspend::hydro
