#include "io/initial_configuration.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>
#include <vector>

#include "core/error.hpp"
#include "io/hdf5.hpp"
#include "io/memory_estimate.hpp"
#include "io/schema_reader.hpp"

#include <yaml-cpp/yaml.h>

namespace suspend::io {

Composition composition_of(const Case& c) {
  Composition k;
  const std::vector<Species>& sp = c.particles.species;
  double smallest = sp.front().radius;
  for (const Species& s : sp) smallest = std::min(smallest, s.radius);
  auto total = [](const std::vector<std::size_t>& counts) {
    double n = 0.0;
    for (std::size_t m : counts) n += static_cast<double>(m);
    return n;
  };
  if (c.particles.count) {
    k.counts = species_counts(sp, static_cast<std::size_t>(*c.particles.count));
    double volume = 0.0;  // of the particles, before any per-particle array exists
    for (std::size_t s = 0; s < sp.size(); ++s)
      volume += static_cast<double>(k.counts[s]) * 4.0 / 3.0 * std::numbers::pi * std::pow(sp[s].radius, 3);
    const double side = std::cbrt(volume / c.particles.phi);
    refuse_what_cannot_fit(c, total(k.counts), Vec3(side, side, side), smallest);
    k.radius = species_radii(sp, k.counts);
    k.box = cube_for_volume_fraction(k.radius, c.particles.phi);
  } else {
    k.box = Box(*c.box);
    k.counts = species_counts(sp, c.particles.phi, k.box);
    refuse_what_cannot_fit(c, total(k.counts), k.box.length(), smallest);
    k.radius = species_radii(sp, k.counts);
    if (k.radius.size() < 2)
      throw InputError("box: too small to hold two particles at particles.phi = " + exact(c.particles.phi));
  }
  // A requested species that gets no sphere would run another suspension than the case says (a size ratio of 4 in
  // a (6 a_1)^3 box gave 12 small spheres at phi 0.23 for 0.45 requested).
  for (std::size_t s = 0; s < k.counts.size(); ++s)
    if (sp[s].volume_share > 0.0 && k.counts[s] == 0)
      throw InputError(std::string(c.particles.count ? "particles.count" : "box") + ": no sphere of species " +
                       std::to_string(s) + " (radius " + exact(sp[s].radius) + ", volume share " +
                       exact(sp[s].volume_share) + ") fits the " + std::to_string(k.radius.size()) +
                       " spheres at particles.phi = " + exact(c.particles.phi) + "; give more particles or a larger box");
  for (std::size_t s = 0; s < k.counts.size(); ++s) k.species.insert(k.species.end(), k.counts[s], static_cast<int>(s));
  k.phi = volume_fraction(k.radius, k.box.volume());
  return k;
}

Particles read_particle_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("particles.initial.file: cannot open '" + path + "'");
  Particles p;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream s(line);
    std::vector<std::string> words;
    for (std::string w; s >> w;) words.push_back(w);
    if (words.empty()) continue;  // blank or comment line
    const std::string where = path + ":" + std::to_string(number) + ": ";
    if (words.size() != 4)
      throw InputError(where + "expected four numbers 'x y z radius', found " + std::to_string(words.size()) +
                       " value(s)");
    // Every word a whole finite number: a row of text, nan, inf or 1e999 is an error, never a skipped line.
    double v[4];
    for (int k = 0; k < 4; ++k) {
      char* end = nullptr;
      errno = 0;
      v[k] = std::strtod(words[k].c_str(), &end);
      if (end == words[k].c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(v[k]))
        throw InputError(where + "'" + words[k] + "' is not a finite number");
    }
    const double x = v[0], y = v[1], z = v[2], a = v[3];
    if (!(a > 0.0)) throw InputError(where + "the radius must be > 0, not " + words[3]);
    p.position.emplace_back(x, y, z);
    p.radius.push_back(a);
  }
  if (p.radius.empty()) throw InputError(path + ": holds no particles");
  const std::size_t n = p.radius.size();
  p.velocity.assign(n, Vec3::Zero());
  p.angular_velocity.assign(n, Vec3::Zero());
  p.species.assign(n, 0);
  return p;
}

