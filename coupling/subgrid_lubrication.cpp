#include "coupling/subgrid_lubrication.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "dem/hydro/exact_relative.hpp"

namespace suspend::coupling {

void SubgridParams::validate() const {
  if (!(cutoff > 2.0 && cutoff <= 5.0)) throw InputError("fcm.subgrid_cutoff must lie in (2, 5] (s' = 2r/(a_i + a_j))");
  if (!(taper_start > 2.0 && taper_start < cutoff))
    throw InputError("fcm.subgrid_taper_start must lie in (2, fcm.subgrid_cutoff)");
  if (!(model_taper_start > 2.0 && model_taper_start < cutoff))
    throw InputError("fcm.subgrid_model_taper_start must lie in (2, fcm.subgrid_cutoff)");
}

SubgridLubrication::SubgridLubrication(std::vector<double> species_radius, const SubgridParams& params,
                                       const hydro::LubricationParams& lubrication, const FcmPairTableParams& table,
                                       const std::string& cache_dir)
    : species_radius_(std::move(species_radius)), params_(params) {
  params_.validate();
  const std::size_t ns = species_radius_.size();
  pairs_.reserve(ns * ns);
  for (std::size_t a = 0; a < ns; ++a)
    for (std::size_t b = 0; b < ns; ++b) {
      const double ra = species_radius_[a], rb = species_radius_[b];
      const bool swapped = ra > rb;
      FcmPairTableParams tp = table;
      tp.a_i = std::min(ra, rb);
      tp.a_j = std::max(ra, rb);
      tp.s_max = params_.cutoff;
      // Only one table per unordered pair: reuse the mirror entry when it exists.
      if (b < a) {
        const SpeciesPair& mirror = pairs_[b * ns + a];
        pairs_.push_back({ExactPairResistance(tp.a_i, tp.a_j, lubrication), mirror.fcm, swapped});
      } else {
        pairs_.push_back({ExactPairResistance(tp.a_i, tp.a_j, lubrication),
                          FcmPairTable::load_or_compute(tp, cache_dir), swapped});
      }
      range_ = std::max(range_, 0.5 * (params_.cutoff - 2.0) * (ra + rb));
    }
}

double SubgridLubrication::taper(double s, bool tabulated) const {
  const double s0 = tabulated ? params_.taper_start : params_.model_taper_start, s1 = params_.cutoff;
  if (s <= s0) return 1.0;
  if (s >= s1) return 0.0;
  const double t = (s - s0) / (s1 - s0);
  return 1.0 - t * t * (3.0 - 2.0 * t);
}

void SubgridLubrication::scalars(int si, int sj, double gap, ResistanceScalars& from_i,
                                 ResistanceScalars& from_j) const {
  const SpeciesPair& p = pair_of(si, sj);
  const double a_i = species_radius_[si], a_j = species_radius_[sj];
  const double s = 2.0 * (gap + a_i + a_j) / (a_i + a_j);
  from_i = {};
  from_j = {};
  const double w = taper(s, p.exact.tabulated());
  if (w == 0.0) return;
  ResistanceScalars ei, ej, fi, fj;
  p.exact.scalars(gap, ei, ej);  // tables are ordered small sphere first
  p.fcm.scalars(s, fi, fj);
  if (p.swapped) {
    std::swap(ei, ej);
    std::swap(fi, fj);
  }
  for (auto f : correction_functions) {
    from_i.*f = w * (ei.*f - fi.*f);
    from_j.*f = w * (ej.*f - fj.*f);
  }}

void SubgridLubrication::assemble(const std::vector<ActivePair>& pairs, const std::vector<int>& species) {
  links_.clear();
  normal_.clear();
  lever_i_.clear();
  lever_j_.clear();
  s_.clear();
  delta_r_.clear();
  delta_strain_.clear();
  link_pair_.clear();
  link_contact_.clear();
  link_species_.clear();
  contact_.clear();
  pair_count_ = pairs.size();
  // The strain forces per unit shear rate: the flow's rate scales them (add_strain_forces, pair_forces).
  const Mat3 e_hat = AmbientFlow::simple_shear(1.0).strain_rate();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const ActivePair& pr = pairs[k];
    const PairGeometry& g = pr.geometry();
    const double s = 2.0 * g.r / (g.a_i + g.a_j);
    if (s >= params_.cutoff) continue;
    link_pair_.push_back(static_cast<std::uint32_t>(k));
    ResistanceScalars si, sj;
    scalars(species[pr.i], species[pr.j], g.gap(), si, sj);
    links_.push_back({pr.i, pr.j});
    link_species_.push_back({species[pr.i], species[pr.j]});
    normal_.push_back(g.n);
    lever_i_.push_back(g.lever_i());
    lever_j_.push_back(g.lever_j());
    s_.push_back(s);
    delta_r_.push_back(pair_resistance_coefficients(g.a_i, g.a_j, si, sj));
    delta_strain_.push_back(pair_strain_forces(g.a_i, g.a_j, g.n, si, sj, e_hat, e_hat));
  }
}

