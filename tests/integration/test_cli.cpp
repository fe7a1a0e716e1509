// The `suspend` program as users run it: bad input exits with code 2 and one line, writing nothing; a run killed
// with SIGKILL and restarted from its checkpoint ends bit for bit where an unbroken run ends; SIGINT checkpoints
// and stops cleanly.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io/case.hpp"
#include "io/checkpoint.hpp"
#include "io/hdf5.hpp"
#include "io/run_file.hpp"
#include "tests/integration/cli_support.hpp"

extern char** environ;
namespace fs = std::filesystem;
using namespace suspend::io;
using namespace suspend::test;

namespace {
const std::string restart_case = SUSPEND_SOURCE_DIR "/tests/data/restart_case.yaml";
#ifdef NDEBUG
const std::vector<std::string> lighter;  // Release: the case as written
constexpr double kill_strain = 0.1;
#else
// Debug + sanitizers run about 30x slower: the same case, smaller and shorter, still killed mid-run.
const std::vector<std::string> lighter = {"--set", "particles.count=50", "--set", "run.strain=0.2"};
constexpr double kill_strain = 0.05;
#endif
std::vector<std::string> plus(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}
std::vector<std::string> with_lighter(std::vector<std::string> args) { return plus(std::move(args), lighter); }
// A short restart-case run of 50 spheres on one thread, for the tests that run it several times.
std::vector<std::string> small(std::vector<std::string> args, const std::string& average_from) {
  return plus(std::move(args), {"--threads", "1", "--quiet", "--set", "particles.count=50", "--set",
                                "run.average_from=" + average_from});
}

}  // namespace

TEST(Cli, VersionAndHelp) {
  const Result v = run({"--version"});
  EXPECT_EQ(v.code, 0);
  EXPECT_EQ(run({"run", "--help"}).code, 0);
  EXPECT_EQ(run({"check", "--help"}).code, 0);
}

TEST(Cli, BadInputExitsWithTwoAndWritesNothing) {
  const std::string out = fresh_dir("bad_out");
  expect_input_error({"run", restart_case, "--out", out, "--set", "particles.phii=0.3"},
                     "particles.phii: unknown key; did you mean 'phi'?", out);
  expect_input_error({"run", restart_case, "--out", out, "--set", "particles.phi=lots"},
                     "particles.phi: 'lots' is not a number", out);
  expect_input_error({"run", restart_case, "--out", out, "--set", "particles.phi=0.8"}, "out of range", out);
  expect_input_error({"run", restart_case, "--out", out, "--set", "particles.phi=0.72"}, "unreachable", out);
  expect_input_error({"run", restart_case, "--out", out, "--set", "particles.bidisperse.size_ratio=-1.4"},
                     "particles.bidisperse.size_ratio: -1.4 is out of range", out);
  expect_input_error({"run", "/nonexistent/case.yaml", "--out", out}, "case file not found", out);
  expect_input_error({"run", restart_case, "--out", out, "--restart", "/nonexistent/checkpoint.h5"},
                     "--restart", "");
  expect_input_error({"check", write_case("broken.yaml", "particles: [1, 2\n")}, "not valid YAML", "");
  expect_input_error({"run", restart_case, "--out", out, "--threads", "0"}, "threads", out);
  expect_input_error({"run", restart_case, "--out", out, "--set", "particles.phi.=0.45"}, "ends with a dot", out);
  expect_input_error({"run", write_case("two_docs.yaml", "particles: {phi: 0.4, count: 50}\n---\nrun: {strain: 1}\n"),
                      "--out", out},
                     "holds 2 YAML documents", out);
  expect_input_error({"run", scratch(), "--out", out}, "is a directory", out);
  expect_input_error({"run", "/dev/null", "--out", out}, "not a regular file", out);
  expect_input_error({"--bogus"}, "--bogus: unknown option; suspend takes a subcommand first (run,", "");
  // yaml-cpp would swallow the rest of the file into an unclosed quote ("particles.phi: missing").
  expect_input_error({"check", write_case("quote.yaml", "title: \"abc\nparticles: {phi: 0.1, count: 10}\n")},
                     "title: the quoted text opened at line 1, column 8 is never closed", "");
  expect_input_error({"run", restart_case, "--out", out, "--set", "title=" + std::string(70000, 'a')},
                     "title: 70000 characters; at most 1000 are allowed", out);
  // What cannot run is refused before anything is allocated or written: no std::bad_alloc, no run that never ends.
  expect_input_error({"run", restart_case, "--out", out, "--set", "particles.count=", "--set", "box.cube=2000"},
                     "box: 5.863e+08 particles need at least 1.2 TB of memory", out);
  expect_input_error({"run", restart_case, "--out", out, "--set", "hydrodynamics.model=fcm", "--set",
                      "hydrodynamics.fcm.grid_spacing=0.001"},
                     "hydrodynamics.fcm.grid_spacing: a grid of", out);
  expect_input_error({"run", restart_case, "--out", out, "--set", "run.time_step={mode: fixed, fixed: 1e-300}"},
                     "run.strain = 0.5 cannot be reached: with run.time_step.fixed = 1e-300", out);
  expect_input_error({"run", restart_case, "--out", out, "--set", "contact.k_hat=1e308", "--set",
                      "run.time_step.contacts=explicit"},
                     "cannot be reached: with explicit contacts of stiffness 1e+308 (set by contact.k_hat)", out);
  expect_input_error({"run", restart_case, "--out", out, "--set", "flow.shear_rate=1e-12", "--set",
                      "run.time_step={mode: fixed, fixed: 1e-3}"},
                     "at flow.shear_rate = 1e-12, a step advances the strain by at most 1e-15", out);
  // A species that gets no sphere is refused, not dropped (2fbb67f ran 12 small spheres at phi 0.23 here).
  expect_input_error({"run", restart_case, "--out", out, "--set", "particles.count=null", "--set", "box={cube: 6}",
                      "--set", "particles.bidisperse.size_ratio=4"},
                     "box: no sphere of species 1 (radius 4, volume share 0.5) fits", out);
  expect_input_error({"check", restart_case, "--set", "particles.count=null", "--set", "box={cube: 6}", "--set",
                      "particles.bidisperse.size_ratio=4"},
                     "box: no sphere of species 1", "");
  // A flow mapping without the space after a colon is keys without values, never the default silently taken.
  expect_input_error({"run", restart_case, "--out", out, "--set", "particles.initial={from:file, file: x.h5}"},
                     "particles.initial.from:file: not a key; write 'from: file'", out);
  const std::string file = write_case("a_file", "");
  expect_input_error({"run", restart_case, "--out", file + "/run"}, "--out: cannot create the directory", "");
  expect_input_error({"run", restart_case, "--out", out, "--set", "hydrodynamics.model=fcm", "--set",
                      "hydrodynamics.fcm.cache_dir=" + file + "/cache"},
                     "hydrodynamics.fcm.cache_dir: cannot create the directory", out);
}

