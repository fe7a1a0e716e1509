// run.h5 round trip, truncation on restart, checkpoint round trip and refusal, and the XDMF references.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>

#include <filesystem>
#include <fstream>
#include <regex>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "io/case.hpp"
#include "io/checkpoint.hpp"
#include "io/hdf5.hpp"
#include "io/run_file.hpp"
#include "io/xdmf.hpp"
#include "tests/scratch_dir.hpp"

using namespace suspend;
using namespace suspend::io;

namespace {
Particles some_particles(std::size_t n) {
  Particles p;
  p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    p.position[i] = Vec3(0.1 * i, 0.2 * i + 1.0 / 3.0, std::sqrt(2.0) * i);
    p.velocity[i] = Vec3(1e-300 * i, -1.0 * i, 3.0);
    p.angular_velocity[i] = Vec3(0.0, 0.0, -0.5 + i);
    p.radius[i] = i % 2 ? 1.4 : 1.0;
    p.species[i] = static_cast<int>(i % 2);
  }
  return p;
}
SeriesRow row(int k) {
  SeriesRow r;
  r.step = 10 * k;
  r.time = 0.1 * k;
  r.strain = 0.1 * k;
  r.shear_rate = 2.0;
  r.dt = 1e-3;
  r.solver_iterations = 3 + k;
  r.solver_residual = 1e-9 * k;
  r.stress[Contribution::hydrodynamic](0, 1) = 2.0 + k;
  r.stress[Contribution::contact_normal](1, 1) = -3.0 * k;
  return r;
}
Checkpoint small_checkpoint(std::size_t particles, const std::string& fingerprint) {
  Checkpoint c;
  c.state.particles = some_particles(particles);
  c.fingerprint = fingerprint;
  c.rng = serialize(Rng(1));
  return c;
}
std::string temp(const std::string& name) {
  const std::string p = suspend::testing_support::scratch_dir() + "/" + name;
  std::filesystem::remove(p);
  return p;
}
}  // namespace

TEST(RunFile, SeriesAndSnapshotsRoundTrip) {
  const std::string path = temp("roundtrip.h5");
  const Particles p = some_particles(7);
  {
    RunFile f = RunFile::create(path, {"title: x\n", 2});
    for (int k = 0; k < 5; ++k) f.append(row(k));
    Snapshot s;
    s.step = 40;
    s.time = s.strain = 0.4;
    s.box = Box(10, 11, 12);
    s.particles = &p;
    s.contact_pairs = {0, 1, 2, 5};
    s.contact_force = {1, 2, 3, 4, 5, 6};
    f.write_snapshot(s);
  }
  h5::File f = h5::File::open(path, false);
  EXPECT_EQ(h5::string_attribute(f.id(), ".", "case"), "title: x\n");
  EXPECT_EQ(h5::int_attribute(f.id(), ".", "threads"), 2);
  const auto strain = read_series(f.id(), "strain");
  ASSERT_EQ(strain.size(), 5u);
  EXPECT_EQ(strain[3], 0.1 * 3);
  // eta_r is the total shear stress over the row's shear rate.
  EXPECT_DOUBLE_EQ(read_series(f.id(), "eta_r")[4], (2.0 + 4) / 2.0);
  EXPECT_DOUBLE_EQ(read_series(f.id(), "stress/contact_normal", 1)[2], -6.0);
  EXPECT_DOUBLE_EQ(read_series(f.id(), "stress/total", 3)[1], 3.0);
  EXPECT_EQ(read_series(f.id(), "solver_iterations")[2], 5.0);
  EXPECT_EQ(read_series(f.id(), "solver_residual")[4], 4e-9);
  const auto pos = h5::read_doubles(f.id(), "snapshots/000000/position");
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int a = 0; a < 3; ++a) EXPECT_EQ(pos[3 * i + a], p.position[i][a]);  // bit-exact
  EXPECT_EQ(h5::read_ints(f.id(), "snapshots/000000/contact_pairs")[3], 5);
}