Vector12 SubgridLubrication::pair_forces(std::size_t k, const Eigen::VectorXd& dv, double shear_rate) const {
  Vector12 v;
  v << dv.segment<6>(6 * static_cast<Eigen::Index>(links_[k].i)), dv.segment<6>(6 * static_cast<Eigen::Index>(links_[k].j));
  Vector12 f = shear_rate * delta_strain_[k] - pair_resistance_product(delta_r_[k], normal_[k], v);
  if (!link_contact_.empty() && link_contact_[k] >= 0) {  // the implicit contact step's resistance dt C^T S C
    const ContactStep& c = contact_[link_contact_[k]];
    f -= c.c.transpose() * (c.s * (c.c * v));
  }
  return f;
}

void SubgridLubrication::add_velocity_forces(const Eigen::VectorXd& dv, Eigen::VectorXd& f) const {
  // pair_forces without its strain term (zero here): once per corrected pair and Krylov iteration. The same bits
  // as f += pair_forces(k, dv, 0) (negation is exact), up to the sign of zeros.
  for (std::size_t k = 0; k < links_.size(); ++k) {
    const Eigen::Index i = 6 * static_cast<Eigen::Index>(links_[k].i), j = 6 * static_cast<Eigen::Index>(links_[k].j);
    Vector12 v;
    v.head<6>() = dv.segment<6>(i);
    v.tail<6>() = dv.segment<6>(j);
    Vector12 fk = pair_resistance_product(delta_r_[k], normal_[k], v);
    if (!link_contact_.empty() && link_contact_[k] >= 0) {
      const ContactStep& c = contact_[link_contact_[k]];
      fk += c.c.transpose() * (c.s * (c.c * v));
    }
    f.segment<6>(i) -= fk.head<6>();
    f.segment<6>(j) -= fk.tail<6>();
  }
}

void SubgridLubrication::add_strain_forces(double shear_rate, Eigen::VectorXd& f) const {
  for (std::size_t k = 0; k < links_.size(); ++k) {
    f.segment<6>(6 * static_cast<Eigen::Index>(links_[k].i)) += shear_rate * delta_strain_[k].head<6>();
    f.segment<6>(6 * static_cast<Eigen::Index>(links_[k].j)) += shear_rate * delta_strain_[k].tail<6>();
  }
}

void SubgridLubrication::add_contact_steps(const std::vector<ActivePair>& pairs,
                                           const std::vector<ContactStiffness>& stiffness, double dt,
                                           const std::vector<Vec3>& positions, const AmbientFlow& unit_flow) {
  if (pairs.size() != pair_count_ || stiffness.size() != pairs.size())
    throw InputError("sub-grid lubrication: contact stiffnesses must match the assembled pair list");
  link_contact_.assign(links_.size(), -1);
  contact_.clear();
  std::size_t stiff = 0;
  for (std::size_t l = 0; l < links_.size(); ++l) {
    const std::size_t k = link_pair_[l];
    if (!stiffness[k].any()) continue;
    const ContactStep c = contact_step(pairs[k].geometry(), positions[pairs[k].i], stiffness[k], dt, unit_flow);
    // (Its resistance is applied from `contact_` in pair_forces and resistance_matrix: delta_r_ holds the
    // lubrication blocks' coefficients only.)
    delta_strain_[l] += c.ambient_force();
    link_contact_[l] = static_cast<std::int32_t>(contact_.size());
    contact_.push_back(c);
  }
  for (const ContactStiffness& k : stiffness) stiff += k.any() ? 1 : 0;
  if (stiff != contact_.size())
    throw InputError("sub-grid lubrication: a contact pair lies beyond the correction cutoff fcm.subgrid_cutoff");
}

