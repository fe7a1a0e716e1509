// Assembly of the pair tensors from scalars and its inverse for n = e_x; conventions in pair_tensors.hpp.
#include "coupling/pair_tensors.hpp"

#include <numbers>

namespace suspend::coupling {
namespace {

constexpr double pi = std::numbers::pi;

// The strain E seen along d = n: E n and n.E.n (along -n: -E n and the same n.E.n).
struct StrainAlong {
  Vec3 en;
  double ded;
  Vec3 cross;  // n x (E n)
  StrainAlong(const Vec3& n, const Mat3& e) : en(e * n), ded(n.dot(en)), cross(n.cross(en)) {}
};

// Force of strain E through G^{ba}_{jki} E_jk along d = n: X (d.E.d) d + 2 Y (E d - (d.E.d) d); along -n it
// changes sign (both terms are odd in d).
Vec3 strain_force(double scale, const Vec3& n, double x, double y, const StrainAlong& e) {
  return scale * (x * e.ded * n + 2.0 * y * (e.en - e.ded * n));
}

// Torque of strain E through H^{ba}_{jki} E_jk: 2 Y d x (E d), even in d.
Vec3 strain_torque(double scale, double y, const StrainAlong& e) { return scale * 2.0 * y * e.cross; }

}  // namespace

Matrix12 pair_resistance(double a_i, double a_j, const Vec3& n, const ResistanceScalars& si,
                         const ResistanceScalars& sj) {
  Matrix12 r;
  const Mat3 nn = n * n.transpose();
  const Mat3 tt = Mat3::Identity() - nn;
  Mat3 nx;
  nx << 0.0, -n.z(), n.y(), n.z(), 0.0, -n.x(), -n.y(), n.x(), 0.0;
  const double fa_i = 6.0 * pi * a_i, fa_j = 6.0 * pi * a_j;
  const double fb_i = 4.0 * pi * a_i * a_i, fb_j = 4.0 * pi * a_j * a_j;
  const double fc_i = 8.0 * pi * a_i * a_i * a_i, fc_j = 8.0 * pi * a_j * a_j * a_j;
  r.block<3, 3>(0, 0) = fa_i * (si.x11a * nn + si.y11a * tt);
  r.block<3, 3>(6, 6) = fa_j * (sj.x11a * nn + sj.y11a * tt);
  r.block<3, 3>(0, 6) = fa_i * (si.x12a * nn + si.y12a * tt);
  r.block<3, 3>(6, 0) = r.block<3, 3>(0, 6);
  r.block<3, 3>(3, 3) = fc_i * (si.x11c * nn + si.y11c * tt);
  r.block<3, 3>(9, 9) = fc_j * (sj.x11c * nn + sj.y11c * tt);
  r.block<3, 3>(3, 9) = fc_i * (si.x12c * nn + si.y12c * tt);
  r.block<3, 3>(9, 3) = r.block<3, 3>(3, 9);
  // B v = Y v x d = -Y [d]_x v; seen from j, d = -n.
  r.block<3, 3>(3, 0) = (-fb_i * si.y11b) * nx;
  r.block<3, 3>(3, 6) = (-fb_i * si.y12b) * nx;
  r.block<3, 3>(9, 6) = (fb_j * sj.y11b) * nx;
  r.block<3, 3>(9, 0) = (fb_j * sj.y12b) * nx;
  r.block<3, 3>(0, 3) = r.block<3, 3>(3, 0).transpose();
  r.block<3, 3>(6, 3) = r.block<3, 3>(3, 6).transpose();
  r.block<3, 3>(6, 9) = r.block<3, 3>(9, 6).transpose();
  r.block<3, 3>(0, 9) = r.block<3, 3>(9, 0).transpose();
  return r;
}

Vector12 pair_strain_forces(double a_i, double a_j, const Vec3& n, const ResistanceScalars& si,
                            const ResistanceScalars& sj, const Mat3& e_i, const Mat3& e_j) {
  Vector12 f;
  // Seen from j, d = -n: the forces flip sign, the torques do not.
  const StrainAlong ei(n, e_i), ej(n, e_j);
  const double fg_i = 4.0 * pi * a_i * a_i, fg_j = 4.0 * pi * a_j * a_j;
  const double fh_i = 8.0 * pi * a_i * a_i * a_i, fh_j = 8.0 * pi * a_j * a_j * a_j;
  f.segment<3>(0) = strain_force(fg_i, n, si.x11g, si.y11g, ei) - strain_force(fg_j, n, sj.x12g, sj.y12g, ej);
  f.segment<3>(6) = strain_force(fg_i, n, si.x12g, si.y12g, ei) - strain_force(fg_j, n, sj.x11g, sj.y11g, ej);
  f.segment<3>(3) = strain_torque(fh_i, si.y11h, ei) + strain_torque(fh_j, sj.y12h, ej);
  f.segment<3>(9) = strain_torque(fh_j, sj.y11h, ej) + strain_torque(fh_i, si.y12h, ei);
  return f;
}

Vector12 pair_resistance_product(double a_i, double a_j, const Vec3& n, const ResistanceScalars& si,
                                 const ResistanceScalars& sj, const Vector12& v) {
  // Plain scalars (no Eigen temporaries): this runs for every corrected pair in every Krylov iteration.
  const double fa_i = 6.0 * pi * a_i, fa_j = 6.0 * pi * a_j;
  const double fb_i = 4.0 * pi * a_i * a_i, fb_j = 4.0 * pi * a_j * a_j;
  const double fc_i = 8.0 * pi * a_i * a_i * a_i, fc_j = 8.0 * pi * a_j * a_j * a_j;
  const double n0 = n.x(), n1 = n.y(), n2 = n.z();
  double x[12];
  for (int k = 0; k < 12; ++k) x[k] = v(k);
  const double* ui = x;
  const double* wi = x + 3;
  const double* uj = x + 6;
  const double* wj = x + 9;
  const auto dot = [&](const double* u) { return n0 * u[0] + n1 * u[1] + n2 * u[2]; };
  const double nui = dot(ui), nwi = dot(wi), nuj = dot(uj), nwj = dot(wj);
  // (X n n + Y (I - n n)) u = Y u + (X - Y)(n.u) n, and [n]_x u = n x u (pair_resistance's blocks).
  const double cui[3] = {n1 * ui[2] - n2 * ui[1], n2 * ui[0] - n0 * ui[2], n0 * ui[1] - n1 * ui[0]};
  const double cwi[3] = {n1 * wi[2] - n2 * wi[1], n2 * wi[0] - n0 * wi[2], n0 * wi[1] - n1 * wi[0]};
  const double cuj[3] = {n1 * uj[2] - n2 * uj[1], n2 * uj[0] - n0 * uj[2], n0 * uj[1] - n1 * uj[0]};
  const double cwj[3] = {n1 * wj[2] - n2 * wj[1], n2 * wj[0] - n0 * wj[2], n0 * wj[1] - n1 * wj[0]};
  // Axial coefficients (X - Y) and transverse Y, scaled.
  const double ya11 = fa_i * si.y11a, xa11 = fa_i * (si.x11a - si.y11a) * nui;
  const double ya12 = fa_i * si.y12a, xa12j = fa_i * (si.x12a - si.y12a) * nuj, xa12i = fa_i * (si.x12a - si.y12a) * nui;
  const double ya22 = fa_j * sj.y11a, xa22 = fa_j * (sj.x11a - sj.y11a) * nuj;
  const double yc11 = fc_i * si.y11c, xc11 = fc_i * (si.x11c - si.y11c) * nwi;
  const double yc12 = fc_i * si.y12c, xc12j = fc_i * (si.x12c - si.y12c) * nwj, xc12i = fc_i * (si.x12c - si.y12c) * nwi;
  const double yc22 = fc_j * sj.y11c, xc22 = fc_j * (sj.x11c - sj.y11c) * nwj;
  const double b11 = fb_i * si.y11b, b12 = fb_i * si.y12b, b22 = fb_j * sj.y11b, b21 = fb_j * sj.y12b;
  const double nn[3] = {n0, n1, n2};
  Vector12 f;
  for (int c = 0; c < 3; ++c) {
    f(c) = ya11 * ui[c] + xa11 * nn[c] + ya12 * uj[c] + xa12j * nn[c] + b11 * cwi[c] - b21 * cwj[c];
    f(3 + c) = yc11 * wi[c] + xc11 * nn[c] + yc12 * wj[c] + xc12j * nn[c] - b11 * cui[c] - b12 * cuj[c];
    f(6 + c) = ya12 * ui[c] + xa12i * nn[c] + ya22 * uj[c] + xa22 * nn[c] + b12 * cwi[c] - b22 * cwj[c];
    f(9 + c) = yc12 * wi[c] + xc12i * nn[c] + yc22 * wj[c] + xc22 * nn[c] + b21 * cui[c] + b22 * cuj[c];
  }
  return f;
}

void scalars_along_x(double a_i, double a_j, const Matrix12& r, const std::array<std::array<Mat3, 12>, 2>& s,
                     ResistanceScalars& si, ResistanceScalars& sj) {
  const double fa_i = 6.0 * pi * a_i, fa_j = 6.0 * pi * a_j;
  const double fb_i = 4.0 * pi * a_i * a_i, fb_j = 4.0 * pi * a_j * a_j;
  const double fc_i = 8.0 * pi * a_i * a_i * a_i, fc_j = 8.0 * pi * a_j * a_j * a_j;
  // Transverse functions are averaged over the y and z directions (the grid breaks the axial symmetry slightly).
  si.x11a = r(0, 0) / fa_i;
  si.y11a = (r(1, 1) + r(2, 2)) / (2.0 * fa_i);
  si.x12a = r(0, 6) / fa_i;
  si.y12a = (r(1, 7) + r(2, 8)) / (2.0 * fa_i);
  sj.x11a = r(6, 6) / fa_j;
  sj.y11a = (r(7, 7) + r(8, 8)) / (2.0 * fa_j);
  sj.x12a = r(6, 0) / fa_j;
  sj.y12a = (r(7, 1) + r(8, 2)) / (2.0 * fa_j);
  si.x11c = r(3, 3) / fc_i;
  si.y11c = (r(4, 4) + r(5, 5)) / (2.0 * fc_i);
  si.x12c = r(3, 9) / fc_i;
  si.y12c = (r(4, 10) + r(5, 11)) / (2.0 * fc_i);
  sj.x11c = r(9, 9) / fc_j;
  sj.y11c = (r(10, 10) + r(11, 11)) / (2.0 * fc_j);
  sj.x12c = r(9, 3) / fc_j;
  sj.y12c = (r(10, 4) + r(11, 5)) / (2.0 * fc_j);
  si.y11b = (r(4, 2) - r(5, 1)) / (2.0 * fb_i);
  si.y12b = (r(4, 8) - r(5, 7)) / (2.0 * fb_i);
  sj.y11b = (r(11, 7) - r(10, 8)) / (2.0 * fb_j);
  sj.y12b = (r(11, 1) - r(10, 2)) / (2.0 * fb_j);
  // S_a = -G^{ab} dV_b: with d = e_x (seen from i) or -e_x (from j), G e_x has xx = (2/3) X (d.e_x), G e_y has
  // xy = Y (d.e_x), H e_z has xy = Y and H e_y has xz = -Y (factors 4 pi a^2, 8 pi a^3).
  const auto& s_i = s[0];
  const auto& s_j = s[1];
  si.x11g = -1.5 * s_i[0](0, 0) / fb_i;
  si.x12g = -1.5 * s_i[6](0, 0) / fb_i;
  si.y11g = -(s_i[1](0, 1) + s_i[2](0, 2)) / (2.0 * fb_i);
  si.y12g = -(s_i[7](0, 1) + s_i[8](0, 2)) / (2.0 * fb_i);
  si.y11h = (-s_i[5](0, 1) + s_i[4](0, 2)) / (2.0 * fc_i);
  si.y12h = (-s_i[11](0, 1) + s_i[10](0, 2)) / (2.0 * fc_i);
  sj.x11g = 1.5 * s_j[6](0, 0) / fb_j;
  sj.x12g = 1.5 * s_j[0](0, 0) / fb_j;
  sj.y11g = (s_j[7](0, 1) + s_j[8](0, 2)) / (2.0 * fb_j);
  sj.y12g = (s_j[1](0, 1) + s_j[2](0, 2)) / (2.0 * fb_j);
  sj.y11h = (-s_j[11](0, 1) + s_j[10](0, 2)) / (2.0 * fc_j);
  sj.y12h = (-s_j[5](0, 1) + s_j[4](0, 2)) / (2.0 * fc_j);
}

}  // namespace suspend::coupling