StoredParticles read_particles_h5(const std::string& path) {
  try {
    h5::File f = h5::File::open(path, false);
    std::string group;
    if (h5::exists(f.id(), "particles/position")) {
      group = "particles";
    } else {
      for (std::size_t k = 0;; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "snapshots/%06zu", k);
        if (!h5::exists(f.id(), name)) break;
        group = name;
      }
    }
    if (group.empty()) throw InputError(path + ": holds neither a checkpoint nor a snapshot to start from");
    std::vector<hsize_t> shape;
    const std::vector<double> pos = h5::read_doubles(f.id(), group + "/position", &shape);
    StoredParticles out;
    Particles& p = out.particles;
    const std::vector<double> radius = h5::read_doubles(f.id(), group + "/radius");
    const std::size_t n = radius.size();
    if (shape.size() != 2 || shape[0] != n || shape[1] != 3)
      throw InputError(path + ": " + group + "/position does not match the radius count");
    p.resize(n);
    p.radius = radius;
    if (h5::exists(f.id(), group + "/species")) {
      const std::vector<std::int64_t> species = h5::read_ints(f.id(), group + "/species");
      if (species.size() != n) throw InputError(path + ": " + group + "/species does not match the radius count");
      for (std::size_t i = 0; i < n; ++i) {
        if (species[i] < 0 || species[i] > 1000)
          throw InputError(path + ": particle " + std::to_string(i) + " has species " + std::to_string(species[i]));
        p.species[i] = static_cast<int>(species[i]);
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      p.position[i] = Vec3(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]);
      if (!p.position[i].allFinite() || !(p.radius[i] > 0.0))
        throw InputError(path + ": particle " + std::to_string(i) + " has a non-finite position or bad radius");
    }
    auto finite = [&](double v, const std::string& what) {
      if (!std::isfinite(v)) throw InputError(path + ": " + what + " is not finite");
      return v;
    };
    if (group == "particles") {
      out.strain = finite(h5::double_attribute(f.id(), ".", "strain"), "the checkpoint's strain");
      return out;
    }
    const std::vector<double> box = h5::read_doubles(f.id(), group + "/box");
    if (box.size() != 3 || !(box[0] > 0.0 && box[1] > 0.0 && box[2] > 0.0) ||
        !std::isfinite(box[0] * box[1] * box[2]))
      throw InputError(path + ": " + group + "/box is not three positive lengths");
    out.box = Vec3(box[0], box[1], box[2]);
    out.shear_offset = finite(h5::double_attribute(f.id(), group, "shear_offset"), group + " shear_offset");
    if (h5::has_attribute(f.id(), ".", "case")) {
      const YAML::Node run_case = YAML::Load(h5::string_attribute(f.id(), ".", "case"));
      if (run_case["particles"] && run_case["particles"]["phi"])
        out.requested_phi = run_case["particles"]["phi"].as<double>();
    }
    return out;
  } catch (const YAML::Exception& e) {
    throw InputError("particles.initial.file: " + path + ": its case attribute is not readable (" + e.what() + ")");
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const InputError*>(&e)) throw;
    throw InputError(std::string("particles.initial.file: ") + e.what());
  }
}

