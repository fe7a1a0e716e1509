// `suspend pair`: print two-sphere resistance functions (Stokes drag included) in the normalisation of Kim & Karrila /
// Jeffrey & Onishi (dem/hydro/resistance_functions.hpp), seen from sphere 1, to compare with the exact tables
// (tests/data/two_sphere_resistance_table*.txt) or to choose cutoffs. --functions:
//   singular        the pairwise model's default: drag + the terms singular at contact;
//   exact_relative  the pairwise option of that name (dem/hydro/exact_relative.hpp): exact for relative motion and
//                   rotation, rigid translation of the pair force-free, so X11A + X12A = 1 and Y11A + Y12A = 1;
//   exact           the exact two-sphere functions (what FCM + sub-grid correction reproduces), the stresslet
//                   functions M (X, Y, Z) included.
// The M functions of singular and exact_relative are the model's: drag + singular terms (X11M, X12M, Y11M, Y12M),
// Z11M = 1 and Z12M = 0.
// The last two need an exact table for a2/a1 (1, 1.4, 1/1.4; dem/hydro/exact_remainder.hpp).
#include <CLI/CLI.hpp>
#include <array>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "apps/commands.hpp"
#include "core/error.hpp"
#include "dem/hydro/exact_relative.hpp"
#include "dem/hydro/exact_remainder.hpp"
#include "dem/hydro/free_pair.hpp"
#include "dem/hydro/resistance_functions.hpp"

