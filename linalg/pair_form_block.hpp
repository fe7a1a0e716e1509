// A 6x6 block of the form that two spheres' resistance takes along their line of centres n (the compact storage of
// SymmetricBlockMatrix, CouplingStorage::pair_form). With M = [[A, B], [C, D]] (3x3 parts; force and torque rows,
// velocity and angular-velocity columns), N = [n]x (N v = n x v) and P = I - n n:
//     A = a_n n n + a_t P,   B = b N,   C = c N,   D = d_n n n + d_t P,
// which holds for every lubrication block (Kim & Karrila ch. 11: X n n + Y (I - n n) and Y^B eps.n; paper 000
// eq. A.2) and for a sticking contact's backward-Euler block dt C^T S C (dem/integrate/implicit_contacts.hpp).
// A sliding contact (S = k_n n n + k_t (I - n n - t t), t its slip direction) adds terms along t and m = n x t:
//     A += s_a t t,   B += s_b t m^T,   C += s_c m t^T,   D += s_d m m,
// kept in a SlipForm beside the block. 6 numbers and n (72 B) instead of 36 numbers (288 B); a product costs about
// as many flops as the dense one.
#pragma once
#include <Eigen/Dense>
#include <cstdint>

namespace suspend {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

struct SlipForm {
  Eigen::Vector3d t = Eigen::Vector3d::Zero();  // unit slip direction, perpendicular to n
  double a = 0.0, b = 0.0, c = 0.0, d = 0.0;    // s_a, s_b, s_c, s_d of the header
};

struct PairFormBlock {
  Eigen::Vector3d n = Eigen::Vector3d::UnitX();
  double a_n = 0.0, a_t = 0.0, b = 0.0, c = 0.0, d_n = 0.0, d_t = 0.0;
};

// M as a pair-form block along n (and, with slip, t: a unit vector perpendicular to n; the zero vector for none).
// Returns false if M is not of that form to 1e-12 of its largest entry (the block is then left unusable).
bool compress(const Matrix6& m, const Eigen::Vector3d& n, const Eigen::Vector3d& t, PairFormBlock& block,
              SlipForm& slip);
// The dense block (slip: null for none).
Matrix6 expand(const PairFormBlock& block, const SlipForm* slip);

// M x and M^T x.
inline Vector6 times(const PairFormBlock& k, const SlipForm* s, const Vector6& x) {
  const Eigen::Vector3d u = x.head<3>(), w = x.tail<3>();
  const double nu = k.n.dot(u), nw = k.n.dot(w);
  Vector6 y;
  y.head<3>() = k.a_t * u + ((k.a_n - k.a_t) * nu) * k.n + k.b * k.n.cross(w);
  y.tail<3>() = k.c * k.n.cross(u) + k.d_t * w + ((k.d_n - k.d_t) * nw) * k.n;
  if (s) {
    const Eigen::Vector3d m = k.n.cross(s->t);
    const double tu = s->t.dot(u), mw = m.dot(w);
    y.head<3>() += (s->a * tu + s->b * mw) * s->t;
    y.tail<3>() += (s->c * tu + s->d * mw) * m;
  }
  return y;
}
// M^T = [[A, C^T], [B^T, D]] with N^T = -N.
inline Vector6 transpose_times(const PairFormBlock& k, const SlipForm* s, const Vector6& x) {
  const Eigen::Vector3d u = x.head<3>(), w = x.tail<3>();
  const double nu = k.n.dot(u), nw = k.n.dot(w);
  Vector6 y;
  y.head<3>() = k.a_t * u + ((k.a_n - k.a_t) * nu) * k.n - k.c * k.n.cross(w);
  y.tail<3>() = -k.b * k.n.cross(u) + k.d_t * w + ((k.d_n - k.d_t) * nw) * k.n;
  if (s) {
    const Eigen::Vector3d m = k.n.cross(s->t);
    const double tu = s->t.dot(u), mw = m.dot(w);
    y.head<3>() += (s->a * tu + s->c * mw) * s->t;
    y.tail<3>() += (s->b * tu + s->d * mw) * m;
  }
  return y;
}

}  // namespace suspend