// Two runs into one folder (issue 37, item 2), with HDF5's own file locking off as on many clusters: the second is
// refused with exit 2 naming the process that holds the folder, and the first ends as if alone (2fbb67f: the second
// crashed with an HDF5 error, or both wrote and the folder mixed two runs).
TEST(Cli, TwoRunsIntoOneFolderTheSecondIsRefused) {
  setenv("HDF5_USE_FILE_LOCKING", "FALSE", 1);
  const std::string a = fresh_dir("one_folder"), alone = fresh_dir("alone");
  const std::vector<std::string> args = {"run", restart_case, "--threads", "1", "--quiet", "--set", "run.strain=0.3"};
  const pid_t first = spawn(plus(args, {"--out", a}), a + ".err");
  while (!fs::exists(a + "/run.h5")) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  const Result second = run(plus(args, {"--out", a}));
  const Result restart = run(plus(args, {"--restart", a + "/checkpoint.h5", "--set", "run.strain=1"}));
  ASSERT_EQ(wait_exit(first), 0) << read_text(a + ".err");
  EXPECT_EQ(second.code, 2);
  EXPECT_NE(second.err.find("is in use by process " + std::to_string(first)), std::string::npos) << second.err;
  EXPECT_EQ(restart.code, 2) << restart.err;
  ASSERT_EQ(run(plus(args, {"--out", alone})).code, 0);
  nlohmann::json sa = nlohmann::json::parse(read_text(a + "/summary.json")),
                 sb = nlohmann::json::parse(read_text(alone + "/summary.json"));
  sa.erase("wall_seconds");
  sb.erase("wall_seconds");
  EXPECT_EQ(sa, sb);
  unsetenv("HDF5_USE_FILE_LOCKING");
}

TEST(Cli, CheckPrintsTheResolvedCaseWithDerivedValues) {
  const Result r = run({"check", restart_case});
  EXPECT_EQ(r.code, 0) << r.err;
}

TEST(Cli, CheckNamesSpeciesPairsWithoutAnExactTable) {
  // Exact near fields exist for the size ratios 1 and 1.4 only: a 1 : 2 suspension is told which pairs keep the
  // singular terms, a 1 : 1.4 one is not.
  const std::vector<std::string> fcm = {"check", restart_case, "--set", "hydrodynamics.model=fcm"};
  std::vector<std::string> two = fcm, one_four = fcm;
  two.insert(two.end(), {"--set", "particles.bidisperse.size_ratio=2"});
  one_four.insert(one_four.end(), {"--set", "particles.bidisperse.size_ratio=1.4"});
  const Result r2 = run(two), r14 = run(one_four);
  ASSERT_EQ(r2.code, 0) << r2.err;
  ASSERT_EQ(r14.code, 0) << r14.err;
  EXPECT_NE(r2.out.find("# note: species pair of radii 1 and 2 (lambda = 2): no exact two-sphere table"),
            std::string::npos) << r2.out;
  EXPECT_EQ(r2.out.find("radii 1 and 1 "), std::string::npos);
  EXPECT_EQ(r14.out.find("# note:"), std::string::npos) << r14.out;
}

