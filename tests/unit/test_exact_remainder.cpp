// The exact two-sphere functions of the unequal pair lambda = a2/a1 = 1.4 (paper 004's bidisperse suspension),
// as the code builds them (Stokes drag + singular terms + the tabulated remainder of dem/hydro/exact_remainder.hpp),
// against the outside values of tests/data/two_sphere_resistance_table_lambda1.4.txt (Townsend's Stokesian-dynamics
// generator: corrected Jeffrey & Onishi near contact, Lamb's method beyond; docs/references.md):
//  * on the table's nodes, both orderings (lambda = 1.4 seen from the small sphere, 1/1.4 from the large one);
//  * between nodes: each node left out of the table in turn and the interpolant at its gap compared with it: the
//    interpolation error at twice the shipped spacing, within 2% for xi = 1e-4 ... 0.1 (worst: the small functions
//    X12C, Y11G at xi = 0.1 and 0.02-0.025, where the table joins its two methods). Linear interpolation's error
//    scales with the square of the spacing, so at the shipped spacing it is about a quarter of that;
//  * below the table: the near-contact form X11A = 0.283565/xi + 0.258449 ln(1/xi) + 0.91108 of the reference README;
//  * reciprocity of the pair functions seen from either sphere (6 pi a1 X12A(lambda) = 6 pi a2 X12A(1/lambda), ...).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <vector>

#include "dem/hydro/exact_remainder.hpp"
#include "tests/two_sphere_table.hpp"

using namespace suspend::hydro;

namespace {

// Rows of the reference file for one lambda, in the layout of ExactRemainder::Row.
std::vector<ExactRemainder::Row> reference_rows(double lambda) {
  std::vector<ExactRemainder::Row> out;
  for (const auto& [sp, f] : suspend::test::lambda_1_4_table(lambda)) {
    ExactRemainder::Row r{};
    r[0] = sp;
    std::copy(f[0].begin(), f[0].begin() + 8, r.begin() + 1);
    std::copy(f[1].begin(), f[1].begin() + 8, r.begin() + 9);
    std::copy(f[0].begin() + 8, f[0].end(), r.begin() + 17);
    std::copy(f[1].begin() + 8, f[1].end(), r.begin() + 20);
    out.push_back(r);
  }
  return out;
}

// Table column order of the sixteen functions (s' first).
constexpr std::array<double ResistanceScalars::*, 16> column{
    &ResistanceScalars::x11a, &ResistanceScalars::y11a, &ResistanceScalars::y11b, &ResistanceScalars::x11c,
    &ResistanceScalars::y11c, &ResistanceScalars::x11g, &ResistanceScalars::y11g, &ResistanceScalars::y11h,
    &ResistanceScalars::x12a, &ResistanceScalars::y12a, &ResistanceScalars::y12b, &ResistanceScalars::x12c,
    &ResistanceScalars::y12c, &ResistanceScalars::x12g, &ResistanceScalars::y12g, &ResistanceScalars::y12h};
constexpr std::array<const char*, 16> name{"X11A", "Y11A", "Y11B", "X11C", "Y11C", "X11G", "Y11G", "Y11H",
                                           "X12A", "Y12A", "Y12B", "X12C", "Y12C", "X12G", "Y12G", "Y12H"};

ResistanceScalars exact(const ExactRemainder& table, double lambda, double xi) {
  ResistanceScalars s = lubrication_scalars(LubricationCoefficients::for_ratio(lambda), xi);
  add_stokes_drag(s);
  table.add_to(xi, s);
  return s;
}

}  // namespace

TEST(ExactRemainder, ShippedRatiosAreFoundAndOthersAreNot) {
  for (double lambda : {1.0, 1.4, 1.0 / 1.4}) {
    ASSERT_NE(ExactRemainder::for_ratio(lambda), nullptr) << lambda;
    EXPECT_DOUBLE_EQ(ExactRemainder::for_ratio(lambda)->lambda(), lambda);
  }
  EXPECT_EQ(ExactRemainder::for_ratio(1.5), nullptr);
  EXPECT_EQ(ExactRemainder::for_ratio(2.0), nullptr);
  EXPECT_EQ(ExactRemainder::for_ratio(1.4 * (1 + 1e-6)), nullptr);
}

TEST(ExactRemainder, UnequalPairEqualsTheReferenceTableOnItsNodes) {
  for (double lambda : {1.4, 1.0 / 1.4}) {
    const auto rows = reference_rows(lambda);
    ASSERT_EQ(rows.size(), 41u) << lambda;
    const ExactRemainder& table = *ExactRemainder::for_ratio(lambda);
    for (const auto& row : rows) {
      const ResistanceScalars s = exact(table, lambda, row[0] - 2.0);
      for (std::size_t k = 0; k < 16; ++k)
        EXPECT_NEAR(s.*column[k], row[k + 1], 1e-7 * (1.0 + std::abs(row[k + 1])))
            << "lambda " << lambda << " s' " << row[0] << " " << name[k];
    }
  }
}

