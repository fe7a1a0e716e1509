// Small fixed-size linear algebra shared by every folder: positions, velocities, tensors.
#pragma once
#include <Eigen/Dense>

namespace suspend {
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// Symmetric part of the outer product a b^T: the shape of every pair stresslet r F^T.
inline Mat3 sym_outer(const Vec3& a, const Vec3& b) {
  Mat3 m = a * b.transpose();
  return 0.5 * (m + m.transpose());
}
}  // namespace suspend