TEST(Cli, KilledAndRestartedRunEndsBitIdentical) {
  const std::string a = fresh_dir("restart_a"), b = fresh_dir("restart_b");
  ASSERT_EQ(run(with_lighter({"run", restart_case, "--out", a, "--threads", "2", "--quiet"})).code, 0);

  // Run B is killed with SIGKILL as soon as its second checkpoint exists, mid-run.
  const pid_t pid = spawn(with_lighter({"run", restart_case, "--out", b, "--threads", "2", "--quiet"}), b + ".err");
  const auto t0 = std::chrono::steady_clock::now();
  bool killed = false;
  while (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60)) {
    if (fs::exists(b + "/checkpoint.h5")) {
      try {
        suspend::io::h5::File f = suspend::io::h5::File::open(b + "/checkpoint.h5", false);
        if (suspend::io::h5::double_attribute(f.id(), ".", "strain") >= kill_strain) {
          kill(pid, SIGKILL);
          killed = true;
          break;
        }
      } catch (const std::exception&) {
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const int code = wait_exit(pid);
  ASSERT_TRUE(killed);
  ASSERT_EQ(code, 128 + SIGKILL) << "the run finished before it could be killed: make the case longer";
  EXPECT_FALSE(fs::exists(b + "/summary.json"));

  const Result r = run(with_lighter({"run", restart_case, "--restart", b + "/checkpoint.h5", "--threads", "2", "--quiet"}));
  ASSERT_EQ(r.code, 0) << r.err;

  h5::File fa = h5::File::open(a + "/checkpoint.h5", false), fb = h5::File::open(b + "/checkpoint.h5", false);
  for (const char* d : {"particles/position", "particles/velocity", "particles/angular_velocity"})
    EXPECT_EQ(h5::read_doubles(fa.id(), d), h5::read_doubles(fb.id(), d)) << d;
  EXPECT_EQ(h5::int_attribute(fa.id(), ".", "step"), h5::int_attribute(fb.id(), ".", "step"));
  h5::File ra = h5::File::open(a + "/run.h5", false), rb = h5::File::open(b + "/run.h5", false);
  for (const char* s : {"strain", "eta_r", "Pi", "stress/contact_normal"})
    EXPECT_EQ(read_series(ra.id(), s), read_series(rb.id(), s)) << s;
  // ParaView's view of the run: the XDMF parses as XML and names only datasets that exist, with their shapes.
  const int xdmf = std::system(("/usr/bin/python3 " SUSPEND_SOURCE_DIR "/tools/check_xdmf.py " + b + "/run.xdmf").c_str());
  EXPECT_EQ(xdmf, 0);
  // The same summary, but for the invocation's wall time.
  auto without_wall_time = [](const std::string& text) {
    std::stringstream in(text), out;
    for (std::string line; std::getline(in, line);)
      if (line.find("\"wall_seconds\"") == std::string::npos) out << line << '\n';
    return out.str();
  };
  EXPECT_EQ(without_wall_time(read_text(a + "/summary.json")), without_wall_time(read_text(b + "/summary.json")));
}

// A checkpoint continued into a new folder (--out without run.h5) goes on exactly as in its own folder; the new
// run.h5 starts at the checkpoint, the old folder is left alone (the way on after a full disk damaged run.h5).
TEST(Cli, RestartIntoANewFolderContinuesTheSameWay) {
  const std::string c = fresh_dir("branch_c"), d = fresh_dir("branch_d");
  auto with = [](std::vector<std::string> args) { return small(std::move(args), "0.05"); };
  ASSERT_EQ(run(with({"run", restart_case, "--out", c, "--set", "run.strain=0.1"})).code, 0);
  const std::size_t rows_before = [&] {
    h5::File f = h5::File::open(c + "/run.h5", false);
    return read_series(f.id(), "strain").size();
  }();
  const Result r = run(with({"run", restart_case, "--restart", c + "/checkpoint.h5", "--out", d, "--set", "run.strain=0.2"}));
  ASSERT_EQ(r.code, 0) << r.err;
  const Result in_place = run(with({"run", restart_case, "--restart", c + "/checkpoint.h5", "--set", "run.strain=0.2"}));
  ASSERT_EQ(in_place.code, 0) << in_place.err;
  h5::File fc = h5::File::open(c + "/checkpoint.h5", false), fd = h5::File::open(d + "/checkpoint.h5", false);
  EXPECT_EQ(h5::read_doubles(fc.id(), "particles/position"), h5::read_doubles(fd.id(), "particles/position"));
  h5::File rc = h5::File::open(c + "/run.h5", false), rd = h5::File::open(d + "/run.h5", false);
  const std::vector<double> strain_c = read_series(rc.id(), "strain"), strain_d = read_series(rd.id(), "strain");
  ASSERT_GT(strain_c.size(), rows_before);
  ASSERT_FALSE(strain_d.empty());
  EXPECT_GE(strain_d.front(), 0.1 - 1e-9);  // the new record starts at the checkpoint
  EXPECT_EQ(std::vector<double>(strain_c.end() - static_cast<long>(strain_d.size()), strain_c.end()), strain_d);

  // d is now a finished run of its own: a restart of c may not continue into it (its series would be cut).
  const std::string d_record = read_text(d + "/run.h5"), d_summary = read_text(d + "/summary.json");
  expect_input_error(with({"run", restart_case, "--restart", c + "/checkpoint.h5", "--out", d, "--set",
                           "run.strain=0.3"}),
                     "holds another run", "");
  EXPECT_EQ(read_text(d + "/run.h5"), d_record);
  EXPECT_EQ(read_text(d + "/summary.json"), d_summary);
}

TEST(Cli, InterruptWritesACheckpointAndStopsCleanly) {
  const std::string c = fresh_dir("interrupt");
  const pid_t pid = spawn(with_lighter({"run", restart_case, "--out", c, "--threads", "1", "--quiet", "--set",
                                        "run.average_from=0.1"}),
                          c + ".err");
  const auto t0 = std::chrono::steady_clock::now();
  while (!fs::exists(c + "/checkpoint.h5") && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(pid, SIGINT);
  const int code = wait_exit(pid);
  ASSERT_EQ(code, 128 + SIGINT) << "the run must stop on SIGINT with 130";
  std::ifstream err(c + ".err");
  std::stringstream s;
  s << err.rdbuf();
  EXPECT_NE(s.str().find("--restart"), std::string::npos) << s.str();
  EXPECT_TRUE(fs::exists(c + "/run.xdmf"));
  // What it did is summarised, marked as stopped.
  EXPECT_NE(read_text(c + "/summary.json").find("\"status\": \"stopped\""), std::string::npos);
  // The printed command continues the run as it is: with its --set overrides and its thread count.
  const std::string said = s.str();
  const auto at = said.find("continue with: suspend ");
  ASSERT_NE(at, std::string::npos) << said;
  const std::string command = said.substr(at + std::string("continue with: suspend ").size());
  EXPECT_NE(command.find("--set run.average_from=0.1"), std::string::npos) << command;
  EXPECT_NE(command.find(" --threads 1"), std::string::npos) << command;
  const int continued = std::system((suspend_bin + " " + command.substr(0, command.find('\n')) +
                                     " --quiet > /dev/null 2>&1").c_str());
  EXPECT_EQ(continued, 0) << command;
  EXPECT_NE(read_text(c + "/summary.json").find("\"status\": \"done\""), std::string::npos);
  EXPECT_TRUE(fs::exists(c + "/summary.json"));
}

TEST(Cli, RestartFromAnotherCaseIsRefused) {
  const std::string c = fresh_dir("other_case");
  ASSERT_EQ(run({"run", restart_case, "--out", c, "--quiet", "--set", "run.strain=0.05", "--set", "run.average_from=0"}).code, 0);
  expect_input_error({"run", restart_case, "--restart", c + "/checkpoint.h5", "--set", "contact.mu=0.5"},
                     "belongs to another case (contact.mu 1 -> 0.5)", "");
}

TEST(Cli, QuietPrintsNothingAndTheFinalStateIsASnapshot) {
  // run.strain 0.3 is not a multiple of snapshot_every 0.25: the final state is a third snapshot all the same.
  const std::string c = fresh_dir("quiet");
  const Result r = run(with_lighter({"run", restart_case, "--out", c, "--quiet", "--set", "run.output.snapshot_every=0.25",
                                     "--set", "run.strain=0.3"}));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "") << "--quiet prints nothing";
  EXPECT_EQ(r.err, "");
  h5::File f = h5::File::open(c + "/run.h5", false);
  ASSERT_TRUE(h5::exists(f.id(), "snapshots/000002"));
  EXPECT_FALSE(h5::exists(f.id(), "snapshots/000003"));
  h5::File cp = h5::File::open(c + "/checkpoint.h5", false);
  EXPECT_NEAR(h5::double_attribute(f.id(), "snapshots/000002", "strain"), 0.3, 1e-12);
  // The checkpoint is the state before the last (clipped) step: at most one step before the final snapshot.
  EXPECT_LE(h5::double_attribute(cp.id(), ".", "strain"), 0.3);
  EXPECT_GT(h5::double_attribute(cp.id(), ".", "strain"), 0.25);
  const std::string summary = read_text(c + "/summary.json");
  EXPECT_NE(summary.find("\"status\": \"done\""), std::string::npos) << summary;
}

// The step trigger: a snapshot on every 7th step as well as every 0.25 of strain, each step written once.
TEST(Cli, SnapshotsEveryNStepsAsWellAsEveryStrainInterval) {
  const std::string c = fresh_dir("every_steps");
  const Result r = run(with_lighter({"run", restart_case, "--out", c, "--quiet", "--set", "run.output.snapshot_every=0.25",
                                     "--set", "run.output.snapshot_every_steps=7", "--set", "run.strain=0.3"}));
  ASSERT_EQ(r.code, 0) << r.err;
  h5::File f = h5::File::open(c + "/run.h5", false);
  std::int64_t last = -1;
  int by_step = 0;
  double first_past_quarter = 1.0, final_strain = 0.0;
  for (int k = 0; h5::exists(f.id(), snapshot_group(static_cast<std::size_t>(k))); ++k) {
    const std::int64_t step = h5::int_attribute(f.id(), snapshot_group(static_cast<std::size_t>(k)), "step");
    EXPECT_GT(step, last);  // each step once, in order
    last = step;
    if (step % 7 == 0) ++by_step;
    final_strain = h5::double_attribute(f.id(), snapshot_group(static_cast<std::size_t>(k)), "strain");
    if (final_strain >= 0.25) first_past_quarter = std::min(first_past_quarter, final_strain);
  }
  EXPECT_EQ(by_step, static_cast<int>(last / 7) + 1) << "every multiple of 7 up to the last snapshot's step";
  EXPECT_GT(by_step, 3);
  // The strain interval's snapshots stay: the first state at or past 0.25 (within a step of it) and the final state.
  EXPECT_LT(first_past_quarter, 0.251);
  EXPECT_NEAR(final_strain, 0.3, 1e-12);
}

TEST(Cli, OutputThatCannotBeWrittenIsAnError) {
  // `suspend check CASE > /dev/full`: the resolved case never reaches its reader, so the program does not succeed.
  const std::string err = scratch() + "/full_err.txt";
  EXPECT_EQ(wait_exit(spawn({"check", restart_case}, err, false, "/dev/full")), suspend::exit_output_error);
  const std::string text = read_text(err);
  EXPECT_EQ(text.rfind("error: writing the standard output failed", 0), 0u) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
}

TEST(Cli, ThreadsBeyondTheCoresAreCappedWithAWarning) {
  const std::string c = fresh_dir("threads");
  const Result r = run(with_lighter({"run", restart_case, "--out", c, "--quiet", "--threads", "4096", "--set",
                                     "run.strain=0.02", "--set", "run.average_from=0.01"}));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: 4096 threads asked for"), std::string::npos) << r.err;
}

TEST(Cli, ARunEndsWithWhatSetItsSteps) {
  const std::string c = fresh_dir("step_limits");
  const Result r = run(with_lighter({"run", restart_case, "--out", c, "--threads", "1", "--set", "run.strain=0.02",
                                     "--set", "run.average_from=0.01"}));
  ASSERT_EQ(r.code, 0) << r.err;
  // e.g. "steps set by: particles 60%, strain 40% (25 steps of this run)": the shares of the kinds of
  // dem/integrate/step_limit.hpp.
  const auto line = r.out.find("steps set by: ");
  ASSERT_NE(line, std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" steps of this run)", line), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("%", line), std::string::npos) << r.out;
}

TEST(Cli, ACheckpointEditedWithItsChecksumsRecomputedIsRefused) {
  // Checksums can be recomputed (write_checkpoint does): the particles themselves are checked against the case.
  const std::string c = fresh_dir("edited_checkpoint");
  ASSERT_EQ(run(small({"run", restart_case, "--out", c, "--set", "run.strain=0.02"}, "0.01")).code, 0);
  const Case the_case = load_case(restart_case, {"particles.count=50", "run.average_from=0.01", "run.strain=0.02"});
  Checkpoint cp = read_checkpoint(c + "/checkpoint.h5", physics_fingerprint(the_case));
  cp.state.particles.radius[7] *= 1.01;
  write_checkpoint(c + "/checkpoint.h5", cp);
  expect_input_error(small({"run", restart_case, "--restart", c + "/checkpoint.h5", "--set", "run.strain=0.04"}, "0.01"),
                     "particle 7 has radius", "");
}

TEST(Cli, CrossvalRefusesAFolderOfAnotherCase) {
  const std::string c = fresh_dir("crossval_other");
  const std::vector<std::string> tiny = {"--set", "particles.count=20", "--set", "particles.phi=0.1", "--set",
                                         "hydrodynamics.fcm.subgrid=false", "--set", "run.strain=0.02", "--set",
                                         "run.average_from=0", "--quiet", "--threads", "1"};
  std::vector<std::string> first = {"crossval", restart_case, "--out", c};
  first.insert(first.end(), tiny.begin(), tiny.end());
  const Result a = run(first);
  ASSERT_EQ(a.code, 0) << a.err;
  std::vector<std::string> other = first;
  other.insert(other.end(), {"--set", "run.seed=5"});
  const Result b = run(other);
  EXPECT_EQ(b.code, 2) << b.err;
  EXPECT_NE(b.err.find("holds a run of another case (run.seed 3 -> 5)"), std::string::npos) << b.err;
  EXPECT_EQ(run(first).code, 0) << "the same case is reused";
}

TEST(Cli, FailingRunKeepsTheStateBeforeTheFailingStep) {
  // A fixed time step of 1e308 (towards a run.strain as large, so that the last-step clipping leaves it alone)
  // throws every particle to infinity in one step: a numerical failure (exit 3), never a finished run; the checkpoint
  // holds the state before that step, which continues (and fails again) as it was.
  const std::string c = fresh_dir("non_finite");
  const std::vector<std::string> step = {"--set", "run.time_step={mode: fixed, fixed: 1.0e308}", "--set",
                                         "run.strain=1e308", "--quiet"};
  std::vector<std::string> args = {"run", restart_case, "--out", c};
  args.insert(args.end(), step.begin(), step.end());
  const Result r = run(args);
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("became non-finite at step 1"), std::string::npos) << r.err;
  EXPECT_NE(read_text(c + "/summary.json").find("\"status\": \"failed\""), std::string::npos);
  {
    h5::File cp = h5::File::open(c + "/checkpoint.h5", false);
    EXPECT_EQ(h5::int_attribute(cp.id(), ".", "step"), 0);
  }
  std::vector<std::string> again = {"run", restart_case, "--restart", c + "/checkpoint.h5"};
  again.insert(again.end(), step.begin(), step.end());
  const Result r2 = run(again);
  EXPECT_EQ(r2.code, 3) << "the checkpoint is readable and finite: " << r2.err;
}

