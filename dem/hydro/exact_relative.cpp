#include "dem/hydro/exact_relative.hpp"

#include <utility>

namespace suspend::hydro {

void exact_relative_part(double a_i, double a_j, const ResistanceScalars& exact_i, const ResistanceScalars& exact_j,
                         ResistanceScalars& lub_i, ResistanceScalars& lub_j) {
  using S = ResistanceScalars;
  // Translation along and across the line of centres: P A P = k v v^T, v = (1, -1) (force units / 6 pi eta).
  for (const auto& [f11, f12] : {std::pair{&S::x11a, &S::x12a}, std::pair{&S::y11a, &S::y12a}}) {
    const double k = 0.25 * (a_i * exact_i.*f11 + a_j * exact_j.*f11 - a_i * exact_i.*f12 - a_j * exact_j.*f12 -
                             a_i - a_j);
    lub_i.*f11 = k / a_i;
    lub_i.*f12 = -k / a_i;
    lub_j.*f11 = k / a_j;
    lub_j.*f12 = -k / a_j;
  }
  // Couplings of translation with rotation or strain: their mean over the two velocities removed, per sphere.
  for (const auto& [f11, f12] :
       {std::pair{&S::y11b, &S::y12b}, std::pair{&S::x11g, &S::x12g}, std::pair{&S::y11g, &S::y12g}}) {
    lub_i.*f11 = 0.5 * (exact_i.*f11 - exact_i.*f12);
    lub_i.*f12 = -(lub_i.*f11);
    lub_j.*f11 = 0.5 * (exact_j.*f11 - exact_j.*f12);
    lub_j.*f12 = -(lub_j.*f11);
  }
  // Rotation and rotation-strain: untouched by the projection.
  using Side = std::pair<S*, const S*>;
  for (const auto& [lub, exact] : {Side{&lub_i, &exact_i}, Side{&lub_j, &exact_j}}) {
    lub->x11c = exact->x11c - 1.0;
    lub->x12c = exact->x12c;
    lub->y11c = exact->y11c - 1.0;
    lub->y12c = exact->y12c;
    lub->y11h = exact->y11h;
    lub->y12h = exact->y12h;
  }
}

}  // namespace suspend::hydro