namespace suspend::app {
namespace {

struct PairOptions {
  double a1 = 1.0;
  double a2 = 1.0;
  double gap = 0.01;
  bool json = false;
  double regularization = 0.0;
  double outer_cutoff = -1.0;  // none
  std::string functions = "singular";
  bool shear = false;                            // the free pair's stress in simple shear
  std::vector<double> normal{1.0, -1.0, 0.0};    // pair axis for --shear (the compressional axis by default)
};

std::string str(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

void check(const PairOptions& o) {
  auto require = [](bool ok, const std::string& msg) {
    if (!ok) throw InputError(msg);
  };
  require(std::isfinite(o.a1) && o.a1 > 0.0, "--a1 = " + str(o.a1) + ": the radius must be > 0");
  require(std::isfinite(o.a2) && o.a2 > 0.0, "--a2 = " + str(o.a2) + ": the radius must be > 0");
  require(std::isfinite(o.gap) && o.gap >= 0.0, "--gap = " + str(o.gap) + ": the surface gap must be >= 0");
  require(std::isfinite(o.regularization) && o.regularization >= 0.0,
          "--regularization = " + str(o.regularization) + ": must be >= 0");
  require(o.gap > 0.0 || o.regularization > 0.0, "--gap = 0 needs --regularization > 0 (lubrication is singular)");
  require(o.a2 / o.a1 >= 1e-2 && o.a2 / o.a1 <= 1e2,
          "--a2 / --a1 = " + str(o.a2 / o.a1) + ": the size ratio must be between 0.01 and 100");
  require(o.gap <= 1e6 * std::min(o.a1, o.a2), "--gap = " + str(o.gap) + ": at most 1e6 radii");
  require(o.outer_cutoff == -1.0 || (std::isfinite(o.outer_cutoff) && o.outer_cutoff > 0.0),
          "--outer-cutoff = " + str(o.outer_cutoff) + ": the surface gap beyond which lubrication is zero must be > 0");
  if (o.shear) {
    const double norm = std::sqrt(o.normal[0] * o.normal[0] + o.normal[1] * o.normal[1] + o.normal[2] * o.normal[2]);
    require(std::isfinite(norm) && norm > 0.0, "--normal: the pair axis must be a non-zero finite vector");
    require(hydro::ExactRemainder::for_ratio(o.a2 / o.a1) != nullptr,
            "--shear: the exact stress needs an exact two-sphere table; a2/a1 = " + str(o.a2 / o.a1) +
                " has none (shipped for " + hydro::ExactRemainder::shipped_ratios() + ")");
  }
  if (o.functions == "singular" && !o.shear) return;
  require(hydro::ExactRemainder::for_ratio(o.a2 / o.a1) != nullptr,
          "--functions " + o.functions + ": no exact two-sphere table for a2/a1 = " + str(o.a2 / o.a1) +
              " (shipped for " + hydro::ExactRemainder::shipped_ratios() + "); use --functions singular");
  require(2.0 * o.gap / (o.a1 + o.a2) + o.regularization <= 2.5,
          "--gap = " + str(o.gap) + ": the exact tables end at xi = 2(gap)/(a1 + a2) = 2.5");
}

hydro::ResistanceScalars pair_functions(const PairOptions& o) {
  hydro::TwoSphereOptions opt;
  opt.regularization = o.regularization;
  opt.outer_cutoff = o.outer_cutoff;
  hydro::ResistanceScalars s = hydro::two_sphere_resistance(o.a1, o.a2, o.gap, opt);  // singular
  if (o.functions == "singular" || (o.outer_cutoff >= 0.0 && o.gap > o.outer_cutoff)) return s;
  const double xi = 2.0 * o.gap / (o.a1 + o.a2) + o.regularization, log_inv_xi = std::log(1.0 / xi);
  // Seen from sphere 1 (lambda) and from sphere 2 (1/lambda, in a2 units).
  hydro::ResistanceScalars exact_1 = hydro::ExactRemainder::for_ratio(o.a2 / o.a1)->exact_with_stresslet(xi, log_inv_xi);
  const hydro::ResistanceScalars exact_2 = hydro::ExactRemainder::for_ratio(o.a1 / o.a2)->exact(xi, log_inv_xi);
  if (o.functions == "exact") {
    exact_1.xi = s.xi;
    return exact_1;
  }
  using hydro::LubricationCoefficients;
  hydro::ResistanceScalars lub_1 = hydro::lubrication_scalars(LubricationCoefficients::for_ratio(o.a2 / o.a1), xi);
  hydro::ResistanceScalars lub_2 = hydro::lubrication_scalars(LubricationCoefficients::for_ratio(o.a1 / o.a2), xi);
  hydro::exact_relative_part(o.a1, o.a2, exact_1, exact_2, lub_1, lub_2);
  hydro::add_stokes_drag(lub_1);
  lub_1.xi = s.xi;
  return lub_1;
}

// The stress of a force- and torque-free pair in simple shear u = (y, 0, 0) (rate 1): exact (the tables), and the
// model of --functions in the engine's two forms (dem/hydro/free_pair.hpp); interaction parts, eta gammadot a^3.
void run_shear(const PairOptions& o) {
  PairOptions swapped = o;
  std::swap(swapped.a1, swapped.a2);
  const hydro::ResistanceScalars m1 = pair_functions(o), m2 = pair_functions(swapped);
  const double xi = 2.0 * o.gap / (o.a1 + o.a2) + o.regularization, log_inv_xi = std::log(1.0 / xi);
  const hydro::ResistanceScalars e1 = hydro::ExactRemainder::for_ratio(o.a2 / o.a1)->exact_with_stresslet(xi, log_inv_xi);
  const hydro::ResistanceScalars e2 = hydro::ExactRemainder::for_ratio(o.a1 / o.a2)->exact_with_stresslet(xi, log_inv_xi);
  const Vec3 n = Vec3(o.normal[0], o.normal[1], o.normal[2]).normalized();
  Mat3 e = Mat3::Zero();
  e(0, 1) = e(1, 0) = 0.5;
  const hydro::FreePairStress exact = hydro::free_pair_stress(o.a1, o.a2, n, o.gap, e1, e2, e);
  const hydro::FreePairStress model = hydro::free_pair_stress(o.a1, o.a2, n, o.gap, m1, m2, e);
  const std::array<std::pair<const char*, const Mat3*>, 3> forms{
      {{"exact", &exact.stresslet}, {"stresslet", &model.stresslet}, {"force_dipole", &model.force_dipole}}};
  if (o.json) {
    std::printf("{\"gap\": %.12g, \"normal\": [%.12g, %.12g, %.12g], \"functions\": \"%s\"", o.gap, n.x(), n.y(),
                n.z(), o.functions.c_str());
    for (const auto& [name, m] : forms)
      std::printf(", \"%s\": {\"xy\": %.12g, \"xx_minus_yy\": %.12g, \"yy_minus_zz\": %.12g, \"trace\": %.12g}",
                  name, (*m)(0, 1), (*m)(0, 0) - (*m)(1, 1), (*m)(1, 1) - (*m)(2, 2), m->trace());
    std::printf("}\n");
    return;
  }
  std::printf("# free pair in simple shear u = (y, 0, 0), a1 = %g, a2 = %g, gap = %g, axis (%.4g, %.4g, %.4g); pair "
              "stress minus the isolated spheres', eta gammadot a^3; model: %s functions\n",
              o.a1, o.a2, o.gap, n.x(), n.y(), n.z(), o.functions.c_str());
  std::printf("%-13s %14s %14s %14s %14s\n", "form", "xy", "xx - yy", "yy - zz", "trace");
  for (const auto& [name, m] : forms)
    std::printf("%-13s %14.8g %14.8g %14.8g %14.8g\n", name, (*m)(0, 1), (*m)(0, 0) - (*m)(1, 1),
                (*m)(1, 1) - (*m)(2, 2), m->trace());
}

void run_pair(const PairOptions& o) {
  check(o);
  if (o.shear) {
    run_shear(o);
    return;
  }
  const hydro::ResistanceScalars s = pair_functions(o);
  const std::array<std::pair<const char*, double>, 23> values = {{{"xi", s.xi},
                                                                   {"X11A", s.x11a},
                                                                   {"X12A", s.x12a},
                                                                   {"Y11A", s.y11a},
                                                                   {"Y12A", s.y12a},
                                                                   {"Y11B", s.y11b},
                                                                   {"Y12B", s.y12b},
                                                                   {"X11C", s.x11c},
                                                                   {"X12C", s.x12c},
                                                                   {"Y11C", s.y11c},
                                                                   {"Y12C", s.y12c},
                                                                   {"X11G", s.x11g},
                                                                   {"X12G", s.x12g},
                                                                   {"Y11G", s.y11g},
                                                                   {"Y12G", s.y12g},
                                                                   {"Y11H", s.y11h},
                                                                   {"Y12H", s.y12h},
                                                                   {"X11M", s.x11m},
                                                                   {"X12M", s.x12m},
                                                                   {"Y11M", s.y11m},
                                                                   {"Y12M", s.y12m},
                                                                   {"Z11M", s.z11m},
                                                                   {"Z12M", s.z12m}}};
  if (o.json) {
    std::printf("{");
    for (std::size_t k = 0; k < values.size(); ++k)
      std::printf("%s\"%s\": %.12g", k ? ", " : "", values[k].first, values[k].second);
    std::printf("}\n");
    return;
  }
  std::printf("# %s functions; a1 = %g, a2 = %g, lambda = a2/a1 = %g, gap = %g; A x 6 pi eta a1, B, G x 4 pi eta "
              "a1^2, C, H x 8 pi eta a1^3, M x (20/3) pi eta a1^3\n",
              o.functions.c_str(), o.a1, o.a2, o.a2 / o.a1, o.gap);
  for (const auto& [name, value] : values) std::printf("%-5s %.10g\n", name, value);
}

}  // namespace

void add_pair_command(CLI::App& app) {
  auto opts = std::make_shared<PairOptions>();
  CLI::App* sub = app.add_subcommand("pair", "Print the two-sphere resistance functions of the lubrication model");
  sub->add_option("--a1", opts->a1, "radius of sphere 1")->required();
  sub->add_option("--a2", opts->a2, "radius of sphere 2")->required();
  sub->add_option("--gap", opts->gap, "surface gap h = r - a1 - a2 (same length unit)")->required();
  sub->add_flag("--json", opts->json, "print one JSON object");
  sub->add_option("--regularization", opts->regularization, "epsilon added to xi = 2h/(a1+a2) (default 0)");
  sub->add_option("--outer-cutoff", opts->outer_cutoff, "surface gap beyond which lubrication is zero (default none)");
  sub->add_option("--functions", opts->functions,
                  "singular (default: drag + singular terms), exact_relative (the pairwise option: exact relative "
                  "motion, rigid translation force-free) or exact (the exact two-sphere functions)")
      ->check(CLI::IsMember({"singular", "exact_relative", "exact"}));
  sub->add_flag("--shear", opts->shear,
                "print the stress of the force- and torque-free pair in simple shear u = (y, 0, 0): exact, and the "
                "model of --functions as the stresslet and as the force dipole (lubrication.stress)");
  sub->add_option("--normal", opts->normal, "pair axis for --shear, from sphere 1 to 2 (default 1 -1 0)")
      ->expected(3);
  sub->callback([opts]() { run_pair(*opts); });
}

}  // namespace suspend::app
