#include "linalg/pair_form_block.hpp"

#include <cmath>

namespace suspend {

namespace {
Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& n) {
  Eigen::Matrix3d x;
  x << 0.0, -n.z(), n.y(), n.z(), 0.0, -n.x(), -n.y(), n.x(), 0.0;
  return x;
}
}  // namespace

bool compress(const Matrix6& m, const Eigen::Vector3d& n, const Eigen::Vector3d& t, PairFormBlock& k,
              SlipForm& slip) {
  const bool slips = t.squaredNorm() > 0.0;
  // An orthonormal frame (n, e, f = n x e); with slip e = t.
  Eigen::Vector3d e = t;
  if (!slips) {
    const Eigen::Vector3d axis = std::abs(n.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    e = (axis - axis.dot(n) * n).normalized();
  }
  const Eigen::Vector3d f = n.cross(e);
  const Eigen::Matrix3d a = m.block<3, 3>(0, 0), b = m.block<3, 3>(0, 3), c = m.block<3, 3>(3, 0),
                        d = m.block<3, 3>(3, 3);
  k.n = n;
  k.a_n = n.dot(a * n);
  k.d_n = n.dot(d * n);
  // f^T N e = f.(n x e) = 1 and e^T N f = -1; the slip terms t m^T and m t^T add to one of the two each.
  if (slips) {
    k.a_t = f.dot(a * f);
    k.d_t = e.dot(d * e);
    k.b = f.dot(b * e);
    k.c = -e.dot(c * f);
    slip.t = t;
    slip.a = e.dot(a * e) - k.a_t;
    slip.b = e.dot(b * f) + k.b;
    slip.c = f.dot(c * e) - k.c;
    slip.d = f.dot(d * f) - k.d_t;
  } else {
    k.a_t = 0.5 * (e.dot(a * e) + f.dot(a * f));
    k.d_t = 0.5 * (e.dot(d * e) + f.dot(d * f));
    k.b = 0.5 * (f.dot(b * e) - e.dot(b * f));
    k.c = 0.5 * (f.dot(c * e) - e.dot(c * f));
    slip = SlipForm{};
  }
  const Matrix6 back = expand(k, slips ? &slip : nullptr);
  return (m - back).cwiseAbs().maxCoeff() <= 1e-12 * m.cwiseAbs().maxCoeff();
}

Matrix6 expand(const PairFormBlock& k, const SlipForm* s) {
  const Eigen::Matrix3d nn = k.n * k.n.transpose(), p = Eigen::Matrix3d::Identity() - nn, x = cross_matrix(k.n);
  Matrix6 m;
  m.block<3, 3>(0, 0) = k.a_n * nn + k.a_t * p;
  m.block<3, 3>(0, 3) = k.b * x;
  m.block<3, 3>(3, 0) = k.c * x;
  m.block<3, 3>(3, 3) = k.d_n * nn + k.d_t * p;
  if (s) {
    const Eigen::Vector3d mm = k.n.cross(s->t);
    m.block<3, 3>(0, 0) += s->a * s->t * s->t.transpose();
    m.block<3, 3>(0, 3) += s->b * s->t * mm.transpose();
    m.block<3, 3>(3, 0) += s->c * mm * s->t.transpose();
    m.block<3, 3>(3, 3) += s->d * mm * mm.transpose();
  }
  return m;
}

}  // namespace suspend
