// Two-sphere resistance functions of the model against the exact values of Jeffrey & Onishi (1984) / Jeffrey (1992)
// as tabulated by Townsend (tests/data/two_sphere_resistance_table.txt, see docs/references.md).
#include <gtest/gtest.h>

#include <iostream>

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>

#include "core/error.hpp"
#include "dem/hydro/resistance_functions.hpp"

using namespace suspend;
using namespace suspend::hydro;

namespace {

// Table columns after (s', lambda, gamma): XA YA YB XC YC XG YG YH XM YM ZM.
enum Column { XA, YA, YB, XC, YC, XG, YG, YH, XM, YM, ZM, n_columns };
using Row = std::array<double, n_columns>;

class Table {
 public:
  Table() {
    std::ifstream in(SUSPEND_SOURCE_DIR "/tests/data/two_sphere_resistance_table.txt");
    if (!in) throw std::runtime_error("cannot open two_sphere_resistance_table.txt");
    std::string line;
    std::getline(in, line);
    std::getline(in, line);
    while (std::getline(in, line)) {
      std::istringstream ls(line);
      double s, lam, gam;
      Row r;
      if (!(ls >> s >> lam >> gam)) continue;
      for (double& v : r) ls >> v;
      rows_[key(s - 2.0, lam, static_cast<int>(gam))] = r;
    }
  }
  // gamma 0: the "11" functions, 1: the "12" functions.
  double at(double xi, double lambda, int gamma, Column c) const {
    const auto it = rows_.find(key(xi, lambda, gamma));
    if (it == rows_.end()) throw std::runtime_error("no table row for xi = " + std::to_string(xi));
    return it->second[c];
  }

 private:
  using Key = std::tuple<long long, long long, int>;
  static Key key(double xi, double lambda, int gamma) {
    return {std::llround(xi * 1e8), std::llround(lambda * 1e4), gamma};
  }
  std::map<Key, Row> rows_;
};

const Table& table() {
  static const Table t;
  return t;
}

// Model value of the function in column c ("11" if gamma == 0 else "12") at lambda = a2/a1 and scaled gap xi.
double model(double xi, double lambda, int gamma, Column c) {
  const ResistanceScalars s = two_sphere_resistance(1.0, lambda, xi * (1.0 + lambda) / 2.0);
  const bool self = gamma == 0;
  switch (c) {
    case XA: return self ? s.x11a : s.x12a;
    case YA: return self ? s.y11a : s.y12a;
    case YB: return self ? s.y11b : s.y12b;
    case XC: return self ? s.x11c : s.x12c;
    case YC: return self ? s.y11c : s.y12c;
    case XG: return self ? s.x11g : s.x12g;
    case YG: return self ? s.y11g : s.y12g;
    case YH: return self ? s.y11h : s.y12h;
    case XM: return self ? s.x11m : s.x12m;
    case YM: return self ? s.y11m : s.y12m;
    default: return 0.0;
  }
}

constexpr std::array<Column, 9> singular_columns = {XA, YA, YB, YC, XG, YG, YH, XM, YM};
constexpr std::array<const char*, n_columns> names = {"XA", "YA", "YB", "XC", "YC", "XG", "YG", "YH", "XM", "YM", "ZM"};
constexpr std::array<double, 3> ratios = {0.1, 1.0, 10.0};

// The change of a function between two gaps isolates its singular part: the O(1) remainder cancels.
void expect_singular_part_exact(double xi_far, double xi_near, double rel_tol) {
  for (double lambda : ratios)
    for (int gamma : {0, 1})
      for (Column c : singular_columns) {
        const double exact = table().at(xi_near, lambda, gamma, c) - table().at(xi_far, lambda, gamma, c);
        const double ours = model(xi_near, lambda, gamma, c) - model(xi_far, lambda, gamma, c);
        EXPECT_NEAR(ours, exact, rel_tol * std::abs(exact))
            << names[c] << (gamma ? "12" : "11") << " lambda = " << lambda << " between xi = " << xi_far << " and "
            << xi_near;
      }
}

}  // namespace

// The 1/xi terms (X^A, X^G, X^M) are exact to 1% already between xi = 1e-3 and 1e-4.
TEST(ResistanceFunctions, InverseGapTermsMatchExactDifferencesFrom1em3To1em4) {
  for (double lambda : ratios)
    for (int gamma : {0, 1})
      for (Column c : {XA, XG, XM}) {
        const double exact = table().at(1e-4, lambda, gamma, c) - table().at(1e-3, lambda, gamma, c);
        const double ours = model(1e-4, lambda, gamma, c) - model(1e-3, lambda, gamma, c);
        EXPECT_NEAR(ours, exact, 0.01 * std::abs(exact)) << names[c] << gamma << " lambda = " << lambda;
      }
}

