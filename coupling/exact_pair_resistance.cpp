#include "coupling/exact_pair_resistance.hpp"

#include <cmath>

#include "core/error.hpp"

namespace suspend::coupling {
namespace {

hydro::ResistanceScalars model(const hydro::LubricationCoefficients& c, double xi, double log_inv_xi) {
  hydro::ResistanceScalars s = hydro::lubrication_scalars(c, xi, log_inv_xi);
  hydro::add_stokes_drag(s);
  return s;
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
  table_i_ = hydro::ExactRemainder::for_ratio(a_j / a_i);
  table_j_ = hydro::ExactRemainder::for_ratio(a_i / a_j);
  if (table_i_ == nullptr || table_j_ == nullptr) table_i_ = table_j_ = nullptr;
}

double ExactPairResistance::scaled_gap(double gap) const {
  return 2.0 * std::fmax(gap, lubrication_.inner_cutoff) / (a_i_ + a_j_) + lubrication_.regularization;
}

void ExactPairResistance::scalars(double gap, hydro::ResistanceScalars& from_i,
                                  hydro::ResistanceScalars& from_j) const {
  const double xi = scaled_gap(gap);
  const double log_inv_xi = std::log(1.0 / xi);  // (what lubrication_scalars(c, xi) takes: the same bits)
  if (tabulated()) {
    from_i = table_i_->exact(xi, log_inv_xi);
    from_j = table_j_->exact(xi, log_inv_xi);
    return;
  }
  from_i = model(from_i_, xi, log_inv_xi);
  from_j = model(from_j_, xi, log_inv_xi);
}

}  // namespace suspend::coupling