TEST(Cli, TheLastStepEndsOnRunStrain) {
  // Steps of strain 0.03 towards run.strain = 0.1: three full steps and a last one of 0.01, never past 0.1.
  const std::string c = fresh_dir("last_step");
  const Result r = run({"run", restart_case, "--out", c, "--quiet", "--set", "particles.count=50", "--set",
                        "run.time_step={mode: fixed, fixed: 0.03}", "--set", "run.strain=0.1", "--set",
                        "run.average_from=0"});
  ASSERT_EQ(r.code, 0) << r.err;
  {
    h5::File f = h5::File::open(c + "/run.h5", false);
    EXPECT_NEAR(read_series(f.id(), "strain").back(), 0.1, 1e-12);
    EXPECT_EQ(read_series(f.id(), "strain").size(), 5u);  // strain 0, 0.03, 0.06, 0.09 and 0.1
    // The clipped step is the output's: the checkpoint is the state before it, so that a continuation takes the
    // full step there.
    h5::File cp = h5::File::open(c + "/checkpoint.h5", false);
    EXPECT_NEAR(h5::double_attribute(cp.id(), ".", "strain"), 0.09, 1e-12);
    EXPECT_EQ(h5::int_attribute(cp.id(), ".", "step"), 3);
  }
  const Result more = run({"run", restart_case, "--restart", c + "/checkpoint.h5", "--quiet", "--set",
                           "particles.count=50", "--set", "run.time_step={mode: fixed, fixed: 0.03}", "--set",
                           "run.strain=0.2", "--set", "run.average_from=0"});
  ASSERT_EQ(more.code, 0) << more.err;
  h5::File f = h5::File::open(c + "/run.h5", false);
  const std::vector<double> strain = read_series(f.id(), "strain");
  ASSERT_EQ(strain.size(), 8u);  // ... 0.09, 0.12, 0.15, 0.18, 0.2: the row at 0.1 was the first run's ending only
  EXPECT_NEAR(strain[4], 0.12, 1e-12);
  EXPECT_NEAR(strain.back(), 0.2, 1e-12);
}

