// `suspend sweep` as users run it: a campaign gives the same table run with two jobs, after SIGKILL of the sweep
// and its runs followed by the same command (the killed point's wall time kept up to its last checkpoint), and
// point by point as a scheduler would run it; a changed campaign is refused naming the key (by --status too); a stress-controlled
// point that stops flowing ends as `jammed`; a point over its wall-clock budget is `failed` and kept until
// --retry-failed; --status reads a finished and a half-finished sweep.
#include <gtest/gtest.h>

#include <cstdlib>

#include <chrono>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <thread>

#include "core/error.hpp"
#include "io/hdf5.hpp"
#include "tests/integration/cli_support.hpp"

using namespace suspend::test;
using json = nlohmann::json;

namespace {
const std::string restart_case = SUSPEND_SOURCE_DIR "/tests/data/restart_case.yaml";

#ifdef NDEBUG
constexpr const char* strain = "0.3";
constexpr double kill_strain = 0.1;
#else
constexpr const char* strain = "0.12";  // Debug + sanitizers: about 30x slower
constexpr double kill_strain = 0.05;
#endif

// Three points of the frictional restart case, checkpointed every 0.05 strain.
std::string campaign(const std::string& name, const std::string& extra_points = "") {
  return write_case(name, "case: " + restart_case + "\nset: {run.strain: " + strain +
                              ", particles.count: 60}\nvary:\n  particles.phi: [0.40, 0.45]\npoints:\n"
                              "  - {particles.phi: 0.5, contact.mu: 0.5}\n" + extra_points);
}

// campaign.json without what depends on the machine (wall and CPU time).
json table(const std::string& dir) {
  json t = json::parse(read_text(dir + "/campaign.json"));
  for (json& p : t["points"]) p.erase("wall_seconds"), p.erase("cpu_seconds");
  return t;
}

double checkpoint_strain(const std::string& file) {
  try {
    suspend::io::h5::File f = suspend::io::h5::File::open(file, false);
    return suspend::io::h5::double_attribute(f.id(), ".", "strain");
  } catch (const std::exception&) {
    return 0.0;
  }
}
}  // namespace