void SubgridLubrication::contact_changes(const Eigen::VectorXd& dv, double shear_rate,
                                         std::vector<Vec3>& change_on_j) const {
  change_on_j.clear();
  if (contact_.empty()) return;
  change_on_j.assign(pair_count_, Vec3::Zero());
  for (std::size_t l = 0; l < links_.size(); ++l)
    if (link_contact_[l] >= 0) change_on_j[link_pair_[l]] = contact_change(l, dv, shear_rate);
}

Vec3 SubgridLubrication::contact_change(std::size_t l, const Eigen::VectorXd& dv, double shear_rate) const {
  const ContactStep& c = contact_[link_contact_[l]];
  Vector12 v;
  v << dv.segment<6>(6 * static_cast<Eigen::Index>(links_[l].i)), dv.segment<6>(6 * static_cast<Eigen::Index>(links_[l].j));
  return -(c.s * (shear_rate * c.u_inf + c.c * v));
}

Mat3 SubgridLubrication::stress(const Eigen::VectorXd& dv, double shear_rate) const {
  Mat3 sum = Mat3::Zero();
  for (std::size_t k = 0; k < links_.size(); ++k) {
    Vector12 fk = pair_forces(k, dv, shear_rate);
    if (!link_contact_.empty() && link_contact_[k] >= 0)  // the contact step is not lubrication
      fk -= contact_[link_contact_[k]].c.transpose() * contact_change(k, dv, shear_rate);
    const Vec3& n = normal_[k];
    const Mat3 dip = -lever_i_[k] * n * fk.segment<3>(0).transpose() + lever_j_[k] * n * fk.segment<3>(6).transpose();
    sum -= 0.5 * (dip + dip.transpose());
  }
  return sum;
}

Matrix12 SubgridLubrication::fcm_relative_resistance(std::size_t k) const {
  const auto [si, sj] = link_species_[k];
  const SpeciesPair& p = pair_of(si, sj);
  ResistanceScalars fi, fj, li, lj;
  p.fcm.scalars(s_[k], fi, fj);  // tables are ordered small sphere first
  if (p.swapped) std::swap(fi, fj);
  const double a_i = species_radius_[si], a_j = species_radius_[sj];
  hydro::exact_relative_part(a_i, a_j, fi, fj, li, lj);
  return pair_resistance(pair_resistance_coefficients(a_i, a_j, li, lj), normal_[k]);
}

void SubgridLubrication::resistance_matrix(const std::vector<double>& radius, double s_max,
                                           SymmetricBlockMatrix& m, bool every_contact, bool fcm_relative) {
  const auto kept = [&](std::size_t k) {
    return s_[k] < s_max || (every_contact && !link_contact_.empty() && link_contact_[k] >= 0);
  };
  near_links_.clear();
  for (std::size_t k = 0; k < links_.size(); ++k)
    if (kept(k)) near_links_.push_back(links_[k]);
  m.set_structure(radius.size(), near_links_);
  auto& diag = m.diagonal();
  for (std::size_t i = 0; i < radius.size(); ++i) {
    const double a = radius[i];
    diag[i].setZero();
    diag[i].diagonal() << Vec3::Constant(6.0 * std::numbers::pi * a), Vec3::Constant(8.0 * std::numbers::pi * a * a * a);
  }
  auto& coupling = m.coupling();
  std::size_t c = 0;
  for (std::size_t k = 0; k < links_.size(); ++k) {
    if (!kept(k)) continue;
    Matrix12 r = pair_resistance(delta_r_[k], normal_[k]);
    if (fcm_relative && s_[k] < s_max) r += fcm_relative_resistance(k);
    if (!link_contact_.empty() && link_contact_[k] >= 0) r += contact_[link_contact_[k]].resistance();
    diag[links_[k].i] += r.block<6, 6>(0, 0);
    diag[links_[k].j] += r.block<6, 6>(6, 6);
    coupling[c++] = r.block<6, 6>(0, 6);
  }
}

}  // namespace suspend::coupling
