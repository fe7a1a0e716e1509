// The pairwise option `lubrication.functions: exact_relative` against the exact two-sphere table
// (tests/data/two_sphere_resistance_table.txt, lambda = 1): with Stokes drag added, the relative-motion
// combinations of A, B, G (X11A - X12A, ...) and the C, H functions equal the exact ones; rigid translation of the
// pair stays force-free; the pair (with drag) stays positive definite; unequal spheres are refused.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "dem/hydro/lubrication.hpp"

using namespace suspend;
using namespace suspend::hydro;

namespace {

LubricationParams exact_params() {
  LubricationParams p;
  p.inner_cutoff = 1e-6;
  p.outer_cutoff = 0.5;
  p.exact_relative = true;
  return p;
}

// Exact table at lambda = 1: s' -> {"11" row, "12" row}, columns XA YA YB XC YC XG YG YH.
std::map<double, std::array<std::array<double, 8>, 2>> exact_table() {
  std::ifstream in(SUSPEND_SOURCE_DIR "/tests/data/two_sphere_resistance_table.txt");
  std::map<double, std::array<std::array<double, 8>, 2>> t;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    double sp, lam, gam;
    std::array<double, 8> v{};
    if (!(s >> sp >> lam >> gam)) continue;
    bool ok = true;
    for (double& x : v) ok = ok && static_cast<bool>(s >> x);
    if (ok && lam == 1.0) t[sp][gam < 0.5 ? 0 : 1] = v;
  }
  return t;
}

}  // namespace

TEST(LubricationExactRelative, RelativeMotionAndRotationFunctionsAreExact) {
  const PairLubrication law(1.0, 1.0, exact_params());
  const auto table = exact_table();
  int checked = 0;
  for (const auto& [sp, rows] : table) {
    const double xi = sp - 2.0;
    if (xi < 0.005 || xi > 0.25) continue;
    ResistanceScalars si, sj;
    law.scalars(xi, si, sj);  // gap h = xi (a_1 + a_2)/2 = xi
    add_stokes_drag(si);
    const auto& e11 = rows[0];
    const auto& e12 = rows[1];
    const auto near = [](double got, double want) { EXPECT_NEAR(got, want, 1e-6 * (1.0 + std::abs(want))); };
    near(si.x11a - si.x12a, e11[0] - e12[0]);
    near(si.y11a - si.y12a, e11[1] - e12[1]);
    near(si.y11b - si.y12b, e11[2] - e12[2]);
    near(si.x11g - si.x12g, e11[5] - e12[5]);
    near(si.y11g - si.y12g, e11[6] - e12[6]);
    near(si.x11c, e11[3]);
    near(si.x12c, e12[3]);
    near(si.y11c, e11[4]);
    near(si.y12c, e12[4]);
    near(si.y11h, e11[7]);
    near(si.y12h, e12[7]);
    // Rigid translation costs nothing, as in the singular model.
    EXPECT_NEAR(si.x11a - 1.0 + si.x12a, 0.0, 1e-12 * si.x11a);
    EXPECT_NEAR(si.y11a - 1.0 + si.y12a, 0.0, 1e-12);
    EXPECT_NEAR(sj.x11a, si.x11a - 1.0, 1e-12 * si.x11a);
    ++checked;
  }
  EXPECT_GE(checked, 5);  // table nodes at xi = 0.005 ... 0.25
}

TEST(LubricationExactRelative, PairWithDragIsPositiveDefiniteAndTranslationFree) {
  const PairLubrication law(1.0, 1.0, exact_params());
  const Vec3 n = Vec3(1.0, 2.0, -0.5).normalized();
  for (double gap : {1e-4, 1e-3, 1e-2, 0.05, 0.1, 0.3}) {
    Matrix12 r = law.resistance(n, gap);
    Vector12 t;
    t << Vec3(0.3, -1.0, 0.7), Vec3::Zero(), Vec3(0.3, -1.0, 0.7), Vec3::Zero();
    EXPECT_LT((r * t).cwiseAbs().maxCoeff(), 1e-12 * r.cwiseAbs().maxCoeff()) << gap;
    for (int k : {0, 1, 2, 6, 7, 8}) r(k, k) += 6.0 * std::numbers::pi;
    for (int k : {3, 4, 5, 9, 10, 11}) r(k, k) += 8.0 * std::numbers::pi;
    const Eigen::SelfAdjointEigenSolver<Matrix12> eig(r);
    EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0) << gap;
  }
}

TEST(LubricationExactRelative, UnequalSpheresAreRefused) {
  try {
    const PairLubrication law(1.0, 1.4, exact_params());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("exact_relative"), std::string::npos);
  }
}
