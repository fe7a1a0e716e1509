// The coupling's pair tensors against the pairwise engine's public lubrication law (dem/hydro/lubrication.hpp),
// whose conventions (Kim & Karrila section 11.3, Jeffrey & Onishi 1984) test_lubrication_pair checks against the
// exact table: block coefficients and the matrix-free product for random orientations, and the inverse map
// (scalars from a resistance matrix and stresslet responses along e_x) that the FCM pair table relies on.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"
#include "coupling/pair_tensors.hpp"
#include "dem/hydro/lubrication.hpp"

using namespace suspend;
using namespace suspend::coupling;

namespace {

hydro::LubricationParams params() {
  hydro::LubricationParams p;
  p.inner_cutoff = 1e-4;
  p.outer_cutoff = 0.5;
  return p;
}

Vec3 unit(double x, double y, double z) { return Vec3(x, y, z).normalized(); }

}  // namespace

TEST(CouplingPairTensors, BlockCoefficientsGiveThePairwiseLubricationLaw) {
  for (double lambda : {1.0, 1.4, 0.3}) {
    const hydro::PairLubrication law(1.0, lambda, params());
    for (const Vec3& n : {unit(1, 0, 0), unit(0.3, -0.8, 0.52), unit(-0.1, 0.2, -0.97)}) {
      const double gap = 0.03;
      hydro::ResistanceScalars si, sj;
      law.scalars(gap, si, sj);
      const Matrix12 theirs = law.resistance(n, gap);
      // The 16 block coefficients and the matrix-free product equal the assembled matrix (times a vector).
      Vector12 v;
      v << 0.3, -1.2, 0.7, 0.25, 0.9, -0.4, -0.6, 0.1, 1.1, -0.8, 0.35, 0.5;
      const Vector12 rv = theirs * v;
      const PairResistanceCoefficients c = pair_resistance_coefficients(1.0, lambda, si, sj);
      EXPECT_LT((pair_resistance(c, n) - theirs).norm(), 1e-12 * theirs.norm()) << lambda;
      EXPECT_LT((pair_resistance_product(c, n, v) - rv).norm(), 1e-12 * rv.norm()) << lambda;
    }
  }
}

TEST(CouplingPairTensors, ScalarsAlongXInvertTheAssembly) {
  for (double lambda : {1.0, 2.0, 0.5}) {
    const hydro::PairLubrication law(1.0, lambda, params());
    const double gap = 0.02;
    hydro::ResistanceScalars si, sj;
    law.scalars(gap, si, sj);
    const Vec3 n(1.0, 0.0, 0.0);
    const Matrix12 r = law.resistance(n, gap);
    // Stresslet responses to unit disturbance velocities (no strain): S_a = -G^{ab} dV_b.
    std::array<std::array<Mat3, 12>, 2> s;
    for (int c = 0; c < 12; ++c) {
      hydro::PairMotion m;
      Vector12 v = Vector12::Zero();
      v(c) = 1.0;
      m.du_i = v.segment<3>(0);
      m.dw_i = v.segment<3>(3);
      m.du_j = v.segment<3>(6);
      m.dw_j = v.segment<3>(9);
      const hydro::PairHydroForce f = law.evaluate(n, gap, m);
      s[0][c] = f.stresslet_i;
      s[1][c] = f.stresslet_j;
    }
    hydro::ResistanceScalars gi, gj;
    scalars_along_x(1.0, lambda, r, s, gi, gj);
    for (std::size_t k = 0; k < correction_functions.size(); ++k) {
      const auto f = correction_functions[k];
      EXPECT_NEAR(gi.*f, si.*f, 1e-10 * (1.0 + std::abs(si.*f))) << correction_function_names[k] << " from i, " << lambda;
      EXPECT_NEAR(gj.*f, sj.*f, 1e-10 * (1.0 + std::abs(sj.*f))) << correction_function_names[k] << " from j, " << lambda;
    }
  }
}