TEST(Cli, AFinishedRunContinuedIsBitIdenticalToTheStraightRun) {
  // The adaptive step of the case: one run to strain 0.1 continued to 0.2 against one run straight to 0.2.
  const std::string a = fresh_dir("continued"), b = fresh_dir("straight");
  auto with = [](std::vector<std::string> args) { return small(std::move(args), "0.05"); };
  ASSERT_EQ(run(with({"run", restart_case, "--out", a, "--set", "run.strain=0.1"})).code, 0);
  ASSERT_EQ(run(with({"run", restart_case, "--restart", a + "/checkpoint.h5", "--set", "run.strain=0.2"})).code, 0);
  ASSERT_EQ(run(with({"run", restart_case, "--out", b, "--set", "run.strain=0.2"})).code, 0);
  h5::File ca = h5::File::open(a + "/checkpoint.h5", false), cb = h5::File::open(b + "/checkpoint.h5", false);
  EXPECT_EQ(h5::int_attribute(ca.id(), ".", "step"), h5::int_attribute(cb.id(), ".", "step"));
  for (const char* d : {"particles/position", "particles/velocity", "particles/angular_velocity"})
    EXPECT_EQ(h5::read_doubles(ca.id(), d), h5::read_doubles(cb.id(), d)) << d;
  h5::File ra = h5::File::open(a + "/run.h5", false), rb = h5::File::open(b + "/run.h5", false);
  EXPECT_EQ(read_series(ra.id(), "strain"), read_series(rb.id(), "strain"));
  EXPECT_EQ(read_series(ra.id(), "shear_rate"), read_series(rb.id(), "shear_rate"));
  EXPECT_EQ(read_series(ra.id(), "eta_r"), read_series(rb.id(), "eta_r"));
}