TEST(Sweep, SameTableWithJobsAfterSigkillAndPointByPoint) {
  const std::string file = campaign("sweep.yaml");
  const std::string a = fresh_dir("sweep_a"), b = fresh_dir("sweep_b"), c = fresh_dir("sweep_c");
  const Result ra = run({"sweep", file, "--out", a, "--jobs", "2", "--quiet"});
  ASSERT_EQ(ra.code, 0) << ra.err;
  const json ta = table(a);
  ASSERT_EQ(ta["points"].size(), 3u);
  // Each point's cost: its run's CPU time, at most its wall time on one thread (plus the clocks' granularity).
  for (const json& p : json::parse(read_text(a + "/campaign.json"))["points"]) {
    EXPECT_GT(p.value("cpu_seconds", 0.0), 0.0) << p["name"];
    EXPECT_LE(p.value("cpu_seconds", 0.0), p["wall_seconds"].get<double>() + 0.05) << p["name"];
  }
  for (const json& p : ta["points"]) {
    EXPECT_EQ(p["status"], "done") << p.dump();
    EXPECT_GT(p["summary"]["eta_r"]["mean"].get<double>(), 1.0) << p.dump();
    EXPECT_TRUE(p["derived"].contains("mu")) << p.dump();
  }
  EXPECT_EQ(ta["points"][0]["name"], "phi0.40");
  EXPECT_EQ(ta["points"][2]["name"], "phi0.5_mu0.5");
  EXPECT_EQ(ta["points"][2]["parameters"]["contact.mu"], 0.5);
  EXPECT_EQ(ta["points"][2]["case"]["mu_s"], 0.5);
  EXPECT_EQ(ta["points"][2]["case"]["functions"], "singular");  // lubrication on, the default two-sphere functions
  EXPECT_EQ(ta["points"][2]["case"]["count"], 60);
  const Result done = run({"sweep", file, "--out", a, "--status"});
  ASSERT_EQ(done.code, 0) << done.err;
  EXPECT_NE(done.out.find("3 point(s): 3 done"), std::string::npos) << done.out;
  EXPECT_NE(done.out.find("nothing left to run"), std::string::npos) << done.out;

  // B: the sweep and its runs are killed together (SIGKILL) mid-point, then the same command finishes it. The
  // point's record already holds its wall time up to its last checkpoint (the sweep adds it at each checkpoint).
  const pid_t pid = spawn({"sweep", file, "--out", b, "--jobs", "1", "--quiet"}, b + ".err", true);
  const auto t0 = std::chrono::steady_clock::now();
  bool killed = false;
  auto recorded_seconds = [&](const std::string& p) {
    try {
      return json::parse(read_text(b + "/points/" + p + "/point.json")).value("wall_seconds", 0.0);
    } catch (const std::exception&) {
      return 0.0;
    }
  };
  while (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(120) && !killed) {
    for (const char* p : {"phi0.40", "phi0.45", "phi0.5_mu0.5"}) {
      const double s = checkpoint_strain(b + "/points/" + p + "/checkpoint.h5");
      if (s >= kill_strain && s < 0.25 && recorded_seconds(p) > 0.0 &&
          !fs::exists(b + "/points/" + p + "/summary.json")) {
        kill(-pid, SIGKILL);
        killed = true;
        break;
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(killed) << "no point was caught mid-run with its wall time so far in its record";
  EXPECT_EQ(wait_exit(pid), 128 + SIGKILL);
  // --status of the half-finished sweep: the killed point is interrupted (its process is gone) and continues from
  // its checkpoint; nothing is started.
  const Result half = run({"sweep", file, "--out", b, "--status"});
  ASSERT_EQ(half.code, 0) << half.err;
  EXPECT_NE(half.out.find("interrupted"), std::string::npos) << half.out;
  EXPECT_NE(half.out.find("continues from strain"), std::string::npos) << half.out;
  EXPECT_NE(half.out.find("time left"), std::string::npos) << half.out;
  EXPECT_EQ(half.out.find("nothing left"), std::string::npos) << half.out;
  const Result rb = run({"sweep", file, "--out", b, "--jobs", "1", "--quiet"});
  ASSERT_EQ(rb.code, 0) << rb.err;
  json tb = table(b);
  tb["campaign"] = ta["campaign"];
  EXPECT_EQ(tb, ta) << "the table after SIGKILL + rerun differs from the uninterrupted one";

  // C: one point at a time, as a scheduler array would (--list gives the names).
  const Result list = run({"sweep", file, "--list"});
  ASSERT_EQ(list.code, 0);
  for (const char* p : {"phi0.40", "phi0.45", "phi0.5_mu0.5"})
    ASSERT_EQ(run({"sweep", file, "--out", c, "--point", p, "--quiet"}).code, 0) << p;
  EXPECT_EQ(table(c), ta);
}

// Two sweeps on one folder at once (issue 37, item 2): each point runs once, by whichever took its lock first; the
// other skips it, also when it reaches the point after the first has finished it (2fbb67f started such a point
// again, which then failed for good). A record lost to a SIGKILL between a point's end and its record is rebuilt
// from the run's summary, not run again. Both give the table of one clean sweep.
TEST(Sweep, TwoSweepsOnOneFolderRunEachPointOnce) {
  const std::string file = campaign("together.yaml");
  const std::string clean = fresh_dir("sweep_clean"), shared = fresh_dir("sweep_shared");
  ASSERT_EQ(run({"sweep", file, "--out", clean, "--jobs", "2", "--quiet"}).code, 0);
  const pid_t first = spawn({"sweep", file, "--out", shared, "--jobs", "1", "--quiet"}, shared + ".1.err");
  const pid_t second = spawn({"sweep", file, "--out", shared, "--jobs", "1", "--quiet"}, shared + ".2.err");
  EXPECT_EQ(wait_exit(first), 0) << read_text(shared + ".1.err");
  EXPECT_EQ(wait_exit(second), 0) << read_text(shared + ".2.err");
  EXPECT_EQ(table(shared), table(clean));
  for (const char* p : {"phi0.40", "phi0.45", "phi0.5_mu0.5"})
    EXPECT_EQ(json::parse(read_text(shared + "/points/" + p + "/point.json"))["runs"], 1) << p;

  const std::string record = shared + "/points/phi0.45/point.json";
  json lost = json::parse(read_text(record));
  lost["status"] = "running";
  lost["exit_code"] = -1;
  std::ofstream(record) << lost.dump(2);
  const Result again = run({"sweep", file, "--out", shared, "--quiet"});
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_EQ(table(shared), table(clean));
  EXPECT_EQ(json::parse(read_text(record))["runs"], 1) << "the ended point was run again";
}

// The boundary search (issue 34): under imposed stress with run.jammed.viscosity = 3, a point jams where eta_r
// exceeds about 3, which the frictional restart case does between phi 0.3 and 0.35. Bisection of phi in [0.1, 0.5]
// to 0.05 with 3 seeds tries 0.1 and 0.5, then 0.3, 0.4 and 0.35, and stops at the bracket [0.3, 0.35]; one job or
// two give the same table, a second sweep adds nothing, a SIGKILLed search resumes to the same table, and a range
// whose low end jams is reported as such.
// The program a sweep runs for its points, installed anew at the same path while the sweep runs (a rename over it,
// as tools/resume_campaigns.sh installs one), runs the later rounds of a search; removed, it leaves the points it
// cannot start pending and the sweep stops saying why. Nothing is marked failed, and the same command continues.
TEST(Sweep, AProgramReplacedOrRemovedWhileTheSweepRunsLosesNoPoint) {
  const std::string file = write_case(
      "search_program.yaml", "case: " + restart_case +
                                 "\nset: {particles.count: 40, run.strain: 0.3, run.average_from: 0, flow.control: "
                                 "stress, flow.shear_stress: 1, run.jammed.viscosity: 3, run.jammed.strain: 0.01}\n"
                                 "search: {key: particles.phi, lo: 0.1, hi: 0.5, tolerance: 0.05, seeds: 3}\n");
  const std::string program = scratch() + "/suspend-installed";
  auto install = [&] {
    fs::copy_file(suspend_bin, program + ".new", fs::copy_options::overwrite_existing);
    fs::rename(program + ".new", program);
  };
  auto statuses = [&](const std::string& dir) {
    std::map<std::string, int> n;
    const json t = table(dir);
    for (const json& p : t["points"]) ++n[p["status"].get<std::string>()];
    return n;
  };
  install();
  const std::string replaced = fresh_dir("search_replaced");
  pid_t pid = spawn({"sweep", file, "--out", replaced, "--jobs", "1", "--quiet"}, replaced + ".err", true,
                    "/dev/null", program);
  while (!fs::exists(replaced + "/points/phi0.1_seed1/summary.json"))
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  install();  // the later rounds start their points with the new file at the same path
  ASSERT_EQ(wait_exit(pid), 0) << read_text(replaced + ".err");
  EXPECT_EQ(statuses(replaced)["failed"], 0);
  EXPECT_EQ(statuses(replaced)["done"] + statuses(replaced)["jammed"], 15) << "the whole search";

  const std::string removed = fresh_dir("search_removed");
  pid = spawn({"sweep", file, "--out", removed, "--jobs", "1"}, removed + ".err", true, removed + ".out", program);
  while (!fs::exists(removed + "/points/phi0.1_seed1/summary.json"))
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  fs::remove(program);
  EXPECT_EQ(wait_exit(pid), suspend::exit_output_error);
  const std::string said = read_text(removed + ".out");
  EXPECT_NE(said.find("error: cannot start "), std::string::npos) << said;
  EXPECT_NE(said.find("suspend-installed: No such file or directory: no more points are started"), std::string::npos)
      << said;
  EXPECT_EQ(statuses(removed)["failed"], 0);
  EXPECT_GE(statuses(removed)["pending"], 1);
  ASSERT_EQ(run({"sweep", file, "--out", removed, "--jobs", "2", "--quiet"}).code, 0);
  EXPECT_EQ(statuses(removed)["done"] + statuses(removed)["jammed"], 15);
}

TEST(Sweep, TheSearchBisectsToTheBoundaryWithSeeds) {
  const std::string body = "case: " + restart_case +
                           "\nset: {particles.count: 40, run.strain: 0.3, run.average_from: 0, flow.control: stress, "
                           "flow.shear_stress: 1, run.jammed.viscosity: 3, run.jammed.strain: 0.01}\n";
  const std::string file =
      write_case("search.yaml", body + "search: {key: particles.phi, lo: 0.1, hi: 0.5, tolerance: 0.05, seeds: 3}\n");
  const std::string one = fresh_dir("search_one"), two = fresh_dir("search_two"), killed = fresh_dir("search_kill");
  const Result r = run({"sweep", file, "--out", two, "--jobs", "2"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("converged, bracket [0.3, 0.35]"), std::string::npos) << r.out;
  const json t = table(two);
  ASSERT_EQ(t["points"].size(), 15u) << "5 values x 3 seeds";
  std::map<double, std::pair<int, int>> at;  // phi -> (flowed, jammed)
  for (const json& p : t["points"]) {
    auto& [flowed, jammed] = at[p["case"]["phi"].get<double>()];
    (p["status"] == "done" ? flowed : jammed) += 1;
  }
  EXPECT_EQ((std::vector<double>{0.1, 0.3, 0.35, 0.4, 0.5}), [&] {
    std::vector<double> v;
    for (const auto& [phi, counts] : at) v.push_back(phi);
    return v;
  }());
  EXPECT_GE(at[0.3].first, 2);
  EXPECT_GE(at[0.35].second, 2);
  const Result again = run({"sweep", file, "--out", two});
  EXPECT_EQ(again.code, 0);
  EXPECT_EQ(again.out.find("start "), std::string::npos) << "a finished search runs nothing: " << again.out;
  EXPECT_EQ(table(two), t);
  const Result list = run({"sweep", file, "--out", two, "--list"});
  EXPECT_NE(list.out.find("base: converged, bracket [0.3, 0.35]"), std::string::npos) << list.out;

  ASSERT_EQ(run({"sweep", file, "--out", one, "--jobs", "1", "--quiet"}).code, 0);
  EXPECT_EQ(table(one), t);
  const pid_t pid = spawn({"sweep", file, "--out", killed, "--jobs", "1", "--quiet"}, killed + ".err", true);
  while (!fs::exists(killed + "/points/phi0.3_seed1/summary.json")) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  kill(-pid, SIGKILL);
  wait_exit(pid);
  ASSERT_EQ(run({"sweep", file, "--out", killed, "--jobs", "2", "--quiet"}).code, 0);
  EXPECT_EQ(table(killed), t);

  // from_flowing: 0.03: the point at 0.32 starts from its seed's last state at 0.3 when that seed flowed there,
  // rescaled to 0.32 (0.35 is too far from 0.3 and starts from a packing).
  const std::string dense = write_case(
      "from_flowing.yaml",
      body + "search: {key: particles.phi, lo: 0.3, hi: 0.4, tolerance: 0.02, seeds: 3, from_flowing: 0.03}\n");
  const std::string fd = fresh_dir("search_from_flowing");
  const Result rd = run({"sweep", dense, "--out", fd, "--jobs", "2"});
  ASSERT_EQ(rd.code, 0) << rd.err;
  int rescaled = 0;
  const json td = table(fd);
  for (const json& p : td["points"]) {
    const bool from_file = p["parameters"].contains("particles.initial");
    const std::string log = read_text(fd + "/points/" + p["name"].get<std::string>() + "/log.txt");
    EXPECT_EQ(from_file, log.find("rescaled by") != std::string::npos) << p["name"] << log.substr(0, 300);
    if (from_file) {
      ++rescaled;
      EXPECT_EQ(p["case"]["phi"], 0.32) << p.dump();
      EXPECT_NE(log.find("from phi 0.3"), std::string::npos) << log.substr(0, 300);
      // its case names the seed's point at 0.3 and the size of the packing it descends from, as the fresh points do
      const std::string name = p["name"];
      EXPECT_EQ(p["case"]["started_from"], "phi0.3_seed" + name.substr(name.rfind("seed") + 4)) << p.dump();
      EXPECT_EQ(p["case"]["count"], 40) << p.dump();
    }
  }
  EXPECT_GE(rescaled, 2) << "the seeds that flowed at 0.3 start 0.32 from there";
  // Restored from its table into a folder without the runs (tools/restore_campaign.py, a new machine), the search
  // runs nothing and lists the same points with the same starts (point.json keeps what a point started from).
  const std::string restored = fresh_dir("search_from_flowing_restored");
  const std::string restore = "/usr/bin/python3 " SUSPEND_SOURCE_DIR "/tools/restore_campaign.py " + fd +
                              "/campaign.json " + restored + " > /dev/null";
  ASSERT_EQ(std::system(restore.c_str()), 0) << restore;
  const Result rr = run({"sweep", dense, "--out", restored});
  ASSERT_EQ(rr.code, 0) << rr.err;
  EXPECT_EQ(rr.out.find("start "), std::string::npos) << rr.out;
  EXPECT_EQ(table(restored)["points"], td["points"]);

  // flows: above, the yield-stress direction (flow.shear_stress at fixed phi): a value flows above the boundary and
  // jams below it. Searched here on the classifier's own threshold at phi 0.3, where eta_r is about 3: a point flows
  // when run.jammed.viscosity lies above its viscosity.
  std::string unset = body;
  unset.erase(unset.find("run.jammed.viscosity: 3, "), std::string("run.jammed.viscosity: 3, ").size());
  const std::string above = write_case("above.yaml", unset + "vary: {particles.phi: [0.3]}\nsearch: {key: "
                                                            "run.jammed.viscosity, lo: 1, hi: 9, tolerance: 1, "
                                                            "flows: above}\n");
  const std::string ad = fresh_dir("search_above");
  const Result ra = run({"sweep", above, "--out", ad, "--jobs", "2"});
  ASSERT_EQ(ra.code, 0) << ra.err;
  EXPECT_NE(ra.out.find("converged, bracket ["), std::string::npos) << ra.out;
  EXPECT_NE(ra.out.find("(flows above)"), std::string::npos) << ra.out;
  double lowest_flowing = 1e9, highest_jammed = 0.0, eta_r = 0.0;
  const json ta = table(ad);
  for (const json& p : ta["points"]) {
    const double v = p["parameters"]["run.jammed.viscosity"].get<double>();
    if (p["status"] == "done" && v < lowest_flowing) lowest_flowing = v, eta_r = p["summary"]["eta_r"]["mean"];
    if (p["status"] != "done") highest_jammed = std::max(highest_jammed, v);
  }
  EXPECT_GE(highest_jammed, 1.0);  // both sides were seen
  EXPECT_LE(lowest_flowing - highest_jammed, 1.0 + 1e-9);
  // the bracket holds the viscosity that the flowing point measured
  EXPECT_GT(eta_r, highest_jammed);
  EXPECT_LT(eta_r, lowest_flowing);

  const std::string below = write_case("below.yaml", body + "search: {key: particles.phi, lo: 0.4, hi: 0.5, "
                                                            "tolerance: 0.02}\n");
  const Result b = run({"sweep", below, "--out", fresh_dir("search_below")});
  EXPECT_EQ(b.code, 0) << b.err;
  EXPECT_NE(b.out.find("below lo: particles.phi = 0.4 already jams"), std::string::npos) << b.out;
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"lo: 0.5, hi: 0.1, tolerance: 0.05", "search: lo = 0.5 must be below hi = 0.1"},
      {"lo: 0.1, hi: 0.5, tolerance: 0.05, seeds: 0", "search.seeds: must be a whole number from 1 to 100, not 0"},
      {"lo: 0.1, hi: 0.5, tolerance: -1", "search.tolerance: must be > 0"},
      {"lo: 0.1, hi: 0.5, toleranse: 0.1", "search.toleranse: unknown key (did you mean 'tolerance'?)"},
      {"lo: 0.1, hi: 0.5, tolerance: 0.05, flows: sideways", "search.flows: 'sideways' is not allowed"},
      {"lo: 0.1, hi: 0.5, tolerance: 0.05, flows: above, from_flowing: 0.03",
       "search.from_flowing: only with flows: below"}};
  for (const auto& [fields, message] : bad)
    expect_input_error(
        {"sweep", write_case("bad_search.yaml", body + "search: {key: particles.phi, " + fields + "}\n"), "--list"},
        message, "");
}

TEST(Sweep, ChangedCampaignIsRefusedAddedPointsRun) {
  const std::string dir = fresh_dir("sweep_changed");
  ASSERT_EQ(run({"sweep", campaign("c1.yaml"), "--out", dir, "--quiet"}).code, 0);
  const std::string changed = write_case(
      "c2.yaml", "case: " + restart_case + "\nset: {run.strain: " + strain +
                     ", particles.count: 60}\nvary:\n  particles.phi: [0.40, 0.45]\npoints:\n"
                     "  - {particles.phi: 0.5, contact.mu: 0.6}\n");
  expect_input_error({"sweep", changed, "--out", dir}, "point phi0.5_mu0.5", "");
  const std::string seed = write_case(
      "c3.yaml", "case: " + restart_case + "\nset: {run.strain: " + strain + ", particles.count: 60, run.seed: 9}\n"
                 "vary:\n  particles.phi: [0.40, 0.45]\npoints:\n  - {particles.phi: 0.5, contact.mu: 0.5}\n");
  expect_input_error({"sweep", seed, "--out", dir}, "run.seed 3 -> 9", "");
  // --status refuses what the sweep would, so that a changed campaign is caught before a queue of sweeps runs
  // (tools/resume_campaigns.sh), and records nothing.
  const std::string recorded = read_text(dir + "/sweep.json");
  expect_input_error({"sweep", seed, "--out", dir, "--status"}, "run.seed 3 -> 9", "");
  EXPECT_EQ(read_text(dir + "/sweep.json"), recorded);
  // A point recorded by an older version without a key its resolved form has since gained (with the value the old
  // form implied) is the same point, not a changed campaign.
  json record = json::parse(read_text(dir + "/sweep.json"));
  std::string old_form = record["points"]["phi0.40"].get<std::string>();
  const std::size_t friction = old_form.find("  friction: coulomb\n");
  ASSERT_NE(friction, std::string::npos) << old_form;
  record["points"]["phi0.40"] = old_form.erase(friction, std::string("  friction: coulomb\n").size());
  std::ofstream(dir + "/sweep.json") << record.dump(1);
  const std::string added = campaign("c4.yaml", "  - {particles.phi: 0.42}\n");
  const Result r = run({"sweep", added, "--out", dir, "--quiet"});
  ASSERT_EQ(r.code, 0) << r.err;
  const json t = table(dir);
  ASSERT_EQ(t["points"].size(), 4u);
  EXPECT_EQ(t["points"][3]["name"], "phi0.42");
  EXPECT_EQ(t["points"][3]["status"], "done");
  expect_input_error({"sweep", campaign("c5.yaml"), "--out", dir, "--point", "phi0.99"}, "--point", "");
  expect_input_error({"sweep", write_case("c6.yaml", "case: " + restart_case + "\nvary: {particles.phi: [0.4, 0.9]}\n"),
                      "--out", fresh_dir("sweep_bad")},
                     "point phi0.9: particles.phi", fresh_dir("sweep_bad"));
  expect_input_error({"sweep", write_case("c7.yaml", "case: " + restart_case + "\nvary: {particles.phi: 0.4}\n"),
                      "--out", dir},
                     "vary.particles.phi: must be a non-empty list", "");
  expect_input_error({"sweep", write_case("c8.yaml", "case: " + restart_case + "\nvaryy: {}\n"), "--out", dir},
                     "did you mean 'vary'", "");
}

TEST(Sweep, CampaignFilesMeanExactlyWhatTheySay) {
  const std::string head = "case: " + restart_case + "\n";
  auto refused = [&](const std::string& name, const std::string& body, const std::string& fragment) {
    const auto t0 = std::chrono::steady_clock::now();
    expect_input_error({"sweep", write_case(name, head + body), "--list"}, fragment, "");
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(10)) << name << " took long to refuse";
  };
  refused("same_key.yaml", "set: {particles.phi: 0.4}\nvary: {particles.phi: [0.40, 0.45]}\n",
          "set.particles.phi: also varied");
  refused("empty_vary.yaml", "vary: []\n", "vary: an empty list");
  // A hand-edited table: `suspend phim` names the file, not the JSON library's complaint alone.
  const std::string edited = fresh_dir("edited_table");
  fs::create_directories(edited);
  std::ofstream(edited + "/campaign.json") << R"({"points": [{"name": 3}]})";
  expect_input_error({"phim", edited}, edited + "/campaign.json has a point with a missing or mistyped field", "");
  refused("one_folder.yaml", "points:\n  - {run.seed: 1}\n  - {run.seed: 1}\n", "the same parameters given twice");
  refused("huge.yaml",
          "vary: {run.seed: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10], particles.phi: [0.40, 0.41, 0.42, 0.43, 0.44, 0.45, 0.46, "
          "0.47, 0.48, 0.49], run.strain: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10], contact.mu: [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, "
          "0.7, 0.8, 0.9, 1.0], run.average_from: [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95]}\n",
          "has 100000 points; a campaign holds at most 20000");
}

TEST(Sweep, StoppedFlowEndsJammedAndBudgetEndsFailed) {
  const std::string dir = fresh_dir("sweep_jam");
  // Imposed stress 1 on a suspension of viscosity ~10: with run.jammed.viscosity = 3 its mean rate (~0.1) is below
  // the threshold 1/3, so it ends as jammed after the first window (0.01 strain at that viscosity).
  const std::string file = write_case(
      "jam.yaml", "case: " + restart_case + "\nset: {particles.count: 60, flow.control: stress, flow.shear_stress: 1, "
                  "run.jammed.viscosity: 3, run.jammed.strain: 0.01}\npoints:\n  - {run.strain: 5}\n");
  const Result r = run({"sweep", file, "--out", dir, "--quiet"});
  EXPECT_EQ(r.code, 0) << r.err;
  const json t = table(dir);
  EXPECT_EQ(t["points"][0]["status"], "jammed");
  EXPECT_EQ(t["points"][0]["summary"]["status"], "jammed");
  EXPECT_LT(t["points"][0]["summary"]["jammed"]["mean_shear_rate"].get<double>(), 1.0 / 3.0);
  EXPECT_NE(t["points"][0]["message"].get<std::string>().find("jammed"), std::string::npos);
  // A flow that stops long before the jamming window closes (3 / 2e-5 time units) trips the no-progress guard
  // first: under imposed stress, with its mean rate (~2e-6) below Sigma / run.jammed.viscosity, that is a jam too.
  const std::string stalled = fresh_dir("run_stalled");
  const Result s = run({"run", restart_case, "--set", "particles.count=60", "--set", "flow.control=stress", "--set",
                        "flow.shear_stress=2e-5", "--set", "run.jammed.viscosity=3", "--set", "run.jammed.strain=1",
                        "--set", "run.strain=5", "--out", stalled, "--quiet"});
  EXPECT_EQ(s.code, 4) << s.err;
  EXPECT_NE(s.err.find("jammed: the mean shear rate"), std::string::npos) << s.err;
  const json ss = json::parse(read_text(stalled + "/summary.json"));
  EXPECT_EQ(ss["status"], "jammed");
  EXPECT_LT(ss["jammed"]["mean_shear_rate"].get<double>(), 2e-5 / 3.0);

  const std::string slow = fresh_dir("sweep_budget");
  const std::string long_case = write_case("long.yaml", "case: " + restart_case + "\nset: {run.strain: 50}\n");
  const Result b = run({"sweep", long_case, "--out", slow, "--quiet", "--point-seconds", "1"});
  EXPECT_EQ(b.code, 3) << b.err;
  json tb = table(slow);
  EXPECT_EQ(tb["points"][0]["status"], "failed");
  EXPECT_NE(tb["points"][0]["message"].get<std::string>().find("budget"), std::string::npos);
  EXPECT_TRUE(fs::exists(slow + "/points/base/checkpoint.h5"));
  EXPECT_EQ(run({"sweep", long_case, "--out", slow, "--quiet"}).code, 3) << "failed points are kept, not rerun";
  EXPECT_EQ(table(slow)["points"][0]["status"], "failed");
  // Restored from its table on a new machine, the failed point still waits for --retry-failed, with its message.
  const std::string restored = fresh_dir("sweep_budget_restored");
  const std::string restore = "/usr/bin/python3 " SUSPEND_SOURCE_DIR "/tools/restore_campaign.py " + slow +
                              "/campaign.json " + restored + " > /dev/null";
  ASSERT_EQ(std::system(restore.c_str()), 0) << restore;
  EXPECT_EQ(run({"sweep", long_case, "--out", restored, "--quiet"}).code, 3) << "a restored failure is not rerun";
  EXPECT_EQ(table(restored)["points"][0]["message"], tb["points"][0]["message"]);
  EXPECT_FALSE(fs::exists(restored + "/points/base/run.h5"));
  EXPECT_EQ(run({"sweep", long_case, "--out", slow, "--quiet", "--retry-failed", "--point-seconds", "1"}).code, 3);
  EXPECT_NE(read_text(slow + "/points/base/point.json").find("\"runs\": 2"), std::string::npos);
}

TEST(Sweep, MpiRanksGiveTheSameTable) {
  if (std::system("command -v mpirun > /dev/null 2>&1") != 0) GTEST_SKIP() << "no mpirun (Debian openmpi-bin)";
  const std::string file = campaign("mpi.yaml");
  const std::string a = fresh_dir("mpi_a"), b = fresh_dir("mpi_b");
  ASSERT_EQ(run({"sweep", file, "--out", a, "--jobs", "2", "--quiet"}).code, 0);
  // mpirun refuses root unless told; --oversubscribe: three ranks on a two-core machine.
  const std::string command = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe -n 3 " +
                              suspend_bin + " sweep " + file + " --out " + b + " --quiet > " + b + ".log 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << read_text(b + ".log");
  EXPECT_EQ(table(b), table(a));
  // A boundary search under MPI: the dispatcher replans as points end and hands out the next values.
  const std::string search = write_case(
      "mpi_search.yaml", "case: " + restart_case +
                             "\nset: {particles.count: 40, run.strain: 0.3, run.average_from: 0, flow.control: stress, "
                             "flow.shear_stress: 1, run.jammed.viscosity: 3, run.jammed.strain: 0.01}\n"
                             "search: {key: particles.phi, lo: 0.1, hi: 0.5, tolerance: 0.05, seeds: 2}\n");
  const std::string sa = fresh_dir("mpi_search_a"), sb = fresh_dir("mpi_search_b");
  ASSERT_EQ(run({"sweep", search, "--out", sa, "--jobs", "2", "--quiet"}).code, 0);
  const std::string searched = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe -n 3 " +
                               suspend_bin + " sweep " + search + " --out " + sb + " --quiet > " + sb + ".log 2>&1";
  ASSERT_EQ(std::system(searched.c_str()), 0) << read_text(sb + ".log");
  EXPECT_EQ(table(sb), table(sa));
  EXPECT_EQ(table(sa)["points"].size(), 10u) << "0.1, 0.5, 0.3, 0.4, 0.35 x 2 seeds";
}
