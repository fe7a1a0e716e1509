// Assembly of the pair lubrication law; formulas and sign conventions in lubrication.hpp.
#include "dem/hydro/lubrication.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "dem/hydro/exact_relative.hpp"
#include "dem/hydro/exact_remainder.hpp"

namespace suspend::hydro {
using std::numbers::pi;
namespace {

Mat3 normal_projector(const Vec3& d) { return d * d.transpose(); }

// Force of strain E through G^{ba}_{jki} E_jk: X (d.E.d) d + 2 Y (E d - (d.E.d) d).
Vec3 strain_force(double scale, const Vec3& d, double x, double y, const Mat3& e) {
  const Vec3 ed = e * d;
  const double ded = d.dot(ed);
  return scale * (x * ded * d + 2.0 * y * (ed - ded * d));
}

// Torque of strain E through H^{ba}_{jki} E_jk: 2 Y d x (E d).
Vec3 strain_torque(double scale, const Vec3& d, double y, const Mat3& e) { return scale * 2.0 * y * d.cross(e * d); }

// G v: X (d d - I/3)(d.v) + Y (d v + v d - 2 d d (d.v)).
Mat3 stresslet_of_velocity(double scale, const Vec3& d, double x, double y, const Vec3& v) {
  const double dv = d.dot(v);
  const Mat3 nn = normal_projector(d);
  const Mat3 dvt = d * v.transpose();
  return scale * (x * dv * (nn - Mat3::Identity() / 3.0) + y * (dvt + dvt.transpose() - 2.0 * dv * nn));
}

// H w: Y ((w x d) d + d (w x d)).
Mat3 stresslet_of_rotation(double scale, const Vec3& d, double y, const Vec3& w) {
  const Mat3 t = w.cross(d) * d.transpose();
  return scale * y * (t + t.transpose());
}

// M : E: X (3/2)(d.E.d)(d d - I/3) + Y (d (E d) + (E d) d - 2 (d.E.d) d d).
Mat3 stresslet_of_strain(double scale, const Vec3& d, double x, double y, const Mat3& e) {
  const Vec3 ed = e * d;
  const double ded = d.dot(ed);
  const Mat3 nn = normal_projector(d);
  const Mat3 ded_t = d * ed.transpose();
  return scale * (1.5 * x * ded * (nn - Mat3::Identity() / 3.0) + y * (ded_t + ded_t.transpose() - 2.0 * ded * nn));
}

}  // namespace

void LubricationParams::validate() const {
  if (!(regularization >= 0.0) || !std::isfinite(regularization))
    throw InputError("lubrication.regularization = " + std::to_string(regularization) + " must be >= 0");
  if (!(inner_cutoff >= 0.0) || !std::isfinite(inner_cutoff))
    throw InputError("lubrication.inner_cutoff = " + std::to_string(inner_cutoff) + " must be >= 0");
  if (!(outer_cutoff > inner_cutoff))
    throw InputError("lubrication.outer_cutoff = " + std::to_string(outer_cutoff) +
                     " must be > lubrication.inner_cutoff = " + std::to_string(inner_cutoff));
  if (regularization == 0.0 && inner_cutoff == 0.0)
    throw InputError(
        "lubrication.regularization and lubrication.inner_cutoff are both 0: overlapping pairs would have infinite "
        "resistance; set one of them > 0 (e.g. inner_cutoff: 0.001)");
}

Vector12 PairMotion::stacked() const {
  Vector12 v;
  v << du_i, dw_i, du_j, dw_j;
  return v;
}

PairLubrication::PairLubrication(double a_i, double a_j, const LubricationParams& params)
    : a_i_(a_i),
      a_j_(a_j),
      params_(params),
      from_i_(LubricationCoefficients::for_ratio(a_j / a_i)),
      from_j_(LubricationCoefficients::for_ratio(a_i / a_j)) {
  if (!(a_i > 0.0) || !(a_j > 0.0))
    throw InputError("lubrication pair radii must be > 0 (got " + std::to_string(a_i) + ", " + std::to_string(a_j) +
                     ")");
  if (params.exact_relative) {
    exact_i_ = ExactRemainder::for_ratio(a_j / a_i);
    exact_j_ = ExactRemainder::for_ratio(a_i / a_j);
    if (exact_i_ == nullptr || exact_j_ == nullptr) exact_i_ = exact_j_ = nullptr;
  }
  // The ln(1/xi) terms change sign at xi = 1: beyond it the model would no longer dissipate (paper 002 App. B:
  // the outer cutoff cannot be arbitrarily large).
  if (!(scaled_gap(params.outer_cutoff) < 1.0))
    throw InputError("lubrication.outer_cutoff = " + std::to_string(params.outer_cutoff) +
                     " is too large for radii " + std::to_string(a_i) + " and " + std::to_string(a_j) +
                     ": need 2 h_out/(a_i + a_j) + regularization < 1");
}

double PairLubrication::scaled_gap(double gap) const {
  return 2.0 * std::fmax(gap, params_.inner_cutoff) / (a_i_ + a_j_) + params_.regularization;
}

void PairLubrication::scalars(double gap, ResistanceScalars& from_i, ResistanceScalars& from_j) const {
  if (!active(gap)) {
    from_i = ResistanceScalars{};
    from_j = ResistanceScalars{};
    return;
  }
  const double xi = scaled_gap(gap);
  const double log_inv_xi = std::log(1.0 / xi);  // shared by both perspectives
  from_i = lubrication_scalars(from_i_, xi, log_inv_xi);
  from_j = lubrication_scalars(from_j_, xi, log_inv_xi);
  if (exact_i_ != nullptr)
    exact_relative_part(a_i_, a_j_, exact_i_->exact(xi, log_inv_xi), exact_j_->exact(xi, log_inv_xi), from_i, from_j);
}

Matrix12 PairLubrication::resistance(const Vec3& n, double gap) const {
  if (!active(gap)) return Matrix12::Zero();
  ResistanceScalars si, sj;
  scalars(gap, si, sj);
  return pair_resistance(a_i_, a_j_, n, si, sj);
}

Matrix12 pair_resistance(double ai, double aj, const Vec3& n, const ResistanceScalars& si,
                         const ResistanceScalars& sj) {
  Matrix12 r;  // all 16 blocks are written below
  // d d^T is the same seen from i (d = n) and from j (d = -n); [d]_x flips sign.
  const Mat3 nn = normal_projector(n);
  const Mat3 tt = Mat3::Identity() - nn;
  Mat3 nx;
  nx << 0.0, -n.z(), n.y(), n.z(), 0.0, -n.x(), -n.y(), n.x(), 0.0;
  const double fa_i = 6.0 * pi * ai, fa_j = 6.0 * pi * aj;
  const double fb_i = 4.0 * pi * ai * ai, fb_j = 4.0 * pi * aj * aj;
  const double fc_i = 8.0 * pi * ai * ai * ai, fc_j = 8.0 * pi * aj * aj * aj;

  // Translation (A): self blocks from each particle, the pair block from i and its transpose (reciprocity).
  r.block<3, 3>(0, 0) = fa_i * (si.x11a * nn + si.y11a * tt);
  r.block<3, 3>(6, 6) = fa_j * (sj.x11a * nn + sj.y11a * tt);
  r.block<3, 3>(0, 6) = fa_i * (si.x12a * nn + si.y12a * tt);
  r.block<3, 3>(6, 0) = r.block<3, 3>(0, 6);  // symmetric block
  // Rotation (C).
  r.block<3, 3>(3, 3) = fc_i * (si.x11c * nn + si.y11c * tt);
  r.block<3, 3>(9, 9) = fc_j * (sj.x11c * nn + sj.y11c * tt);
  r.block<3, 3>(3, 9) = fc_i * (si.x12c * nn + si.y12c * tt);
  r.block<3, 3>(9, 3) = r.block<3, 3>(3, 9);
  // Coupling (B v = Y v x d = -Y [d]_x v): torque rows from velocity columns; force rows from rotation columns are
  // the transposes. Seen from j, d = -n.
  r.block<3, 3>(3, 0) = (-fb_i * si.y11b) * nx;  // T_i from U_i
  r.block<3, 3>(3, 6) = (-fb_i * si.y12b) * nx;  // T_i from U_j
  r.block<3, 3>(9, 6) = (fb_j * sj.y11b) * nx;   // T_j from U_j
  r.block<3, 3>(9, 0) = (fb_j * sj.y12b) * nx;   // T_j from U_i
  r.block<3, 3>(0, 3) = r.block<3, 3>(3, 0).transpose();
  r.block<3, 3>(6, 3) = r.block<3, 3>(3, 6).transpose();
  r.block<3, 3>(6, 9) = r.block<3, 3>(9, 6).transpose();
  r.block<3, 3>(0, 9) = r.block<3, 3>(9, 0).transpose();
  return r;
}

Vector12 PairLubrication::strain_forces(const Vec3& n, double gap, const Mat3& e_i, const Mat3& e_j) const {
  if (!active(gap)) return Vector12::Zero();
  ResistanceScalars si, sj;
  scalars(gap, si, sj);
  return pair_strain_forces(a_i_, a_j_, n, si, sj, e_i, e_j);
}

Vector12 pair_strain_forces(double ai, double aj, const Vec3& n, const ResistanceScalars& si,
                            const ResistanceScalars& sj, const Mat3& e_i, const Mat3& e_j) {
  Vector12 f;
  const Vec3 m = -n;
  const double fg_i = 4.0 * pi * ai * ai, fg_j = 4.0 * pi * aj * aj;
  const double fh_i = 8.0 * pi * ai * ai * ai, fh_j = 8.0 * pi * aj * aj * aj;
  // F_a = G^{aa}_{jki} E_a,jk + G^{ba}_{jki} E_b,jk: the second term is the stresslet of b due to the motion of a.
  f.segment<3>(0) = strain_force(fg_i, n, si.x11g, si.y11g, e_i) + strain_force(fg_j, m, sj.x12g, sj.y12g, e_j);
  f.segment<3>(6) = strain_force(fg_j, m, sj.x11g, sj.y11g, e_j) + strain_force(fg_i, n, si.x12g, si.y12g, e_i);
  f.segment<3>(3) = strain_torque(fh_i, n, si.y11h, e_i) + strain_torque(fh_j, m, sj.y12h, e_j);
  f.segment<3>(9) = strain_torque(fh_j, m, sj.y11h, e_j) + strain_torque(fh_i, n, si.y12h, e_i);
  return f;
}

PairHydroForce PairLubrication::evaluate(const Vec3& n, double gap, const PairMotion& mo) const {
  PairHydroForce out;
  if (!active(gap)) return out;
  ResistanceScalars si, sj;
  scalars(gap, si, sj);
  const Vector12 f = -pair_resistance(a_i_, a_j_, n, si, sj) * mo.stacked() +
                     pair_strain_forces(a_i_, a_j_, n, si, sj, mo.e_i, mo.e_j);
  out.force_i = f.segment<3>(0);
  out.torque_i = f.segment<3>(3);
  out.force_j = f.segment<3>(6);
  out.torque_j = f.segment<3>(9);

  const Vec3 m = -n;
  const double ai = a_i_, aj = a_j_;
  const double fg_i = 4.0 * pi * ai * ai, fg_j = 4.0 * pi * aj * aj;
  const double fh_i = 8.0 * pi * ai * ai * ai, fh_j = 8.0 * pi * aj * aj * aj;
  const double fm_i = 20.0 / 3.0 * pi * ai * ai * ai, fm_j = 20.0 / 3.0 * pi * aj * aj * aj;
  out.stresslet_i = -stresslet_of_velocity(fg_i, n, si.x11g, si.y11g, mo.du_i) -
                    stresslet_of_velocity(fg_i, n, si.x12g, si.y12g, mo.du_j) -
                    stresslet_of_rotation(fh_i, n, si.y11h, mo.dw_i) - stresslet_of_rotation(fh_i, n, si.y12h, mo.dw_j) +
                    stresslet_of_strain(fm_i, n, si.x11m, si.y11m, mo.e_i) +
                    stresslet_of_strain(fm_i, n, si.x12m, si.y12m, mo.e_j);
  out.stresslet_j = -stresslet_of_velocity(fg_j, m, sj.x11g, sj.y11g, mo.du_j) -
                    stresslet_of_velocity(fg_j, m, sj.x12g, sj.y12g, mo.du_i) -
                    stresslet_of_rotation(fh_j, m, sj.y11h, mo.dw_j) - stresslet_of_rotation(fh_j, m, sj.y12h, mo.dw_i) +
                    stresslet_of_strain(fm_j, m, sj.x11m, sj.y11m, mo.e_j) +
                    stresslet_of_strain(fm_j, m, sj.x12m, sj.y12m, mo.e_i);
  return out;
}

}  // namespace suspend::hydro
