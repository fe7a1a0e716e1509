#include "io/checkpoint.hpp"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "io/atomic_file.hpp"
#include "io/case.hpp"
#include "io/hdf5.hpp"

namespace suspend::io {

namespace {
constexpr const char* format = "suspend-checkpoint-1";

// 64-bit FNV-1a, fed byte ranges in a fixed order.
struct Fnv1a {
  std::uint64_t h = 1469598103934665603ull;
  void operator()(const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < n; ++k) h = (h ^ b[k]) * 1099511628211ull;
  }
  std::int64_t value() const { return static_cast<std::int64_t>(h); }
};

// FNV-1a over the root attributes (text, then the bytes of every number, in a fixed order): stored in a dataset,
// which carries a Fletcher32 checksum like every dataset, so that a flipped bit in an attribute is found too.
// `accumulated`: the checkpoint holds accumulated_strain (absent before it existed, where it equals the strain).
std::int64_t attribute_checksum(const Checkpoint& c, bool accumulated = true) {
  Fnv1a h;
  for (const std::string* t : {&c.fingerprint, &c.rng}) h(t->data(), t->size());
  const std::int64_t ints[] = {c.threads, c.state.step, c.clock.series_rows, c.clock.snapshots};
  const double reals[] = {c.state.time,           c.state.strain,          c.state.last_dt,
                          c.state.shear_rate,     c.clock.next_series,     c.clock.next_snapshot,
                          c.clock.next_checkpoint, c.clock.jam_window_time, c.clock.jam_window_strain};
  h(ints, sizeof ints);
  h(reals, sizeof reals);
  if (accumulated) h(&c.state.accumulated_strain, sizeof c.state.accumulated_strain);
  return h.value();
}

// FNV-1a of the decoded arrays: Fletcher32 guards each dataset's stored bytes, not the metadata that says how to
// decode them (a flipped bit in a datatype message reads other numbers from intact bytes).
std::int64_t content_checksum(const SimulationState& s) {
  Fnv1a h;
  const Particles& p = s.particles;
  for (const std::vector<Vec3>* v : {&p.position, &p.velocity, &p.angular_velocity})
    for (const Vec3& x : *v) h(x.data(), 3 * sizeof(double));
  h(p.radius.data(), p.radius.size() * sizeof(double));
  for (int k : p.species) {
    const std::int64_t w = k;
    h(&w, sizeof w);
  }
  h(s.warm_start.data(), s.warm_start.size() * sizeof(double));
  h(s.verlet.data(), s.verlet.size() * sizeof(double));
  for (const ContactHistory::Entry& e : s.contacts) {
    const std::int64_t ij[2] = {e.i, e.j};
    h(ij, sizeof ij);
    h(e.history.tangential_stretch.data(), 3 * sizeof(double));
    h(e.history.rolling_stretch.data(), 3 * sizeof(double));
    // A scalar slot enters only where a sub-model set it: checkpoints written before a slot existed (and runs
    // without the sub-model that keeps it) have the checksum they always had.
    for (const PairHistorySlot& slot : scalar_slots)
      if (e.history.*slot.member != 0.0) h(&(e.history.*slot.member), sizeof(double));
  }
  return h.value();
}

std::vector<double> flatten(const std::vector<Vec3>& v) {
  std::vector<double> out(3 * v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int a = 0; a < 3; ++a) out[3 * i + a] = v[i][a];
  return out;
}
std::vector<Vec3> unflatten(const std::vector<double>& v, std::size_t n, const std::string& what) {
  if (v.size() != 3 * n) throw InputError("checkpoint: " + what + " has the wrong size");
  std::vector<Vec3> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = Vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
    if (!out[i].allFinite())
      throw InputError("checkpoint: " + what + " of particle " + std::to_string(i) + " is not finite (NaN or inf)");
  }
  return out;
}
}  // namespace