TEST(RunFile, ReopenTruncatesToTheCheckpoint) {
  const std::string path = temp("truncate.h5");
  const Particles p = some_particles(3);
  {
    RunFile f = RunFile::create(path, {"", 1});
    Snapshot s;
    s.particles = &p;
    for (int k = 0; k < 6; ++k) f.append(row(k));
    f.write_snapshot(s);
    f.write_snapshot(s);
  }
  {
    RunFile f = RunFile::reopen(path, 4, 1);
    EXPECT_EQ(f.series_rows(), 4u);
    EXPECT_EQ(f.snapshot_count(), 1u);
    f.append(row(9));
  }
  h5::File f = h5::File::open(path, false);
  const auto step = read_series(f.id(), "step");
  ASSERT_EQ(step.size(), 5u);
  EXPECT_EQ(step[4], 90.0);
  EXPECT_FALSE(h5::exists(f.id(), "snapshots/000001"));
  EXPECT_THROW(RunFile::reopen(path, 7, 1), std::runtime_error);
}

TEST(Checkpoint, RoundTripIsBitExact) {
  const std::string path = temp("checkpoint.h5");
  Checkpoint c;
  c.state.particles = some_particles(5);
  c.state.time = 1.0 / 3.0;
  c.state.strain = 2.0 / 3.0;
  c.state.step = 12345;
  c.clock = {0.67, 1.0, 1.5, 67, 1};
  c.fingerprint = "physics";
  c.rng = serialize(Rng(123456));
  c.threads = 2;
  write_checkpoint(path, c);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp." + std::to_string(getpid())));
  const Checkpoint d = read_checkpoint(path, "physics");
  EXPECT_EQ(d.state.step, 12345);
  EXPECT_EQ(d.state.strain, c.state.strain);
  EXPECT_EQ(d.clock.series_rows, 67);
  EXPECT_EQ(d.rng, c.rng);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(d.state.particles.position[i], c.state.particles.position[i]);
    EXPECT_EQ(d.state.particles.velocity[i], c.state.particles.velocity[i]);
    EXPECT_EQ(d.state.particles.species[i], c.state.particles.species[i]);
  }
}

// The contact histories come back whole, every scalar slot of the pair history included (JKR's neck, the twisting
// stretch); a checkpoint written before a slot existed (no contacts/<slot>) reads with zeros there, and its checksum
// still holds.
TEST(Checkpoint, ContactHistoriesWithTheirScalarSlotsRoundTrip) {
  const std::string path = temp("checkpoint_contacts.h5");
  Checkpoint c = small_checkpoint(5, "physics");
  c.state.contacts = {{0, 3, {Vec3(1e-3, 2e-3, 0.0), Vec3::Zero(), true, 0.0, -2.5e-4}},
                      {1, 4, {Vec3::Zero(), Vec3(0.0, 5e-4, 0.0), true, 0.0421, 0.0}}};
  write_checkpoint(path, c);
  const Checkpoint d = read_checkpoint(path, "physics");
  ASSERT_EQ(d.state.contacts.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(d.state.contacts[k].history.tangential_stretch, c.state.contacts[k].history.tangential_stretch);
    EXPECT_EQ(d.state.contacts[k].history.rolling_stretch, c.state.contacts[k].history.rolling_stretch);
    for (const PairHistorySlot& slot : scalar_slots)
      EXPECT_EQ(d.state.contacts[k].history.*slot.member, c.state.contacts[k].history.*slot.member) << slot.name;
  }
  for (const PairHistorySlot& slot : scalar_slots) {
    Checkpoint before = c;  // as before the slot: no state, and no dataset
    for (auto& e : before.state.contacts) e.history.*slot.member = 0.0;
    write_checkpoint(path, before);
    {
      h5::File f = h5::File::open(path, true);
      ASSERT_GE(H5Ldelete(f.id(), ("contacts/" + std::string(slot.name)).c_str(), H5P_DEFAULT), 0);
    }
    const Checkpoint old = read_checkpoint(path, "physics");
    ASSERT_EQ(old.state.contacts.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_EQ(old.state.contacts[k].history.*slot.member, 0.0) << slot.name;
      EXPECT_EQ(old.state.contacts[k].history.rolling_stretch, c.state.contacts[k].history.rolling_stretch);
    }
  }
}

