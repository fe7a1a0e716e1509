// Periodic box with Lees-Edwards boundaries (paper 000, eq. 16; docs/units.md, Conventions).
// Flow x, gradient y, vorticity z. The periodic image of the cell at y + L_y is displaced by +shear_offset in x,
// where shear_offset = origin + strain * L_y wrapped into [-L_x/2, L_x/2). Only the wrapped offset matters for
// geometry, so the strain may grow without bound. The origin is the offset at strain 0: zero for a generated packing,
// the snapshot's offset for a run that starts from a sheared state.
#pragma once
#include <cmath>

#include "core/vec.hpp"

namespace suspend {

struct MinimumImage {
  Vec3 d;        // r_j(image) - r_i, the shortest separation vector
  int y_images;  // k such that the image of j used is r_j - k L_y (shifted by -k offset in x)
};

class Box {
 public:
  Box() = default;
  Box(double lx, double ly, double lz) : length_(lx, ly, lz) {}
  explicit Box(const Vec3& length) : length_(length) {}

  const Vec3& length() const { return length_; }
  double volume() const { return length_.prod(); }
  double shear_offset() const { return offset_; }

  // Sets the offset from the accumulated strain; works for any strain history (stress control, oscillation).
  void set_strain(double strain);
  // The offset at strain 0 (kept by set_strain); also sets the offset to it.
  void set_offset_origin(double offset);
  double offset_origin() const { return origin_; }
  // Sets the offset directly (wrapped into [-L_x/2, L_x/2)).
  void set_shear_offset(double offset);

  // Minimum-image separation from r_i to r_j under Lees-Edwards (paper 000, eq. 16).
  // Inline: it is the innermost operation of the neighbour search and of every pair loop.
  MinimumImage minimum_image(const Vec3& ri, const Vec3& rj) const {
    Vec3 d = rj - ri;
    const double ky = std::round(d.y() / length_.y());
    d.y() -= ky * length_.y();
    d.x() -= ky * offset_;
    d.x() -= length_.x() * std::round(d.x() / length_.x());
    d.z() -= length_.z() * std::round(d.z() / length_.z());
    return {d, static_cast<int>(ky)};
  }

  // Maps r into the primary cell [0, L)^3. Returns the number of times the y face was crossed upwards
  // (negative: downwards) so that the caller can remap the x velocity by -crossings * shear_rate * L_y (eq. 16d).
  int wrap(Vec3& r) const;

 private:
  Vec3 length_{1.0, 1.0, 1.0};
  double offset_ = 0.0;
  double origin_ = 0.0;
};

// Wraps x into [-L/2, L/2).
double wrap_centered(double x, double length);

}  // namespace suspend