// A run started from another run's last snapshot starts where that one ended (issue 37, item 7): in its box, at its
// Lees-Edwards offset, so with the same contacts, and at the phi its run asked for, which the reached one differs
// from (2fbb67f dropped the offset, so contacts across the sheared face were lost or became overlaps, and refused the
// asked-for phi). A phi that is neither is refused.
TEST(Cli, AShearedSnapshotStartsWhereItsRunEnded) {
  const std::string a = fresh_dir("sheared"), b = fresh_dir("from_sheared"), c = fresh_dir("other_phi");
  ASSERT_EQ(run({"run", restart_case, "--threads", "1", "--quiet", "--set", "particles.count=null", "--set",
                 "box={cube: 7}", "--set", "run.strain=0.3", "--set", "run.average_from=0", "--out", a})
                .code,
            0);
  const std::vector<std::string> from = {"--threads", "1", "--quiet", "--set", "particles.count=null", "--set",
                                         "particles.initial={from: file, file: " + a + "/run.h5}", "--set",
                                         "run.strain=0.05", "--set", "run.average_from=0"};
  const Result r = run(plus({"run", restart_case, "--out", b}, from));
  ASSERT_EQ(r.code, 0) << r.err;
  h5::File fa = h5::File::open(a + "/run.h5", false), fb = h5::File::open(b + "/run.h5", false);
  auto snapshot = [](const h5::File& f, bool last) {
    std::size_t k = 0;
    while (last && h5::exists(f.id(), "snapshots/" + std::string(6 - std::to_string(k + 1).size(), '0') +
                                          std::to_string(k + 1)))
      ++k;
    return "snapshots/" + std::string(6 - std::to_string(k).size(), '0') + std::to_string(k);
  };
  const std::string end = snapshot(fa, true), start = snapshot(fb, false);
  ASSERT_NE(end, "snapshots/000000");
  EXPECT_NE(h5::double_attribute(fa.id(), end, "shear_offset"), 0.0);
  EXPECT_EQ(h5::double_attribute(fb.id(), start, "shear_offset"), h5::double_attribute(fa.id(), end, "shear_offset"));
  EXPECT_EQ(h5::read_doubles(fb.id(), start + "/box"), h5::read_doubles(fa.id(), end + "/box"));
  EXPECT_EQ(h5::read_doubles(fb.id(), start + "/position"), h5::read_doubles(fa.id(), end + "/position"));
  const auto contacts = h5::shape_of(fa.id(), end + "/contact_pairs")[0];
  EXPECT_GT(contacts, 0u);
  EXPECT_EQ(h5::shape_of(fb.id(), start + "/contact_pairs")[0], contacts);
  expect_input_error(plus({"run", restart_case, "--out", c, "--set", "particles.phi=0.5"}, from),
                     "particles.phi = 0.5 does not match", c);
  // Rescaled to a denser phi (particles.initial.compress): the same arrangement in a smaller box, offset included.
  const std::string d = fresh_dir("compressed");
  const std::vector<std::string> compress = {"--threads", "1", "--quiet", "--set", "particles.count=null", "--set",
                                             "particles.initial={from: file, file: " + a + "/run.h5, compress: true}",
                                             "--set", "run.strain=0.02", "--set", "run.average_from=0"};
  ASSERT_EQ(run(plus({"run", restart_case, "--out", d, "--set", "particles.phi=0.47"}, compress)).code, 0);
  h5::File fd = h5::File::open(d + "/run.h5", false);
  const double s = h5::read_doubles(fd.id(), start + "/box")[0] / h5::read_doubles(fa.id(), end + "/box")[0];
  EXPECT_NEAR(s * s * s, 0.4543921456 / 0.47, 1e-9);
  EXPECT_NEAR(h5::double_attribute(fd.id(), start, "shear_offset"), s * h5::double_attribute(fa.id(), end, "shear_offset"),
              1e-12);
  expect_input_error(plus({"run", restart_case, "--out", c, "--set", "particles.phi=0.55"}, compress),
                     "particles.initial.compress: from phi 0.4543921455967", c);
  expect_input_error(plus({"run", restart_case, "--out", c, "--set", "particles.phi=0.47", "--set", "box={cube: 7}"},
                          compress),
                     "particles.initial.compress: the file's particles are rescaled", c);
}

