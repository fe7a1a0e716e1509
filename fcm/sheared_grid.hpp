// The FCM grid on the Lees-Edwards lattice (docs/fcm.md, "Lees-Edwards").
// With offset D (wrapped into [-L_x/2, L_x/2)) the disturbance flow is periodic under (L_x, 0, 0), (D, L_y, 0) and
// (0, 0, L_z). In sheared coordinates x' = x - gamma_t y, gamma_t = D / L_y, it is periodic on a regular box, so
// it lives on a regular grid: node (i, j, k) sits at x' = i h_x, y = j h_y, z = k h_z, i.e. at the physical point
// (i h_x + gamma_t j h_y, j h_y, k h_z). The map has unit Jacobian, so a node carries volume h_x h_y h_z.
// Derivatives: d/dx = d/dx', d/dy = d/dy - gamma_t d/dx', so the physical wavevector of sheared-lattice mode
// (k1, k2, k3) is k = (k1, k2 - gamma_t k1, k3).
#pragma once
#include <array>
#include <cstddef>

#include "core/vec.hpp"

namespace suspend::fcm {

struct ShearedGrid {
  std::array<int, 3> n{};  // nodes per direction (x', y, z)
  Vec3 length = Vec3::Ones();
  Vec3 spacing = Vec3::Ones();
  double shear_fraction = 0.0;  // gamma_t = D / L_y with D in [-L_x/2, L_x/2)

  double cell_volume() const { return spacing.prod(); }
  std::size_t index(int ix, int iy, int iz) const {
    return (static_cast<std::size_t>(iz) * n[1] + iy) * n[0] + ix;
  }
};

// i mod n in [0, n) for any integer i.
inline int periodic_index(int i, int n) {
  const int r = i % n;
  return r < 0 ? r + n : r;
}

}  // namespace suspend::fcm
