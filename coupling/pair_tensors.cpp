// Assembly of the pair tensors from scalars and its inverse for n = e_x; conventions in pair_tensors.hpp.
#include "coupling/pair_tensors.hpp"

#include <numbers>

namespace suspend::coupling {

using std::numbers::pi;

PairResistanceCoefficients pair_resistance_coefficients(double a_i, double a_j, const ResistanceScalars& si,
                                                        const ResistanceScalars& sj) {
  const double fa_i = 6.0 * pi * a_i, fa_j = 6.0 * pi * a_j;
  const double fb_i = 4.0 * pi * a_i * a_i, fb_j = 4.0 * pi * a_j * a_j;
  const double fc_i = 8.0 * pi * a_i * a_i * a_i, fc_j = 8.0 * pi * a_j * a_j * a_j;
  PairResistanceCoefficients c;
  c.ya11 = fa_i * si.y11a;
  c.xa11 = fa_i * (si.x11a - si.y11a);
  c.ya12 = fa_i * si.y12a;
  c.xa12 = fa_i * (si.x12a - si.y12a);
  c.ya22 = fa_j * sj.y11a;
  c.xa22 = fa_j * (sj.x11a - sj.y11a);
  c.yc11 = fc_i * si.y11c;
  c.xc11 = fc_i * (si.x11c - si.y11c);
  c.yc12 = fc_i * si.y12c;
  c.xc12 = fc_i * (si.x12c - si.y12c);
  c.yc22 = fc_j * sj.y11c;
  c.xc22 = fc_j * (sj.x11c - sj.y11c);
  c.b11 = fb_i * si.y11b;
  c.b12 = fb_i * si.y12b;
  c.b22 = fb_j * sj.y11b;
  c.b21 = fb_j * sj.y12b;
  return c;
}

Matrix12 pair_resistance(const PairResistanceCoefficients& c, const Vec3& n) {
  Matrix12 r;
  const Mat3 nn = n * n.transpose();
  const Mat3 id = Mat3::Identity();
  Mat3 nx;
  nx << 0.0, -n.z(), n.y(), n.z(), 0.0, -n.x(), -n.y(), n.x(), 0.0;
  r.block<3, 3>(0, 0) = c.ya11 * id + c.xa11 * nn;
  r.block<3, 3>(6, 6) = c.ya22 * id + c.xa22 * nn;
  r.block<3, 3>(0, 6) = c.ya12 * id + c.xa12 * nn;
  r.block<3, 3>(6, 0) = r.block<3, 3>(0, 6);
  r.block<3, 3>(3, 3) = c.yc11 * id + c.xc11 * nn;
  r.block<3, 3>(9, 9) = c.yc22 * id + c.xc22 * nn;
  r.block<3, 3>(3, 9) = c.yc12 * id + c.xc12 * nn;
  r.block<3, 3>(9, 3) = r.block<3, 3>(3, 9);
  r.block<3, 3>(3, 0) = -c.b11 * nx;
  r.block<3, 3>(3, 6) = -c.b12 * nx;
  r.block<3, 3>(9, 6) = c.b22 * nx;
  r.block<3, 3>(9, 0) = c.b21 * nx;
  r.block<3, 3>(0, 3) = r.block<3, 3>(3, 0).transpose();
  r.block<3, 3>(6, 3) = r.block<3, 3>(3, 6).transpose();
  r.block<3, 3>(6, 9) = r.block<3, 3>(9, 6).transpose();
  r.block<3, 3>(0, 9) = r.block<3, 3>(9, 0).transpose();
  return r;
}

Vector12 pair_resistance_product(const PairResistanceCoefficients& c, const Vec3& n, const Vector12& v) {
  // Plain scalars (no Eigen temporaries): this runs for every corrected pair in every Krylov iteration.
  // (y I + x n n) u = y u + x (n.u) n, and [n]_x u = n x u (pair_resistance's blocks).
  const double n0 = n.x(), n1 = n.y(), n2 = n.z();
  double x[12];
  for (int k = 0; k < 12; ++k) x[k] = v(k);
  const double* ui = x;
  const double* wi = x + 3;
  const double* uj = x + 6;
  const double* wj = x + 9;
  const auto dot = [&](const double* u) { return n0 * u[0] + n1 * u[1] + n2 * u[2]; };
  const double nui = dot(ui), nwi = dot(wi), nuj = dot(uj), nwj = dot(wj);
  const double cui[3] = {n1 * ui[2] - n2 * ui[1], n2 * ui[0] - n0 * ui[2], n0 * ui[1] - n1 * ui[0]};
  const double cwi[3] = {n1 * wi[2] - n2 * wi[1], n2 * wi[0] - n0 * wi[2], n0 * wi[1] - n1 * wi[0]};
  const double cuj[3] = {n1 * uj[2] - n2 * uj[1], n2 * uj[0] - n0 * uj[2], n0 * uj[1] - n1 * uj[0]};
  const double cwj[3] = {n1 * wj[2] - n2 * wj[1], n2 * wj[0] - n0 * wj[2], n0 * wj[1] - n1 * wj[0]};
  // Axial parts along n of the four outputs.
  const double af_i = c.xa11 * nui + c.xa12 * nuj, af_j = c.xa12 * nui + c.xa22 * nuj;
  const double at_i = c.xc11 * nwi + c.xc12 * nwj, at_j = c.xc12 * nwi + c.xc22 * nwj;
  const double nn[3] = {n0, n1, n2};
  Vector12 f;
  for (int k = 0; k < 3; ++k) {
    f(k) = c.ya11 * ui[k] + c.ya12 * uj[k] + af_i * nn[k] + c.b11 * cwi[k] - c.b21 * cwj[k];
    f(3 + k) = c.yc11 * wi[k] + c.yc12 * wj[k] + at_i * nn[k] - c.b11 * cui[k] - c.b12 * cuj[k];
    f(6 + k) = c.ya12 * ui[k] + c.ya22 * uj[k] + af_j * nn[k] + c.b12 * cwi[k] - c.b22 * cwj[k];
    f(9 + k) = c.yc12 * wi[k] + c.yc22 * wj[k] + at_j * nn[k] + c.b21 * cui[k] + c.b22 * cuj[k];
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