// All singular terms (1/xi and ln(1/xi)) between xi = 1e-4 and 1e-5: within 1%, measured worst 0.3%. Between 1e-3
// and 1e-4 the xi ln(1/xi) terms the model omits shift some log-only functions by up to 2.2% (lambda = 10: YB, YC,
// YG, YH, YM; lambda = 0.1: Y12C, Y12H, Y12M), which the next test bounds.
TEST(ResistanceFunctions, SingularPartsMatchExactDifferencesFrom1em4To1em5) { expect_singular_part_exact(1e-4, 1e-5, 0.01); }

TEST(ResistanceFunctions, SingularPartsMatchExactDifferencesFrom1em3To1em4WithinNextOrder) {
  expect_singular_part_exact(1e-3, 1e-4, 0.025);
}

// The O(1) remainder (exact - model) is constant near contact when every singular term is there: between xi = 1e-5
// and 1e-4 it moves by less than 0.03 for every singular function (measured worst 0.016: lambda = 10, Y12H, the
// xi ln(1/xi) term the model omits), where a missing g ln(1/xi) would move it by g ln(10): for X^M of equal spheres
// Jeffrey's (1992) g2xm = g5xm = 0.135, i.e. 0.31, the terms whose absence made a free pair's model stresslet
// diverge (dem/hydro/free_pair.hpp).
TEST(ResistanceFunctions, RemainderIsConstantNearContact) {
  double worst = 0.0;
  for (double lambda : ratios)
    for (int gamma : {0, 1})
      for (Column c : singular_columns) {
        const double near = table().at(1e-5, lambda, gamma, c) - model(1e-5, lambda, gamma, c);
        const double far = table().at(1e-4, lambda, gamma, c) - model(1e-4, lambda, gamma, c);
        worst = std::max(worst, std::abs(near - far));
        EXPECT_LT(std::abs(near - far), 0.03)
            << names[c] << (gamma ? "12" : "11") << " lambda = " << lambda << ": remainder " << far << " at 1e-4, "
            << near << " at 1e-5";
      }
  std::cout << "largest change of a remainder between xi = 1e-4 and 1e-5: " << worst << "\n";
}

// X^C has no singular term: the model keeps X11C = 1 (Stokes) and X12C = 0; the exact change is tiny.
TEST(ResistanceFunctions, RotationAboutTheLineOfCentresIsNotSingular) {
  for (double lambda : ratios)
    for (int gamma : {0, 1}) {
      EXPECT_LT(std::abs(table().at(1e-5, lambda, gamma, XC) - table().at(1e-3, lambda, gamma, XC)), 0.02);
      EXPECT_DOUBLE_EQ(model(1e-5, lambda, gamma, XC), model(1e-3, lambda, gamma, XC));
    }
}

// Equal spheres: the leading forms quoted in the reference README.
TEST(ResistanceFunctions, EqualSpheresLeadingCoefficients) {
  const double xi = 1e-3, L = std::log(1.0 / xi);
  const ResistanceScalars s = two_sphere_resistance(1.0, 1.0, xi);
  EXPECT_NEAR(s.x11a, 1.0 + 1.0 / (4.0 * xi) + 9.0 / 40.0 * L, 1e-12);
  EXPECT_NEAR(s.y11a, 1.0 + L / 6.0, 1e-12);
  EXPECT_NEAR(s.y11b, -L / 4.0, 1e-12);
  EXPECT_NEAR(s.y11c, 1.0 + L / 5.0, 1e-12);
  EXPECT_NEAR(s.x11g, 3.0 / (8.0 * xi) + 27.0 / 80.0 * L, 1e-12);
  EXPECT_NEAR(s.y11g, L / 8.0, 1e-12);
  EXPECT_NEAR(s.y11h, L / 40.0, 1e-12);
}

