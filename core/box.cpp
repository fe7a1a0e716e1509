#include "core/box.hpp"

#include <cmath>

namespace suspend {

double wrap_centered(double x, double length) {
  double w = x - length * std::floor(x / length + 0.5);
  if (w >= 0.5 * length) w -= length;  // round-off guard
  if (w < -0.5 * length) w += length;
  return w;
}

void Box::set_strain(double strain) { set_shear_offset(origin_ + strain * length_.y()); }

void Box::set_offset_origin(double offset) {
  origin_ = wrap_centered(offset, length_.x());
  offset_ = origin_;
}

void Box::set_shear_offset(double offset) { offset_ = wrap_centered(offset, length_.x()); }

int Box::wrap(Vec3& r) const {
  const double ky = std::floor(r.y() / length_.y());
  r.y() -= ky * length_.y();
  r.x() -= ky * offset_;
  r.x() -= length_.x() * std::floor(r.x() / length_.x());
  r.z() -= length_.z() * std::floor(r.z() / length_.z());
  // floor can leave r == L after round-off; fold it back so 0 <= r < L always holds.
  for (int a = 0; a < 3; ++a)
    if (r[a] >= length_[a]) r[a] -= length_[a];
  return static_cast<int>(ky);
}

}  // namespace suspend