// A file that cannot even be created for lack of room (here a file size limit of zero, as a full disk) is an output
// failure, like a failed write: the run stops with the output exit code and keeps its last checkpoint, and the
// temporary file is removed.
TEST(Checkpoint, NoRoomToCreateTheFileIsAnOutputFailure) {
  const std::string path = temp("no_room.h5");
  const Checkpoint c = small_checkpoint(5, "physics");
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit none = old;
  none.rlim_cur = 0;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &none), 0);
  std::string message;
  bool output_error = false;
  try {
    write_checkpoint(path, c);
  } catch (const OutputError& e) {
    output_error = true;
    message = e.what();
  } catch (const std::exception& e) {
    message = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_TRUE(output_error) << message;
  EXPECT_NE(message.find("cannot write "), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp." + std::to_string(getpid())));
}

TEST(Checkpoint, RefusesOtherCaseCorruptFileAndNaN) {
  const std::string path = temp("refuse.h5");
  Checkpoint c = small_checkpoint(3, "case A");
  write_checkpoint(path, c);
  try {
    read_checkpoint(path, "case B");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("belongs to another case"), std::string::npos);
  }
  const std::string garbage = temp("garbage.h5");
  std::ofstream(garbage) << "not hdf5";
  EXPECT_THROW(read_checkpoint(garbage, "case A"), InputError);
  c.state.particles.position[1].y() = std::nan("");
  write_checkpoint(path, c);
  try {
    read_checkpoint(path, "case A");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("position of particle 1 is not finite"), std::string::npos) << e.what();
  }
}

// Integrity is not optional: with either checksum removed (an edit that also drops the evidence) the checkpoint is
// refused, not continued unverified.
TEST(Checkpoint, WithoutItsChecksumsIsRefused) {
  for (const char* sum : {"checksums/content", "checksums/attributes"}) {
    const std::string path = temp("no_checksum.h5");
    write_checkpoint(path, small_checkpoint(3, "case A"));
    {
      h5::File f = h5::File::open(path, true);
      ASSERT_GE(H5Ldelete(f.id(), sum, H5P_DEFAULT), 0);
    }
    try {
      read_checkpoint(path, "case A");
      ADD_FAILURE() << "a checkpoint without " << sum << " was read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("without its ") + sum), std::string::npos) << e.what();
    }
  }
}

// A checkpoint written by an older version, whose fingerprint lacks a key this version's resolved form has gained
// with the value the old form implied, continues (the checksum is over the fingerprint as written).
TEST(Checkpoint, OlderFormOfTheSameCaseContinues) {
  const Case now_case = parse_case(YAML::Load("particles: {phi: 0.3, count: 20}\ncontact: {law: hertz_adhesive, "
                                              "gamma_bar: 0.9, g_adh: 1.0}\nrun: {strain: 1}\n"),
                                   "");
  const std::string now = physics_fingerprint(now_case);
  std::string old_form = now;
  old_form.erase(old_form.find("  friction: coulomb\n"), std::string("  friction: coulomb\n").size());
  const std::string path = temp("older.h5");
  Checkpoint c;
  c.state.particles = some_particles(3);
  c.fingerprint = old_form;
  c.rng = serialize(Rng(1));
  write_checkpoint(path, c);
  const Checkpoint d = read_checkpoint(path, now);
  EXPECT_EQ(d.fingerprint, now);
  EXPECT_EQ(d.state.particles.position[2], c.state.particles.position[2]);
}