// The stresslet functions (M) of exact_with_stresslet on the table's nodes, both unequal orderings and equal spheres;
// exact() leaves them the model's (singular terms + drag).
TEST(ExactRemainder, StressletFunctionsEqualTheReferenceTableOnItsNodes) {
  constexpr std::array<double ResistanceScalars::*, 6> m{&ResistanceScalars::x11m, &ResistanceScalars::y11m,
                                                         &ResistanceScalars::z11m, &ResistanceScalars::x12m,
                                                         &ResistanceScalars::y12m, &ResistanceScalars::z12m};
  for (double lambda : {1.0, 1.4, 1.0 / 1.4}) {
    const auto table = lambda == 1.0 ? suspend::test::read_two_sphere_table("two_sphere_resistance_table.txt", 1.0)
                                     : suspend::test::lambda_1_4_table(lambda);
    const ExactRemainder& exact_table = *ExactRemainder::for_ratio(lambda);
    int nodes = 0;
    for (const auto& [sp, f] : table) {
      if (sp > 4.5 * (1 + 1e-12)) continue;
      const double xi = sp - 2.0;
      const ResistanceScalars s = exact_table.exact_with_stresslet(xi, std::log(1.0 / xi));
      const ResistanceScalars model = exact_table.exact(xi, std::log(1.0 / xi));
      bool node = false;
      for (std::size_t k = 0; k < 6; ++k) {
        const double want = f[k < 3 ? 0 : 1][8 + k % 3];
        if (std::abs(s.*m[k] - want) <= 1e-7 * (1.0 + std::abs(want))) node = true;
      }
      if (!node) continue;  // a gap of the reference file that the shipped table does not hold
      ++nodes;
      for (std::size_t k = 0; k < 6; ++k) {
        const double want = f[k < 3 ? 0 : 1][8 + k % 3];
        EXPECT_NEAR(s.*m[k], want, 1e-7 * (1.0 + std::abs(want))) << "lambda " << lambda << " s' " << sp << " " << k;
      }
      EXPECT_EQ(model.z11m, 1.0);
      EXPECT_EQ(model.z12m, 0.0);
    }
    EXPECT_EQ(nodes, lambda == 1.0 ? 38 : 41) << lambda;  // every row of the shipped table
  }
}

TEST(ExactRemainder, InterpolationAtTwiceTheSpacingIsWithinTwoPercent) {
  // Leave-one-out: the interpolant over the other nodes at a node's gap, against that node.
  for (double lambda : {1.4, 1.0 / 1.4}) {
    const auto rows = reference_rows(lambda);
    double worst = 0.0;
    for (std::size_t k = 1; k + 1 < rows.size(); ++k) {
      const double xi = rows[k][0] - 2.0;
      if (xi < 1e-4 * (1 - 1e-9) || xi > 0.1 * (1 + 1e-9)) continue;
      std::vector<ExactRemainder::Row> others(rows.begin(), rows.end());
      others.erase(others.begin() + static_cast<long>(k));
      const ExactRemainder sparse(lambda, others);
      const ResistanceScalars s = exact(sparse, lambda, xi);
      for (std::size_t f = 0; f < 16; ++f) {
        // Relative to the function, or to 0.2 (isolated-sphere units) for the functions that pass near zero.
        const double err = std::abs(s.*column[f] - rows[k][f + 1]) / std::max(std::abs(rows[k][f + 1]), 0.2);
        worst = std::max(worst, err);
        EXPECT_LT(err, 2e-2) << "lambda " << lambda << " xi " << xi << " " << name[f];
      }
    }
    std::cout << "lambda " << lambda << ": worst leave-one-out error for xi = 1e-4 ... 0.1: " << worst << "\n";
  }
}

TEST(ExactRemainder, NearContactFormBelowTheTable) {
  const double xi = 1e-7, l = std::log(1.0 / xi);
  const ResistanceScalars s = exact(*ExactRemainder::for_ratio(1.4), 1.4, xi);
  const double g1 = 2.0 * 1.4 * 1.4 / std::pow(2.4, 3);  // 0.283565 in the README: 2 lambda^2/(1 + lambda)^3
  EXPECT_NEAR(s.x11a - g1 / xi, 0.258449 * l + 0.91108, 1e-3);
}

TEST(ExactRemainder, PairFunctionsAreReciprocalFromEitherSphere) {
  // 1 = small sphere (a1 = 1), 2 = large (a2 = 1.4): R_12 = R_21 for every pair block, at gaps on and off nodes.
  const double l = 1.4;
  for (double xi : {3e-5, 1e-3, 0.0137, 0.07, 0.3}) {
    const ResistanceScalars s1 = exact(*ExactRemainder::for_ratio(l), l, xi);
    const ResistanceScalars s2 = exact(*ExactRemainder::for_ratio(1 / l), 1 / l, xi);
    EXPECT_NEAR(s1.x12a, l * s2.x12a, 1e-6 * std::abs(s1.x12a)) << xi;
    EXPECT_NEAR(s1.y12a, l * s2.y12a, 1e-6) << xi;
    EXPECT_NEAR(s1.x12c, l * l * l * s2.x12c, 1e-6) << xi;
    EXPECT_NEAR(s1.y12c, l * l * l * s2.y12c, 1e-6) << xi;
  }
}