void write_checkpoint(const std::string& path, const Checkpoint& c) {
  write_atomically(path, [&](const std::string& tmp) {
    h5::File f = h5::File::create(tmp);
    const hid_t id = f.id();
    const Particles& p = c.state.particles;
    const std::size_t n = p.size();
    h5::write(id, "particles/position", flatten(p.position), {n, 3});
    h5::write(id, "particles/velocity", flatten(p.velocity), {n, 3});
    h5::write(id, "particles/angular_velocity", flatten(p.angular_velocity), {n, 3});
    h5::write(id, "particles/radius", p.radius, {n});
    h5::write(id, "particles/species", std::vector<std::int64_t>(p.species.begin(), p.species.end()), {n});
    h5::set_attribute(id, ".", "format", std::string(format));
    h5::set_attribute(id, ".", "fingerprint", c.fingerprint);
    h5::set_attribute(id, ".", "rng", c.rng);
    h5::set_attribute(id, ".", "threads", static_cast<std::int64_t>(c.threads));
    h5::set_attribute(id, ".", "step", c.state.step);
    h5::set_attribute(id, ".", "time", c.state.time);
    h5::set_attribute(id, ".", "strain", c.state.strain);
    h5::set_attribute(id, ".", "accumulated_strain", c.state.accumulated_strain);
    h5::set_attribute(id, ".", "last_dt", c.state.last_dt);
    h5::set_attribute(id, ".", "shear_rate", c.state.shear_rate);
    const auto& contacts = c.state.contacts;
    std::vector<std::int64_t> pairs;
    std::vector<double> stretch;
    for (const auto& e : contacts) {
      pairs.insert(pairs.end(), {e.i, e.j});
      for (int a = 0; a < 3; ++a) stretch.push_back(e.history.tangential_stretch[a]);
      for (int a = 0; a < 3; ++a) stretch.push_back(e.history.rolling_stretch[a]);
    }
    h5::write(id, "contacts/pairs", pairs, {contacts.size(), 2});
    h5::write(id, "contacts/stretch", stretch, {contacts.size(), 6});
    for (const PairHistorySlot& slot : scalar_slots) {
      std::vector<double> values;
      for (const auto& e : contacts) values.push_back(e.history.*slot.member);
      h5::write(id, "contacts/" + std::string(slot.name), values, {contacts.size()});
    }
    h5::write(id, "solver/warm_start", c.state.warm_start, {c.state.warm_start.size()});
    h5::write(id, "integrator/verlet", c.state.verlet, {c.state.verlet.size()});
    h5::set_attribute(id, ".", "next_series", c.clock.next_series);
    h5::set_attribute(id, ".", "next_snapshot", c.clock.next_snapshot);
    h5::set_attribute(id, ".", "next_checkpoint", c.clock.next_checkpoint);
    h5::set_attribute(id, ".", "series_rows", c.clock.series_rows);
    h5::set_attribute(id, ".", "snapshots", c.clock.snapshots);
    h5::set_attribute(id, ".", "jam_window_time", c.clock.jam_window_time);
    h5::set_attribute(id, ".", "jam_window_strain", c.clock.jam_window_strain);
    h5::write(id, "checksums/attributes", std::vector<std::int64_t>{attribute_checksum(c)}, {1});
    h5::write(id, "checksums/content", std::vector<std::int64_t>{content_checksum(c.state)}, {1});
    f.flush();
  });
}