// Snapshots list the contacts, and only them: as many rows as the `contacts` series counts at the same step, each
// with its gap, normal and tangential force and sliding flag. Adhesive Hertz contacts (at gaps below the roughness
// h_r) and frictional linear springs (at overlap, |F_t| <= mu F_n).
TEST(Cli, SnapshotsListTheContactsWithTheirForces) {
  struct Law {
    std::string name;
    std::vector<std::string> args;
    double contact_gap, mu;  // mu: Coulomb limit |F_t| <= mu F_n to check (0: not this law's limit)
  };
  const std::vector<Law> laws = {
      {"adhesive", {"run", SUSPEND_SOURCE_DIR "/cases/quickstart.yaml", "--set", "run.strain=0.05", "--set",
                    "run.average_from=0", "--set", "box.cube=10"}, 5e-3, 0.0},  // limit mu (F_n + F_adh), implicit
      // Explicit springs: the law's own forces. (Implicit contacts report the end-of-step forces that balance the
      // hydrodynamics, the law's plus their linear change over the step, which may lie a little beyond the cap.)
      {"spring", {"run", restart_case, "--set", "run.strain=0.1", "--set", "run.average_from=0", "--set",
                  "particles.count=50", "--set", "particles.phi=0.55", "--set", "run.time_step.contacts=explicit"},
       0.0, 1.0}};
  for (const Law& law : laws) {
    const std::string c = fresh_dir("contacts_" + law.name);
    std::vector<std::string> args = law.args;
    args.insert(args.end(), {"--out", c, "--quiet", "--threads", "1"});
    const Result r = run(args);
    ASSERT_EQ(r.code, 0) << r.err;
    h5::File f = h5::File::open(c + "/run.h5", false);
    std::size_t last = 0;
    while (h5::exists(f.id(), snapshot_group(last + 1))) ++last;
    const std::string g = snapshot_group(last);
    const std::vector<double> gap = h5::read_doubles(f.id(), g + "/contact_gap");
    const std::vector<double> fn = h5::read_doubles(f.id(), g + "/contact_normal_force");
    const std::vector<double> ft = h5::read_doubles(f.id(), g + "/contact_tangential_force");
    const std::vector<std::int64_t> sliding = h5::read_ints(f.id(), g + "/contact_sliding");
    const std::vector<double> contacts = read_series(f.id(), "contacts");
    ASSERT_GT(gap.size(), 10u) << law.name;
    EXPECT_EQ(static_cast<double>(gap.size()), contacts.back()) << law.name << ": rows = the series' contacts";
    EXPECT_EQ(h5::shape_of(f.id(), g + "/contact_pairs")[0], gap.size());
    std::size_t slides = 0;  // reported, to see that both kinds occur
    for (std::size_t k = 0; k < gap.size(); ++k) {
      EXPECT_LT(gap[k], law.contact_gap) << law.name << " contact " << k;
      EXPECT_GT(fn[k], 0.0) << law.name << " contact " << k;
      slides += sliding[k] ? 1 : 0;
      if (law.mu == 0.0) continue;
      const double t = std::hypot(ft[3 * k], ft[3 * k + 1], ft[3 * k + 2]);
      EXPECT_LE(t, law.mu * fn[k] * (1 + 1e-9) + 1e-12) << law.name << " contact " << k;
      if (sliding[k]) {
        EXPECT_NEAR(t, law.mu * fn[k], 1e-9 * fn[k]) << law.name << " sliding contact " << k;
      }
    }
    std::printf("%s: %zu contacts, %zu sliding\n", law.name.c_str(), gap.size(), slides);
  }
}