// Near contact the full model (Stokes + singular terms) is within 3% of the exact functions for the squeeze force
// and its strain-driven counterpart; the worst case is the small sphere next to a big one at xi = 0.01.
TEST(ResistanceFunctions, SqueezeFunctionsWithin3PercentNearContact) {
  for (double lambda : {0.1, 1.0})
    for (double xi : {0.01, 0.001}) {
      EXPECT_NEAR(model(xi, lambda, 0, XA), table().at(xi, lambda, 0, XA), 0.03 * table().at(xi, lambda, 0, XA));
      EXPECT_NEAR(model(xi, lambda, 1, XA), table().at(xi, lambda, 1, XA), 0.03 * std::abs(table().at(xi, lambda, 1, XA)));
      EXPECT_NEAR(model(xi, lambda, 0, XG), table().at(xi, lambda, 0, XG), 0.03 * table().at(xi, lambda, 0, XG));
    }
  // lambda = 10 (sphere 1 the small one): within 3% at xi = 0.001; at xi = 0.01 the O(1) remainders
  // (X11A +0.51, X11G -0.84, docs/lubrication.md) are 3.1% and 4.1% of the exact values.
  const double lambda = 10.0;
  for (Column c : {XA, XG})
    for (int gamma : {0, 1}) {
      const double exact = table().at(0.001, lambda, gamma, c);
      EXPECT_NEAR(model(0.001, lambda, gamma, c), exact, 0.03 * std::abs(exact)) << names[c] << gamma;
    }
  EXPECT_NEAR(model(0.01, lambda, 1, XA), table().at(0.01, lambda, 1, XA), 0.03 * std::abs(table().at(0.01, lambda, 1, XA)));
  // X11A and X11G miss 3% there; the miss is the constant O(1) remainder of the contact limit (model minus exact
  // at xi = 0.01 equals that at xi = 1e-4 up to the omitted O(xi ln(1/xi)) terms), not an error in a singular term.
  for (Column c : {XA, XG}) {
    const double remainder_near = model(1e-4, lambda, 0, c) - table().at(1e-4, lambda, 0, c);
    const double remainder_far = model(0.01, lambda, 0, c) - table().at(0.01, lambda, 0, c);
    EXPECT_NEAR(remainder_far, remainder_near, 0.05) << names[c];
  }
}

// Lorentz reciprocity: the "12" function of sphere 1 scaled by a1^k equals the "21" one of sphere 2 scaled by a2^k
// (k = 1 for A, 3 for C), and for B, G the sign flips with d (Jeffrey & Onishi 1984, eq. 1.12 symmetries).
TEST(ResistanceFunctions, ReciprocityBetweenTheTwoSpheres) {
  const double a1 = 1.0, a2 = 3.0, gap = 0.004;
  const ResistanceScalars s1 = two_sphere_resistance(a1, a2, gap);
  const ResistanceScalars s2 = two_sphere_resistance(a2, a1, gap);
  EXPECT_NEAR(a1 * s1.x12a, a2 * s2.x12a, 1e-12 * std::abs(a1 * s1.x12a));
  EXPECT_NEAR(a1 * s1.y12a, a2 * s2.y12a, 1e-12 * std::abs(a1 * s1.y12a));
  EXPECT_NEAR(std::pow(a1, 3) * s1.y12c, std::pow(a2, 3) * s2.y12c, 1e-12 * std::abs(s1.y12c));
  // The table obeys the same relation: X12A(lambda) = lambda X12A(1/lambda).
  EXPECT_NEAR(table().at(1e-3, 10.0, 1, XA), 10.0 * table().at(1e-3, 0.1, 1, XA), 1e-6 * 152.5);
}

TEST(ResistanceFunctions, FarApartOnlyStokesDragRemains) {
  TwoSphereOptions opt;
  opt.outer_cutoff = 0.5;
  const ResistanceScalars s = two_sphere_resistance(1.0, 2.0, 0.6, opt);
  EXPECT_EQ(s.x11a, 1.0);
  EXPECT_EQ(s.y11a, 1.0);
  EXPECT_EQ(s.x11c, 1.0);
  EXPECT_EQ(s.y11c, 1.0);
  EXPECT_EQ(s.x12a, 0.0);
  EXPECT_EQ(s.y11b, 0.0);
  EXPECT_EQ(s.x11g, 0.0);
  EXPECT_EQ(s.y12h, 0.0);
  EXPECT_NEAR(s.xi, 2.0 * 0.6 / 3.0, 1e-15);
  // Just inside the cutoff the lubrication is on.
  EXPECT_GT(two_sphere_resistance(1.0, 2.0, 0.49, opt).x11a, 1.0);
}

TEST(ResistanceFunctions, RegularisationAddsToTheScaledGap) {
  TwoSphereOptions opt;
  opt.regularization = 0.01;
  const ResistanceScalars reg = two_sphere_resistance(1.0, 1.0, 0.0, opt);  // contact: finite
  const ResistanceScalars ref = two_sphere_resistance(1.0, 1.0, 0.01);      // xi = 0.01
  EXPECT_DOUBLE_EQ(reg.x11a, ref.x11a);
  EXPECT_DOUBLE_EQ(reg.y11b, ref.y11b);
  EXPECT_EQ(reg.xi, 0.0);  // the reported xi is the geometric one
}

TEST(ResistanceFunctions, BadInputIsAnInputError) {
  EXPECT_THROW(two_sphere_resistance(-1.0, 1.0, 0.1), InputError);
  EXPECT_THROW(two_sphere_resistance(1.0, 0.0, 0.1), InputError);
  EXPECT_THROW(two_sphere_resistance(1.0, 1.0, -0.1), InputError);  // overlap without regularisation
  EXPECT_THROW(two_sphere_resistance(1.0, 1.0, 0.0), InputError);
}
