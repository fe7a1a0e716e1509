// Lees-Edwards geometry (paper 000, eq. 16): minimum image, wrapping and velocity remap across the y faces.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/box.hpp"

using namespace suspend;

TEST(Box, OffsetIsStrainTimesHeightWrappedIntoHalfOpenInterval) {
  Box box(10.0, 8.0, 6.0);
  box.set_strain(0.5);
  EXPECT_DOUBLE_EQ(box.shear_offset(), 4.0);
  box.set_strain(1.0);  // 8 -> wrapped to -2
  EXPECT_DOUBLE_EQ(box.shear_offset(), -2.0);
  box.set_strain(0.625);  // exactly L_x / 2 maps to -L_x / 2
  EXPECT_DOUBLE_EQ(box.shear_offset(), -5.0);
  box.set_strain(1e6 + 0.25);  // long runs: only the wrapped value matters
  EXPECT_NEAR(box.shear_offset(), std::remainder(8e6 + 2.0, 10.0), 1e-6);
}

TEST(Box, MinimumImageAcrossTheShearedFace) {
  Box box(10.0, 10.0, 10.0);
  box.set_shear_offset(3.0);
  // j sits just below the top face, i just above the bottom one: the nearest image of j is one period down,
  // displaced by -offset in x.
  const Vec3 ri(5.0, 0.2, 5.0), rj(8.0, 9.9, 5.0);
  const MinimumImage m = box.minimum_image(ri, rj);
  EXPECT_EQ(m.y_images, 1);
  EXPECT_NEAR(m.d.x(), 0.0, 1e-12);
  EXPECT_NEAR(m.d.y(), -0.3, 1e-12);
  EXPECT_NEAR(m.d.z(), 0.0, 1e-12);
  // Antisymmetry: seen from j, the image of i is the mirror vector.
  const MinimumImage back = box.minimum_image(rj, ri);
  EXPECT_EQ(back.y_images, -1);
  EXPECT_NEAR((back.d + m.d).norm(), 0.0, 1e-12);
}

TEST(Box, MinimumImageIsTheShortestOverExplicitImages) {
  Box box(7.0, 9.0, 8.0);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    box.set_shear_offset((u(rng) - 0.5) * 7.0);
    const Vec3 ri(7.0 * u(rng), 9.0 * u(rng), 8.0 * u(rng));
    const Vec3 rj(7.0 * u(rng), 9.0 * u(rng), 8.0 * u(rng));
    double best = 1e300;
    for (int ky = -2; ky <= 2; ++ky)
      for (int kx = -2; kx <= 2; ++kx)
        for (int kz = -2; kz <= 2; ++kz) {
          const Vec3 img = rj + Vec3(kx * 7.0 + ky * box.shear_offset(), ky * 9.0, kz * 8.0);
          best = std::min(best, (img - ri).norm());
        }
    // Lees-Edwards minimum image picks the nearest y layer first; it is exact whenever the pair is within L/2.
    const double d = box.minimum_image(ri, rj).d.norm();
    if (best < 3.4) {
      EXPECT_NEAR(d, best, 1e-12);
    }
  }
}

TEST(Box, WrapRemapsPositionAndReportsCrossings) {
  Box box(10.0, 10.0, 10.0);
  box.set_shear_offset(2.5);
  Vec3 r(1.0, 10.5, 3.0);  // left through the top face
  EXPECT_EQ(box.wrap(r), 1);
  EXPECT_NEAR(r.x(), 8.5, 1e-12);  // (1 - 2.5) mod 10, eq. 16a
  EXPECT_NEAR(r.y(), 0.5, 1e-12);
  Vec3 s(9.0, -0.5, -1.0);  // left through the bottom face
  EXPECT_EQ(box.wrap(s), -1);
  EXPECT_NEAR(s.x(), 1.5, 1e-12);  // (9 + 2.5) mod 10
  EXPECT_NEAR(s.y(), 9.5, 1e-12);
  EXPECT_NEAR(s.z(), 9.0, 1e-12);
}

TEST(Box, WrappedParticleKeepsItsNeighbourDistances) {
  // Remapping across the y face must not change any minimum-image distance (the physics is invariant).
  Box box(10.0, 10.0, 10.0);
  box.set_shear_offset(-4.2);
  const Vec3 other(3.0, 0.4, 5.0);
  Vec3 r(4.0, 10.3, 5.5);
  const double before = box.minimum_image(other, r).d.norm();
  box.wrap(r);
  EXPECT_NEAR(box.minimum_image(other, r).d.norm(), before, 1e-12);
}
