// `suspend analyze` on a real run: paper 004's adhesive frictional suspension (cases/quickstart.yaml, implicit
// Hertz contacts with adhesion and Coulomb friction). The contact stress rebuilt from each snapshot's contact list
// must be the series' contact stress of the same step, and the contact number the series' count.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/hdf5.hpp"
#include "io/run_file.hpp"
#include "tests/integration/cli_support.hpp"

using namespace suspend;
using namespace suspend::test;
using json = nlohmann::json;

namespace {

const std::string& analysed_run() {
  static const std::string dir = [] {
    const std::string d = fresh_dir("analyzed");
    const Result r = run({"run", SUSPEND_SOURCE_DIR "/cases/quickstart.yaml", "--set", "run.strain=0.6", "--set",
                          "run.output.snapshot_every=0.2", "--set", "run.average_from=0.2", "--out", d, "--quiet",
                          "--threads", "1"});
    EXPECT_EQ(r.code, 0) << r.err;
    return d;
  }();
  return dir;
}

}  // namespace

TEST(Analyze, SnapshotContactStressIsTheSeriesContactStress) {
  const std::string dir = analysed_run();
  const Result r = run({"analyze", dir, "--snapshot", "all", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const json snapshots = json::parse(r.out);
  ASSERT_EQ(snapshots.size(), 4u);  // strain 0, 0.2, 0.4, 0.6

  io::h5::File f = io::h5::File::open(dir + "/run.h5", false);
  const std::vector<double> step = io::read_series(f.id(), "step"), contacts = io::read_series(f.id(), "contacts");
  int compared = 0;
  for (const json& s : snapshots) {
    const auto row = std::find(step.begin(), step.end(), s["step"].get<double>());
    ASSERT_NE(row, step.end()) << "a series row at the snapshot's step " << s["step"];
    const std::size_t k = static_cast<std::size_t>(row - step.begin());
    EXPECT_EQ(s["contacts"].get<double>(), contacts[k]);
    EXPECT_DOUBLE_EQ(s["contacts_per_particle"].get<double>(), 2.0 * contacts[k] / s["particles"].get<double>());
    if (s["contacts"].get<int>() == 0) continue;
    for (int c = 0; c < 6; ++c) {
      const std::string name = io::tensor_components[c];
      const double law = io::read_series(f.id(), "stress/contact_normal", c)[k] +
                         io::read_series(f.id(), "stress/contact_tangential", c)[k];
      const double all = law + io::read_series(f.id(), "stress/adhesion", c)[k] +
                         io::read_series(f.id(), "stress/repulsion", c)[k];
      const double scale = std::abs(io::read_series(f.id(), "stress/contact_normal", 0)[k]);
      EXPECT_NEAR(s["contact_stress"][name].get<double>(), law, 1e-9 * scale) << name << " at step " << s["step"];
      EXPECT_NEAR(s["contact_pair_stress"][name].get<double>(), all, 1e-9 * scale) << name;
    }
    EXPECT_NEAR(s["fabric"]["xx"].get<double>() + s["fabric"]["yy"].get<double>() + s["fabric"]["zz"].get<double>(),
                1.0, 1e-12);
    EXPECT_GE(s["sliding_fraction"].get<double>(), 0.0);
    EXPECT_LE(s["sliding_fraction"].get<double>(), 1.0);
    ++compared;
  }
  EXPECT_GE(compared, 3);
  // The adhesive network of the sheared state: a cluster spans the box.
  EXPECT_TRUE(snapshots.back()["clusters"]["percolates"]["x"].get<bool>());
}

TEST(Analyze, PrintsALinePerSnapshotAndRefusesBadChoices) {
  const std::string dir = analysed_run();
  const Result r = run({"analyze", dir, "--snapshot", "all"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 5) << r.out;  // header + 4 snapshots
  expect_input_error({"analyze", dir, "--snapshot", "4"}, "allowed are 0 to 3, last or all", "");
  expect_input_error({"analyze", dir, "--snapshot", "1x"}, "--snapshot '1x'", "");
  expect_input_error({"analyze", dir + "/nowhere"}, "not found", "");
}