TEST(Xdmf, EveryReferencedDatasetExists) {
  const std::string path = temp("xdmf.h5");
  Particles p = some_particles(4);
  p.position[0] = Vec3(0.5, 0.5, 1.0);  // touches particle 1 through the sheared y face
  p.position[1] = Vec3(3.5, 9.5, 1.0);
  std::vector<SnapshotInfo> info;
  {
    RunFile f = RunFile::create(path, {"", 1});
    Snapshot s;
    s.box = Box(10.0, 10.0, 10.0);
    s.box.set_shear_offset(3.0);
    s.particles = &p;
    f.write_snapshot(s);
    s.time = 0.25;
    s.strain = 0.5;
    s.contact_pairs = {0, 1};
    s.contact_force = {0.0, 1.0, 0.0};
    s.contact_gap = {-0.01};
    s.contact_normal_force = {1.0};
    s.contact_tangential_force = {0.0, 0.0, 0.0};
    s.contact_sliding = {0};
    f.write_snapshot(s);
    info = f.snapshots();
  }
  ASSERT_EQ(info.size(), 2u);
  EXPECT_TRUE(info[1].segments);
  EXPECT_DOUBLE_EQ(info[1].shear_offset, 3.0);
  const std::string x = xdmf_text("xdmf.h5", info);
  h5::File f = h5::File::open(path, false);
  const std::regex ref(R"re(Dimensions="([0-9 ]+)"[^>]*Format="HDF">xdmf\.h5:(/[^<]+)<)re");
  int count = 0;
  for (auto it = std::sregex_iterator(x.begin(), x.end(), ref); it != std::sregex_iterator(); ++it, ++count) {
    const std::string name = (*it)[2].str();
    ASSERT_TRUE(h5::exists(f.id(), name)) << name;
    std::string dims;
    for (hsize_t d : h5::shape_of(f.id(), name)) {
      if (!dims.empty()) dims += ' ';
      dims += std::to_string(d);
    }
    EXPECT_EQ(dims, (*it)[1].str()) << name;
  }
  // particles: position, radius, species, velocity, angular_velocity per snapshot; contacts (second snapshot only):
  // nodes, segments, force, normal force, tangential force, gap, sliding.
  EXPECT_EQ(count, 2 * 5 + 7);
  EXPECT_NE(x.find("<Time Value=\"0.5\"/>"), std::string::npos);  // the strain
  EXPECT_NE(x.find("<Information Name=\"time\" Value=\"0.25\"/>"), std::string::npos);
  // The contact is drawn at its length: from particle 0 to the image of 1 below the bottom face, (3.5 - 3, -0.5).
  const std::vector<double> seg = h5::read_doubles(f.id(), "snapshots/000001/contact_segments");
  ASSERT_EQ(seg.size(), 6u);
  EXPECT_NEAR(seg[3], 0.5, 1e-12);
  EXPECT_NEAR(seg[4], -0.5, 1e-12);
  // The cell's top face is shifted by the offset.
  EXPECT_NE(x.find("3 1e+01 0 13 1e+01 0 13 1e+01 1e+01 3 1e+01 1e+01"), std::string::npos) << x;
}

TEST(Checkpoint, FlippedBitsAreRefusedNeverSilentlyRead) {
  // Every dataset carries a Fletcher32 checksum and the attributes a checksum of their own: a single flipped bit
  // anywhere in the file either makes the checkpoint unreadable (InputError) or leaves what is read unchanged
  // (padding, unused metadata); it never changes the state that a run would continue from.
  const std::string path = temp("flip_original.h5"), flipped = temp("flip.h5");
  Checkpoint c;
  c.state.particles = some_particles(6);
  c.state.time = 0.25;
  c.state.strain = 0.5;
  c.state.step = 321;
  c.clock = {0.51, 1.0, 1.0, 51, 1};
  c.fingerprint = "physics";
  c.rng = serialize(Rng(99));
  c.state.warm_start.assign(36, 0.125);
  write_checkpoint(path, c);
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const Checkpoint original = read_checkpoint(path, "physics");
  Rng rng(2024);
  int refused = 0, unchanged = 0, silently_changed = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::string b = bytes;
    const std::size_t at = rng() % b.size();
    b[at] = static_cast<char>(b[at] ^ (1 << (rng() % 8)));
    std::ofstream(flipped, std::ios::binary | std::ios::trunc) << b;
    try {
      const Checkpoint d = read_checkpoint(flipped, "physics");
      const bool same = d.state.step == original.state.step && d.state.time == original.state.time &&
                        d.state.strain == original.state.strain && d.rng == original.rng &&
                        d.clock.series_rows == original.clock.series_rows &&
                        d.clock.next_series == original.clock.next_series &&
                        d.state.particles.position == original.state.particles.position &&
                        d.state.particles.velocity == original.state.particles.velocity &&
                        d.state.particles.radius == original.state.particles.radius &&
                        d.state.particles.species == original.state.particles.species &&
                        d.state.warm_start == original.state.warm_start;
      (same ? unchanged : silently_changed) += 1;
    } catch (const InputError&) {
      ++refused;
    }
  }
  EXPECT_EQ(silently_changed, 0) << refused << " refused, " << unchanged << " unchanged";
  EXPECT_GT(refused, 30);
}
