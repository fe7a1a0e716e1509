#include "io/snapshot_reader.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "io/hdf5.hpp"
#include "io/run_file.hpp"

namespace suspend::io {

std::size_t snapshot_count(hid_t run_file) {
  std::size_t k = 0;
  while (h5::exists(run_file, snapshot_group(k))) ++k;
  // Numbered from 0 without gaps: a group missing in the middle is damage, not the end of the run.
  H5G_info_t info{};
  if (h5::exists(run_file, "snapshots") && H5Gget_info_by_name(run_file, "snapshots", &info, H5P_DEFAULT) >= 0 &&
      info.nlinks != k)
    throw InputError(snapshot_group(k) + " is missing, yet /snapshots holds " + std::to_string(info.nlinks) +
                     " entries: the file is damaged (snapshots are numbered from 000000 without gaps)");
  return k;
}

analysis::Configuration read_configuration(hid_t run_file, std::size_t index) {
  const std::string g = snapshot_group(index);
  if (!h5::exists(run_file, g))
    throw InputError("snapshot " + std::to_string(index) + " not found (the run has " +
                     std::to_string(snapshot_count(run_file)) + " snapshots, numbered from 0)");
  analysis::Configuration c;
  c.step = h5::int_attribute(run_file, g, "step");
  c.time = h5::double_attribute(run_file, g, "time");
  c.strain = h5::double_attribute(run_file, g, "strain");
  const std::vector<double> box = h5::read_doubles(run_file, g + "/box");
  if (box.size() != 3 || !(box[0] > 0.0 && box[1] > 0.0 && box[2] > 0.0) || !std::isfinite(box[0] * box[1] * box[2]))
    throw InputError(g + "/box: not three positive finite lengths");
  c.box = Box(box[0], box[1], box[2]);
  const double offset = h5::double_attribute(run_file, g, "shear_offset");
  if (!std::isfinite(offset) || !std::isfinite(c.time) || !std::isfinite(c.strain))
    throw InputError(g + ": its time, strain or shear_offset is not finite");
  c.box.set_shear_offset(offset);
  const std::vector<double> position = h5::read_doubles(run_file, g + "/position");
  c.radius = h5::read_doubles(run_file, g + "/radius");
  const std::vector<std::int64_t> species = h5::read_ints(run_file, g + "/species");
  const std::size_t n = c.radius.size();
  if (position.size() != 3 * n || species.size() != n)
    throw InputError(g + ": position, radius and species differ in length");
  c.position.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    c.position[i] = Vec3(position[3 * i], position[3 * i + 1], position[3 * i + 2]);
    if (!c.position[i].allFinite() || !(c.radius[i] > 0.0) || !std::isfinite(c.radius[i]))
      throw InputError(g + ": particle " + std::to_string(i) + " has a non-finite position or a bad radius");
  }
  c.species.assign(species.begin(), species.end());
  if (h5::exists(run_file, g + "/velocity")) {
    const std::vector<double> velocity = h5::read_doubles(run_file, g + "/velocity");
    if (velocity.size() != 3 * n) throw InputError(g + "/velocity: not one vector per particle");
    c.velocity.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      c.velocity[i] = Vec3(velocity[3 * i], velocity[3 * i + 1], velocity[3 * i + 2]);
      if (!c.velocity[i].allFinite())
        throw InputError(g + "/velocity: particle " + std::to_string(i) + " is not finite");
    }
  }

  const std::vector<std::int64_t> pairs = h5::read_ints(run_file, g + "/contact_pairs");
  const std::vector<double> force = h5::read_doubles(run_file, g + "/contact_force");
  const std::size_t m = pairs.size() / 2;
  const bool detailed = h5::exists(run_file, g + "/contact_gap");  // files before the contacts' own quantities
  c.contact_details = detailed;
  std::vector<double> gap, normal, tangential;
  std::vector<std::int64_t> sliding;
  if (detailed) {
    gap = h5::read_doubles(run_file, g + "/contact_gap");
    normal = h5::read_doubles(run_file, g + "/contact_normal_force");
    tangential = h5::read_doubles(run_file, g + "/contact_tangential_force");
    sliding = h5::read_ints(run_file, g + "/contact_sliding");
  }
  if (force.size() != 3 * m || (detailed && (gap.size() != m || normal.size() != m || tangential.size() != 3 * m ||
                                             sliding.size() != m)))
    throw InputError(g + ": the contact datasets differ in length");
  c.contacts.resize(m);
  for (std::size_t k = 0; k < m; ++k) {
    analysis::Contact& ct = c.contacts[k];
    if (pairs[2 * k] < 0 || pairs[2 * k + 1] < 0 || static_cast<std::size_t>(pairs[2 * k]) >= n ||
        static_cast<std::size_t>(pairs[2 * k + 1]) >= n)
      throw InputError(g + "/contact_pairs: particle index out of range");
    ct.i = static_cast<std::uint32_t>(pairs[2 * k]);
    ct.j = static_cast<std::uint32_t>(pairs[2 * k + 1]);
    ct.force_on_j = Vec3(force[3 * k], force[3 * k + 1], force[3 * k + 2]);
    if (detailed) {
      ct.gap = gap[k];
      ct.normal_force = normal[k];
      ct.tangential_force = Vec3(tangential[3 * k], tangential[3 * k + 1], tangential[3 * k + 2]);
      ct.sliding = sliding[k] != 0;
    }
  }
  return c;
}

}  // namespace suspend::io