TEST(Cli, ARunWithoutProgressStopsWithACheckpoint) {
  // A time step that collapses mid-run (here: a displacement bound of 1e-16 a_1) stops after 1000 such steps with
  // exit 3, saying so, and keeps the state in a checkpoint, instead of running for ever.
  const std::string c = fresh_dir("no_progress");
  const Result r = run({"run", restart_case, "--out", c, "--quiet", "--set", "particles.count=30", "--set",
                        "hydrodynamics.lubrication.enabled=false", "--set", "run.time_step.max_displacement=1e-16"});
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("no progress: the last 1000 steps advanced the strain by"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(c + "/checkpoint.h5"));
}

TEST(Cli, RunawayOverlapKeepsTheStateOfTheStepBefore) {
  // The overlap bound is checked when a configuration is evaluated: the step that produced the overlap is the
  // failing one, so the checkpoint holds the configuration one step before the failing snapshot.
  const std::string c = fresh_dir("overlap");
  const Result r = run({"run", restart_case, "--out", c, "--quiet", "--set", "run.max_overlap=1e-4"});
  ASSERT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("exceeds the bound"), std::string::npos) << r.err;
  h5::File f = h5::File::open(c + "/run.h5", false), cp = h5::File::open(c + "/checkpoint.h5", false);
  const std::int64_t failing = h5::int_attribute(f.id(), "snapshots/000001", "step");
  EXPECT_GT(failing, 1);
  EXPECT_EQ(h5::int_attribute(cp.id(), ".", "step"), failing - 1);
}