InitialConfiguration build_initial_configuration(const Case& c) {
  InitialConfiguration ic;
  if (c.particles.initial == "random") {
    const Composition k = composition_of(c);
    PackingParams pp;
    pp.seed = static_cast<std::uint64_t>(c.run.seed);
    pp.min_gap = c.particles.min_gap;
    Packing packing = random_packing(k.radius, k.box, pp);
    ic.particles.resize(k.radius.size());
    ic.particles.position = std::move(packing.position);
    ic.particles.radius = k.radius;
    ic.particles.species = k.species;
    ic.box = k.box;
    ic.packing = packing.report;
    std::ostringstream o;
    o << "random packing of " << k.radius.size() << " particles at phi = " << packing.report.phi
      << " (min gap " << packing.report.min_gap << " a_1, " << packing.report.wall_seconds << " s)";
    ic.origin = o.str();
  } else {
    const std::string& f = c.particles.initial_file;
    const bool h5file = f.size() > 3 && (f.ends_with(".h5") || f.ends_with(".hdf5"));
    StoredParticles stored;
    if (h5file) stored = read_particles_h5(f);
    else stored.particles = read_particle_table(f);
    ic.particles = std::move(stored.particles);
    if (ic.particles.size() < 2) throw InputError("particles.initial.file: " + f + " holds fewer than two particles");
    if (c.particles.count && *c.particles.count != static_cast<long>(ic.particles.size()))
      throw InputError("particles.count: " + std::to_string(*c.particles.count) + " disagrees with the " +
                       std::to_string(ic.particles.size()) + " particles of " + f + "; leave it out or make them agree");
    const double vol = ic.particles.volume();
    if (stored.box) {
      // A snapshot: its own box, so its phi (a given box must be the same one).
      if (c.box && (*c.box - *stored.box).norm() > 1e-12 * stored.box->norm())
        throw InputError("box: differs from the box of the snapshot in " + f + "; leave box out to use the snapshot's");
      ic.box = Box(*stored.box);
    } else {
      ic.box = c.box ? Box(*c.box) : Box(Vec3::Constant(std::cbrt(vol / c.particles.phi)));
    }
    // Lees-Edwards: the sheared state goes on from its own offset, so its images (and contacts) stay where they were.
    double offset = stored.shear_offset ? *stored.shear_offset : stored.strain ? *stored.strain * ic.box.length().y() : 0.0;
    std::string compressed;
    if (c.particles.compress) {
      // A uniform rescaling of the box, the positions and the offset (the same sheared arrangement, every
      // centre-to-centre distance times s) to the requested phi; the run's first strain relaxes the overlaps it
      // makes (docs/campaigns.md, "Searching for phi_m").
      const double from_phi = vol / ic.box.volume();
      if (std::abs(c.particles.phi / from_phi - 1.0) > 0.1)
        throw InputError("particles.initial.compress: from phi " + exact(from_phi) + " to " + exact(c.particles.phi) +
                         " is more than 10%; the rescaled spheres would overlap far beyond their roughness");
      const double s = std::cbrt(from_phi / c.particles.phi);
      ic.box = Box(ic.box.length() * s);
      for (Vec3& r : ic.particles.position) r *= s;
      offset *= s;
      std::ostringstream o;
      o << ", rescaled by " << s << " from phi " << from_phi << " to " << c.particles.phi;
      compressed = o.str();
    }
    if (stored.shear_offset || stored.strain) ic.box.set_offset_origin(offset);
    for (Vec3& r : ic.particles.position) ic.box.wrap(r);
    ic.origin = "loaded " + std::to_string(ic.particles.size()) + " particles from " + f;
    if (stored.box) {
      std::ostringstream o;
      o << " (its box and Lees-Edwards offset " << ic.box.offset_origin() << compressed << ")";
      ic.origin += o.str();
    }
    ic.phi = ic.particles.volume() / ic.box.volume();
    // The phi the snapshot's run asked for names the same state as the phi it reached.
    const bool requested = c.particles.compress ||
                           (stored.requested_phi && std::abs(*stored.requested_phi - c.particles.phi) < 1e-12);
    if (!requested && std::abs(ic.phi - c.particles.phi) > 1e-3)
      throw InputError("particles.phi = " + exact(c.particles.phi) + " does not match the file's particles in this box (phi = " +
                       exact(ic.phi) + (stored.requested_phi ? ", asked for as " + exact(*stored.requested_phi) : std::string()) +
                       "); set particles.phi to the file's value" + (stored.box ? "" : " or give the matching box"));
    return ic;
  }
  ic.phi = ic.particles.volume() / ic.box.volume();
  return ic;
}

}  // namespace suspend::io
