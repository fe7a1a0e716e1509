// The exact near-contact functions of the sub-grid correction against outside values: the tabulated exact
// functions (tests/data/two_sphere_resistance_table.txt, Townsend / Jeffrey & Onishi) at gaps between and on the
// table's nodes, and below the table the near-contact asymptotes of docs/references.md
// (X11A = 1/(4 xi) + (9/40) ln(1/xi) + 0.99542, Y11A = (1/6) ln(1/xi) + 0.99832, Y11B = -(1/4) ln(1/xi) + 0.23892,
// Y11C = (1/5) ln(1/xi) + 0.70283, X11G = 3/(8 xi) + (27/80) ln(1/xi) - 0.46921, Y11G = (1/8) ln(1/xi) - 0.14116,
// Y11H = (1/40) ln(1/xi) - 0.07401).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "coupling/exact_pair_resistance.hpp"
#include "tests/two_sphere_table.hpp"

using namespace suspend;

TEST(CouplingExactPair, EqualSpheresFollowTheJeffreyOnishiAsymptotesBelowTheTable) {
  hydro::LubricationParams lp;
  lp.inner_cutoff = 1e-9;
  const coupling::ExactPairResistance exact(1.0, 1.0, lp);
  ASSERT_TRUE(exact.tabulated());
  const double xi = 2e-6, l = std::log(1.0 / xi);
  hydro::ResistanceScalars si, sj;
  exact.scalars(xi, si, sj);  // gap h = xi (a1 + a2)/2 = xi
  EXPECT_NEAR(si.x11a, 1.0 / (4 * xi) + 0.225 * l + 0.99542, 2e-3);
  EXPECT_NEAR(si.y11a, l / 6 + 0.99832, 2e-3);
  EXPECT_NEAR(si.y11b, -l / 4 + 0.23892, 2e-3);
  EXPECT_NEAR(si.y11c, l / 5 + 0.70283, 2e-3);
  EXPECT_NEAR(si.x11g, 3.0 / (8 * xi) + 27.0 / 80 * l - 0.46921, 2e-3);
  EXPECT_NEAR(si.y11g, l / 8 - 0.14116, 2e-3);
  EXPECT_NEAR(si.y11h, l / 40 - 0.07401, 2e-3);
}

TEST(CouplingExactPair, EqualSpheresReproduceTheExactTableOnItsNodes) {
  hydro::LubricationParams lp;
  lp.inner_cutoff = 1e-9;
  const coupling::ExactPairResistance exact(1.0, 1.0, lp);
  std::ifstream in(SUSPEND_SOURCE_DIR "/tests/data/two_sphere_resistance_table.txt");
  ASSERT_TRUE(in);
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  int checked = 0;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    double sp, lam, gam, xa, ya, yb, xc, yc, xg, yg, yh;
    if (!(s >> sp >> lam >> gam >> xa >> ya >> yb >> xc >> yc >> xg >> yg >> yh)) continue;
    if (lam != 1.0 || sp > 3.5) continue;
    hydro::ResistanceScalars si, sj;
    exact.scalars(sp - 2.0, si, sj);
    const bool self = gam < 0.5;
    const double got[8] = {self ? si.x11a : si.x12a, self ? si.y11a : si.y12a, self ? si.y11b : si.y12b,
                           self ? si.x11c : si.x12c, self ? si.y11c : si.y12c, self ? si.x11g : si.x12g,
                           self ? si.y11g : si.y12g, self ? si.y11h : si.y12h};
    const double want[8] = {xa, ya, yb, xc, yc, xg, yg, yh};
    for (int k = 0; k < 8; ++k) EXPECT_NEAR(got[k], want[k], 1e-6 * (1.0 + std::abs(want[k]))) << sp << " " << k;
    ++checked;
  }
  EXPECT_GT(checked, 40);
}

TEST(CouplingExactPair, UnequalSpheresReproduceTheLambda14TableFromBothSides) {
  // tests/data/two_sphere_resistance_table_lambda1.4.txt: rows for lambda = 1.4 (seen from the small sphere) and
  // 1/1.4 (from the large one, in its units). Spheres in both orders: the "from i" functions are the rows of a_j/a_i.
  hydro::LubricationParams lp;
  lp.inner_cutoff = 1e-9;
  int checked = 0;
  for (const auto& [a_i, a_j] : {std::pair{1.0, 1.4}, std::pair{1.4, 1.0}}) {
    const coupling::ExactPairResistance exact(a_i, a_j, lp);
    ASSERT_TRUE(exact.tabulated());
    for (const bool from_i : {true, false}) {
      // The rows seen from i are those of a_j/a_i; from j, those of a_i/a_j.
      const auto table = test::lambda_1_4_table(from_i ? a_j / a_i : a_i / a_j);
      for (const auto& [sp, rows] : table) {
        if (sp > 3.5) continue;
        hydro::ResistanceScalars si, sj;
        exact.scalars((sp - 2.0) * 0.5 * (a_i + a_j), si, sj);
        const hydro::ResistanceScalars& f = from_i ? si : sj;
        for (const bool self : {true, false}) {
          const double got[8] = {self ? f.x11a : f.x12a, self ? f.y11a : f.y12a, self ? f.y11b : f.y12b,
                                 self ? f.x11c : f.x12c, self ? f.y11c : f.y12c, self ? f.x11g : f.x12g,
                                 self ? f.y11g : f.y12g, self ? f.y11h : f.y12h};
          const auto& v = rows[self ? 0 : 1];
          for (int k = 0; k < 8; ++k) EXPECT_NEAR(got[k], v[k], 1e-6 * (1.0 + std::abs(v[k]))) << sp << " " << k;
          ++checked;
        }
      }
    }
  }
  EXPECT_EQ(checked, 2 * 2 * 2 * 31);  // orders x perspectives x (11, 12) x the 31 gaps up to s' = 3.5
}

TEST(CouplingExactPair, OtherRatiosKeepTheSingularModel) {
  hydro::LubricationParams lp;
  lp.inner_cutoff = 1e-9;
  EXPECT_FALSE(coupling::ExactPairResistance(1.0, 2.0, lp).tabulated());
}
