// The shipped JKR case (cases/validation/jkr_pull_off.yaml) through the program: a bonded pair pulled by a
// repulsion just below the JKR pull-off force holds (a neck at a positive gap, shorter than -delta_c), just above it
// separates; and a run continued from a checkpoint taken while bonded (the neck's contact radius in
// contacts/normal_state) ends bit for bit as the run that never stopped.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "io/hdf5.hpp"
#include "io/run_file.hpp"
#include "io/snapshot_reader.hpp"

#include "tests/integration/cli_support.hpp"

using namespace suspend::test;
namespace h5 = suspend::io::h5;

namespace {
const std::string pair_case = SUSPEND_SOURCE_DIR "/cases/validation/jkr_pull_off.yaml";

// Surface gap of the pair in the last snapshot.
double final_gap(const std::string& dir) {
  h5::File f = h5::File::open(dir + "/run.h5", false);
  const suspend::analysis::Configuration c =
      suspend::io::read_configuration(f.id(), suspend::io::snapshot_count(f.id()) - 1);
  return (c.position[1] - c.position[0]).norm() - 2.0;
}

std::string run_pair(const std::string& name, double force, const std::vector<std::string>& more = {}) {
  const std::string out = fresh_dir(name);
  std::vector<std::string> args = {"run", pair_case, "--out", out, "--threads", "1", "--quiet", "--set",
                                   "contact.repulsion.force=" + std::to_string(force)};
  for (const std::string& s : more) args.insert(args.end(), {"--set", s});
  const Result r = run(args);
  EXPECT_EQ(r.code, 0) << r.err;
  return out;
}
}  // namespace

TEST(JkrPullOff, TheBondHoldsBelowThePullOffForceAndSnapsAboveIt) {
  // E* = 1e4, W = 2, R* = 1/2: pull-off (3/2) pi W R* at the neck gap h* = -delta(a*), a*^(3/2) = 3 c R* / 4, where
  // the repulsion F_ER exp(-h*) applies; delta_c the snap.
  const double pi = std::numbers::pi, e = 1.0e4, w = 2.0, r = 0.5, c = std::sqrt(2.0 * pi * w / e);
  const double a_star = std::cbrt(std::pow(0.75 * c * r, 2.0));
  const double h_star = -(a_star * a_star / r - c * std::sqrt(a_star));
  const double threshold = 1.5 * pi * w * r * std::exp(h_star);
  const double snap_gap = 0.75 * std::cbrt(pi * pi * w * w * r / (e * e));
  const double holds = final_gap(run_pair("jkr_holds", 0.995 * threshold));
  const double snaps = final_gap(run_pair("jkr_snaps", 1.005 * threshold));
  std::cout << "threshold F_ER " << threshold << ": at -0.5% the neck holds at gap " << holds << " (snap at "
            << snap_gap << "), at +0.5% the pair is " << snaps << " apart\n";
  EXPECT_GT(holds, 0.0);
  EXPECT_LT(holds, snap_gap);
  EXPECT_GT(snaps, 0.1);
}

TEST(JkrPullOff, ARunContinuedFromACheckpointWithTheBondEndsAsTheWholeRun) {
  const std::string whole = run_pair("jkr_whole", 4.5);
  const std::string part = run_pair("jkr_part", 4.5, {"run.strain=1"});
  {
    h5::File f = h5::File::open(part + "/checkpoint.h5", false);
    const std::vector<double> neck = h5::read_doubles(f.id(), "contacts/normal_state");
    ASSERT_EQ(neck.size(), 1u);
    EXPECT_GT(neck[0], 0.0);  // bonded, its contact radius carried
  }
  const Result r = run({"run", pair_case, "--restart", part + "/checkpoint.h5", "--threads", "1", "--quiet", "--set",
                        "contact.repulsion.force=4.5"});
  ASSERT_EQ(r.code, 0) << r.err;
  h5::File a = h5::File::open(whole + "/run.h5", false), b = h5::File::open(part + "/run.h5", false);
  for (const char* s : {"time", "strain", "stress/total", "stress/adhesion", "contacts"})
    EXPECT_EQ(suspend::io::read_series(a.id(), s), suspend::io::read_series(b.id(), s)) << s;
  EXPECT_EQ(final_gap(whole), final_gap(part));
}
