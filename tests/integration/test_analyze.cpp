// `suspend analyze` on a real run: paper 004's adhesive frictional suspension (cases/quickstart.yaml, implicit
// Hertz contacts with adhesion and Coulomb friction). The contact stress rebuilt from each snapshot's contact list
// must be the series' contact stress of the same step, and the contact number the series' count.
#include <gtest/gtest.h>

#include <cstdlib>

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

TEST(Analyze, SummaryAveragesTheSnapshotsOfTheWindow) {
  const std::string dir = analysed_run();
  const Result r = run({"analyze", dir, "--snapshot", "all", "--json", "--no-distributions"});
  ASSERT_EQ(r.code, 0) << r.err;
  double sliding = 0.0, rattlers = 0.0;
  int n = 0;
  for (const json& s : json::parse(r.out)) {
    EXPECT_FALSE(s.contains("pair_distribution"));
    if (s["strain"].get<double>() < 0.2) continue;  // run.average_from
    sliding += s["sliding_fraction"].get<double>(), rattlers += s["rattler_fraction"].get<double>(), ++n;
  }
  ASSERT_GE(n, 2);
  const json summary = json::parse(read_text(dir + "/summary.json"));
  const json& m = summary["microstructure"];
  EXPECT_EQ(m["snapshots"].get<int>(), n);
  EXPECT_NEAR(m["sliding_fraction"]["mean"].get<double>(), sliding / n, 1e-12);
  EXPECT_NEAR(m["rattler_fraction"]["mean"].get<double>(), rattlers / n, 1e-12);
  EXPECT_GT(m["sliding_fraction"]["mean"].get<double>(), 0.0);  // mu_s = 0.5 under shear: some contacts slide
}

TEST(Analyze, XdmfShowsParticlesContactsAndTheShearedCell) {
  // What a ParaView user opens: every dataset the XDMF names exists with its shape (tools/check_xdmf.py), and a
  // picture drawn through the XDMF's references shows the spheres, the contact network and the cell.
  const std::string dir = analysed_run();
  const std::string log = scratch() + "/xdmf.txt", png = scratch() + "/snapshot.png";
  fs::remove(png);
  ASSERT_EQ(std::system(("/usr/bin/python3 " SUSPEND_SOURCE_DIR "/tools/check_xdmf.py " + dir + "/run.xdmf > " + log +
                         " 2>&1").c_str()), 0) << read_text(log);
  EXPECT_NE(read_text(log).find("particles 4, contacts 4, box 4"), std::string::npos) << read_text(log);
  ASSERT_EQ(std::system(("/usr/bin/python3 " SUSPEND_SOURCE_DIR "/tools/render_snapshot.py " + dir + " --out " + png +
                         " > " + log + " 2>&1").c_str()), 0) << read_text(log);
  EXPECT_NE(read_text(log).find("contacts"), std::string::npos) << read_text(log);
  ASSERT_TRUE(fs::exists(png));
  EXPECT_GT(fs::file_size(png), 20000u);
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

TEST(Analyze, GradientProfileOfTheRun) {
  const std::string dir = analysed_run();
  const Result r = run({"analyze", dir, "--snapshot", "last", "--json", "--no-distributions", "--bins", "6"});
  ASSERT_EQ(r.code, 0) << r.err;
  const json g = json::parse(r.out).back()["gradient_profile"];
  ASSERT_EQ(g["phi"].size(), 6u);
  double phi = 0.0, count = 0.0;
  for (int k = 0; k < 6; ++k) phi += g["phi"][k].get<double>() / 6.0, count += g["count"][k].get<double>();
  const json summary = json::parse(read_text(dir + "/summary.json"));
  EXPECT_NEAR(phi, summary["phi"].get<double>(), 1e-12);  // the slabs' exact sphere volumes add up to the box's
  EXPECT_EQ(count, json::parse(r.out).back()["particles"].get<double>());
  EXPECT_TRUE(g["shear_rate"].is_number());  // the snapshots carry velocities
  const Result text = run({"analyze", dir, "--snapshot", "all", "--profile", "--no-distributions"});
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("gradient profile, mean of 4 snapshot(s), 8 slabs"), std::string::npos) << text.out;
  const Result bad = run({"analyze", dir, "--bins", "0"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--bins"), std::string::npos) << bad.err;
}