Checkpoint read_checkpoint(const std::string& path, const std::string& fingerprint) {
  Checkpoint c;
  try {
    h5::File f = h5::File::open(path, false);
    const hid_t id = f.id();
    if (!h5::exists(id, "particles/position") || h5::string_attribute(id, ".", "format") != format)
      throw InputError(path + ": not a suspend checkpoint");
    const std::string stored = h5::string_attribute(id, ".", "fingerprint");
    const std::string changes = case_changes(stored, fingerprint, physics_fingerprint);
    if (!changes.empty())
      throw InputError(path + ": the checkpoint belongs to another case (" + changes +
                       "); restart with the case and --set values it was written with");
    c.fingerprint = stored;  // as written, for the checksum; the run continues under this version's form
    c.rng = h5::string_attribute(id, ".", "rng");
    c.threads = static_cast<int>(h5::int_attribute(id, ".", "threads"));
    c.state.step = h5::int_attribute(id, ".", "step");
    c.state.time = h5::double_attribute(id, ".", "time");
    c.state.strain = h5::double_attribute(id, ".", "strain");
    const bool accumulated = h5::has_attribute(id, ".", "accumulated_strain");
    c.state.accumulated_strain = accumulated ? h5::double_attribute(id, ".", "accumulated_strain") : c.state.strain;
    c.state.last_dt = h5::double_attribute(id, ".", "last_dt");
    c.state.shear_rate = h5::double_attribute(id, ".", "shear_rate");
    c.clock.next_series = h5::double_attribute(id, ".", "next_series");
    c.clock.next_snapshot = h5::double_attribute(id, ".", "next_snapshot");
    c.clock.next_checkpoint = h5::double_attribute(id, ".", "next_checkpoint");
    c.clock.series_rows = h5::int_attribute(id, ".", "series_rows");
    c.clock.snapshots = h5::int_attribute(id, ".", "snapshots");
    if (h5::has_attribute(id, ".", "jam_window_time")) {  // absent in checkpoints written before it existed
      c.clock.jam_window_time = h5::double_attribute(id, ".", "jam_window_time");
      c.clock.jam_window_strain = h5::double_attribute(id, ".", "jam_window_strain");
    }
    for (double v : {c.state.time, c.state.strain, c.state.accumulated_strain, c.state.last_dt, c.state.shear_rate, c.clock.next_series, c.clock.next_snapshot, c.clock.next_checkpoint,
                     c.clock.jam_window_time, c.clock.jam_window_strain})
      if (!std::isfinite(v)) throw InputError(path + ": time, strain or output clock is not finite");
    // Integrity is not optional: a checkpoint whose checksums were removed is refused like a corrupt one (those
    // written before checksums existed, before 2026-12-03, cannot be continued: run them again).
    for (const char* sum : {"checksums/attributes", "checksums/content"})
      if (!h5::exists(id, sum))
        throw InputError(path + ": checkpoint without its " + sum + " (edited, or older than checksums); it cannot be "
                         "verified, so it is not continued");
    if (h5::read_ints(id, "checksums/attributes") != std::vector<std::int64_t>{attribute_checksum(c, accumulated)})
      throw InputError(path + ": corrupt checkpoint (its attributes do not match their checksum)");
    c.fingerprint = fingerprint;
    if (c.state.step < 0 || c.clock.series_rows < 0 || c.clock.snapshots < 0 || c.threads < 1)
      throw InputError(path + ": corrupt checkpoint (negative step, row or snapshot count, or no threads)");
    {
      Rng probe;
      std::istringstream in(c.rng);
      if (!(in >> probe)) throw InputError(path + ": corrupt checkpoint (unreadable random-number state)");
    }
    Particles& p = c.state.particles;
    p.radius = h5::read_doubles(id, "particles/radius");
    const std::size_t n = p.radius.size();
    for (std::size_t i = 0; i < n; ++i)
      if (!(p.radius[i] > 0.0) || !std::isfinite(p.radius[i]))
        throw InputError(path + ": radius of particle " + std::to_string(i) + " is not a positive number");
    p.position = unflatten(h5::read_doubles(id, "particles/position"), n, "position");
    p.velocity = unflatten(h5::read_doubles(id, "particles/velocity"), n, "velocity");
    p.angular_velocity = unflatten(h5::read_doubles(id, "particles/angular_velocity"), n, "angular velocity");
    const std::vector<std::int64_t> species = h5::read_ints(id, "particles/species");
    if (species.size() != n) throw InputError(path + ": particles/species has the wrong size");
    for (std::int64_t k : species)
      if (k < 0 || k > 1'000'000) throw InputError(path + ": particles/species holds " + std::to_string(k));
    p.species.assign(species.begin(), species.end());
    c.state.warm_start = h5::read_doubles(id, "solver/warm_start");
    const std::size_t warm = c.state.warm_start.size();
    if (n == 0 || warm % n != 0)  // 6 or 12 (pairwise), 11 or 22 (FCM) values per particle
      throw InputError(path + ": solver/warm_start does not match the particle count");
    for (double v : c.state.warm_start)
      if (!std::isfinite(v)) throw InputError(path + ": solver/warm_start is not finite");
    c.state.verlet = h5::read_doubles(id, "integrator/verlet");
    if (!c.state.verlet.empty() && c.state.verlet.size() != 12 * n)
      throw InputError(path + ": integrator/verlet does not match the particle count");
    for (double v : c.state.verlet)
      if (!std::isfinite(v)) throw InputError(path + ": integrator/verlet is not finite");
    const std::vector<std::int64_t> pairs = h5::read_ints(id, "contacts/pairs");
    const std::vector<double> stretch = h5::read_doubles(id, "contacts/stretch");
    if (stretch.size() != 3 * pairs.size()) throw InputError(path + ": contacts/stretch does not match contacts/pairs");
    // A scalar slot is absent in checkpoints written before it existed: zero, as it was.
    std::vector<std::vector<double>> scalars;
    for (const PairHistorySlot& slot : scalar_slots) {
      const std::string name = "contacts/" + std::string(slot.name);
      scalars.push_back(h5::exists(id, name) ? h5::read_doubles(id, name) : std::vector<double>(pairs.size() / 2, 0.0));
      if (2 * scalars.back().size() != pairs.size())
        throw InputError(path + ": " + name + " does not match contacts/pairs");
    }
    for (std::size_t k = 0; k < pairs.size() / 2; ++k) {
      const std::int64_t i = pairs[2 * k], j = pairs[2 * k + 1];
      if (i < 0 || j <= i || static_cast<std::size_t>(j) >= n)
        throw InputError(path + ": contact " + std::to_string(k) + " names particles outside the run");
      ContactHistory::Entry e{static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j), {}};
      e.history.tangential_stretch = Vec3(stretch[6 * k], stretch[6 * k + 1], stretch[6 * k + 2]);
      e.history.rolling_stretch = Vec3(stretch[6 * k + 3], stretch[6 * k + 4], stretch[6 * k + 5]);
      e.history.in_contact = true;
      bool finite = e.history.tangential_stretch.allFinite() && e.history.rolling_stretch.allFinite();
      for (std::size_t q = 0; q < scalar_slots.size(); ++q) {
        e.history.*scalar_slots[q].member = scalars[q][k];
        finite = finite && std::isfinite(scalars[q][k]);
      }
      if (!finite) throw InputError(path + ": contact " + std::to_string(k) + " has a non-finite stretch or state");
      c.state.contacts.push_back(e);
    }
    if (h5::read_ints(id, "checksums/content") != std::vector<std::int64_t>{content_checksum(c.state)})
      throw InputError(path + ": corrupt checkpoint (its arrays do not match their checksum)");
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path + ": corrupt or unreadable checkpoint (" + e.what() + ")");
  }
  return c;
}

}  // namespace suspend::io
