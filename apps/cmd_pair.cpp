// `suspend pair`: print the two-sphere resistance functions of the pairwise model (Stokes drag + lubrication) in the
// normalisation of Kim & Karrila / Jeffrey & Onishi (dem/hydro/resistance_functions.hpp), to compare with the exact
// table (tests/data/two_sphere_resistance_table.txt) or to choose cutoffs.
#include <CLI/CLI.hpp>
#include <array>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <utility>

#include "apps/commands.hpp"
#include "core/error.hpp"
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
}

void run_pair(const PairOptions& o) {
  check(o);
  hydro::TwoSphereOptions opt;
  opt.regularization = o.regularization;
  opt.outer_cutoff = o.outer_cutoff;
  const hydro::ResistanceScalars s = hydro::two_sphere_resistance(o.a1, o.a2, o.gap, opt);
  const std::array<std::pair<const char*, double>, 16> values = {{{"xi", s.xi},
                                                                   {"X11A", s.x11a},
                                                                   {"X12A", s.x12a},
                                                                   {"Y11A", s.y11a},
                                                                   {"Y12A", s.y12a},
                                                                   {"Y11B", s.y11b},
                                                                   {"Y12B", s.y12b},
                                                                   {"X11C", s.x11c},
                                                                   {"Y11C", s.y11c},
                                                                   {"Y12C", s.y12c},
                                                                   {"X11G", s.x11g},
                                                                   {"X12G", s.x12g},
                                                                   {"Y11G", s.y11g},
                                                                   {"Y12G", s.y12g},
                                                                   {"Y11H", s.y11h},
                                                                   {"Y12H", s.y12h}}};
  if (o.json) {
    std::printf("{");
    for (std::size_t k = 0; k < values.size(); ++k)
      std::printf("%s\"%s\": %.12g", k ? ", " : "", values[k].first, values[k].second);
    std::printf("}\n");
    return;
  }
  std::printf("# a1 = %g, a2 = %g, lambda = a2/a1 = %g, gap = %g; A x 6 pi eta a1, B, G x 4 pi eta a1^2, "
              "C, H x 8 pi eta a1^3\n",
              o.a1, o.a2, o.a2 / o.a1, o.gap);
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
  sub->callback([opts]() { run_pair(*opts); });
}

}  // namespace suspend::app
