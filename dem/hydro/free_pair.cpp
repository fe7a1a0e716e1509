// Stress of a free pair; conventions in free_pair.hpp and lubrication.hpp.
#include "dem/hydro/free_pair.hpp"

#include <numbers>

namespace suspend::hydro {
using std::numbers::pi;
namespace {

// G v: X (d d - I/3)(d.v) + Y (d v + v d - 2 d d (d.v)).
Mat3 of_velocity(double scale, const Vec3& d, double x, double y, const Vec3& v) {
  const double dv = d.dot(v);
  const Mat3 nn = d * d.transpose();
  const Mat3 dvt = d * v.transpose();
  return scale * (x * dv * (nn - Mat3::Identity() / 3.0) + y * (dvt + dvt.transpose() - 2.0 * dv * nn));
}

// H w: Y ((w x d) d + d (w x d)).
Mat3 of_rotation(double scale, const Vec3& d, double y, const Vec3& w) {
  const Mat3 t = w.cross(d) * d.transpose();
  return scale * y * (t + t.transpose());
}

// M : E for symmetric traceless E (Kim & Karrila eq. 11.3.x contracted):
//   X (3/2)(d.E.d)(d d - I/3) + Y (d (E d) + (E d) d - 2 (d.E.d) d d)
//   + Z (E + (1/2)(d.E.d)(I + d d) - d (E d) - (E d) d);  X = Y = Z = 1 gives E.
Mat3 of_strain(double scale, const Vec3& d, double x, double y, double z, const Mat3& e) {
  const Vec3 ed = e * d;
  const double ded = d.dot(ed);
  const Mat3 nn = d * d.transpose();
  const Mat3 d_ed = d * ed.transpose();
  const Mat3 sym = d_ed + d_ed.transpose();
  return scale * (1.5 * x * ded * (nn - Mat3::Identity() / 3.0) + y * (sym - 2.0 * ded * nn) +
                  z * (e + 0.5 * ded * (Mat3::Identity() + nn) - sym));
}

}  // namespace

void pair_stresslets(double ai, double aj, const Vec3& n, const ResistanceScalars& si, const ResistanceScalars& sj,
                     const Vector12& dv, const Mat3& e_i, const Mat3& e_j, Mat3& s_i, Mat3& s_j) {
  const Vec3 m = -n;
  const Vec3 du_i = dv.segment<3>(0), dw_i = dv.segment<3>(3), du_j = dv.segment<3>(6), dw_j = dv.segment<3>(9);
  const double fg_i = 4.0 * pi * ai * ai, fg_j = 4.0 * pi * aj * aj;
  const double fh_i = 8.0 * pi * ai * ai * ai, fh_j = 8.0 * pi * aj * aj * aj;
  const double fm_i = 20.0 / 3.0 * pi * ai * ai * ai, fm_j = 20.0 / 3.0 * pi * aj * aj * aj;
  s_i = -of_velocity(fg_i, n, si.x11g, si.y11g, du_i) - of_velocity(fg_i, n, si.x12g, si.y12g, du_j) -
        of_rotation(fh_i, n, si.y11h, dw_i) - of_rotation(fh_i, n, si.y12h, dw_j) +
        of_strain(fm_i, n, si.x11m, si.y11m, si.z11m, e_i) + of_strain(fm_i, n, si.x12m, si.y12m, si.z12m, e_j);
  s_j = -of_velocity(fg_j, m, sj.x11g, sj.y11g, du_j) - of_velocity(fg_j, m, sj.x12g, sj.y12g, du_i) -
        of_rotation(fh_j, m, sj.y11h, dw_j) - of_rotation(fh_j, m, sj.y12h, dw_i) +
        of_strain(fm_j, m, sj.x11m, sj.y11m, sj.z11m, e_j) + of_strain(fm_j, m, sj.x12m, sj.y12m, sj.z12m, e_i);
}

FreePairStress free_pair_stress(double ai, double aj, const Vec3& n, double gap, const ResistanceScalars& si,
                                const ResistanceScalars& sj, const Mat3& e) {
  FreePairStress out;
  const Matrix12 r = pair_resistance(ai, aj, n, si, sj);
  const Vector12 load = pair_strain_forces(ai, aj, n, si, sj, e, e);
  out.disturbance = r.ldlt().solve(load);
  Mat3 s_i, s_j;
  pair_stresslets(ai, aj, n, si, sj, out.disturbance, e, e, s_i, s_j);
  const Mat3 isolated = 20.0 / 3.0 * pi * (ai * ai * ai + aj * aj * aj) * e;
  out.stresslet = s_i + s_j - isolated;
  const Vec3 d = (ai + aj + gap) * n;
  const Vec3 f_j = 6.0 * pi * aj * out.disturbance.segment<3>(6);  // balances the pair force on j
  const Mat3 df = d * f_j.transpose();
  out.force_dipole = -0.5 * (df + df.transpose());
  return out;
}

}  // namespace suspend::hydro
