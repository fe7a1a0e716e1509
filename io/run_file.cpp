#include "io/run_file.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "core/error.hpp"
#include "core/version.hpp"

namespace suspend::io {

namespace {
struct Column {
  const char* name;
  const char* units;  // lengths in a_1, times in 1/gammadot_ref, stresses in eta_0 gammadot_ref (docs/units.md)
  bool integer;
};
const std::array<Column, 14> scalar_columns = {{{"step", "1", true},
                                                {"time", "1/gammadot_ref", false},
                                                {"strain", "1", false},
                                                {"accumulated_strain", "1", false},
                                                {"shear_rate", "gammadot_ref", false},
                                                {"dt", "1/gammadot_ref", false},
                                                {"contacts", "1", true},
                                                {"max_overlap", "a_1", false},
                                                {"eta_r", "eta_0", false},
                                                {"N1", "eta_0 gammadot_ref", false},
                                                {"N2", "eta_0 gammadot_ref", false},
                                                {"Pi", "eta_0 gammadot_ref", false},
                                                {"solver_iterations", "1", true},
                                                {"solver_residual", "1", false}}};
std::array<double, 6> components_of(const Mat3& m) {
  return {m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(0, 2), m(1, 2)};
}
}  // namespace

std::string snapshot_group(std::size_t index) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "snapshots/%06zu", index);
  return buf;
}

void RunFile::open_tables(bool create) {
  tables_.clear();
  auto table = [&](const std::string& name, hsize_t width, const char* units, bool integer) {
    const std::string path = "series/" + name;
    if (!create && name == "accumulated_strain" && !h5::exists(file_.id(), path)) {
      // Files from before the column: their runs were steady, whose accumulated strain is the strain.
      const h5::Table strain = h5::Table::open(file_.id(), "series/strain");
      h5::Table t = h5::Table::create(file_.id(), path, width, 256, integer);
      t.append_rows(strain.read_rows(strain.rows()).data(), strain.rows());
      h5::set_attribute(file_.id(), path, "units", std::string(units));
      tables_.emplace(name, std::move(t));
      return;
    }
    if (!create) {
      tables_.emplace(name, h5::Table::open(file_.id(), path));
      return;
    }
    tables_.emplace(name, h5::Table::create(file_.id(), path, width, 256, integer));
    h5::set_attribute(file_.id(), path, "units", std::string(units));
  };
  for (const Column& c : scalar_columns) table(c.name, 1, c.units, c.integer);
  table("stress/total", 6, "eta_0 gammadot_ref", false);
  for (auto name : contribution_names) table("stress/" + std::string(name), 6, "eta_0 gammadot_ref", false);
}

RunFile RunFile::create(const std::string& path, const RunAttributes& attributes) {
  RunFile r;
  r.file_ = h5::File::create(path);
  h5::set_attribute(r.file_.id(), ".", "case", attributes.case_yaml);
  h5::set_attribute(r.file_.id(), ".", "version", std::string(suspend::version));
  h5::set_attribute(r.file_.id(), ".", "git_commit", std::string(suspend::git_commit));
  h5::set_attribute(r.file_.id(), ".", "threads", static_cast<std::int64_t>(attributes.threads));
  h5::create_groups(r.file_.id(), "series/stress");
  std::string comps;
  for (const char* c : tensor_components) {
    if (!comps.empty()) comps += ' ';
    comps += c;
  }
  h5::set_attribute(r.file_.id(), "series/stress", "components", comps);
  h5::set_attribute(r.file_.id(), "series/stress", "units", std::string("eta_0 gammadot_ref"));
  h5::create_groups(r.file_.id(), "snapshots");
  r.open_tables(true);
  return r;
}

RunFile RunFile::reopen(const std::string& path, std::size_t series_rows, std::size_t snapshots) {
  try {
    return reopen_intact(path, series_rows, snapshots);
  } catch (const std::runtime_error& damaged) {
    // A write that failed (disk full) can leave objects written after the checkpoint that cannot be read or
    // deleted; what the checkpoint knew was complete when it was written. Rebuild from that, or report the damage.
    try {
      salvage(path, series_rows, snapshots);
    } catch (const std::exception&) {
      throw InputError("--restart: " + std::string(damaged.what()) +
                       "; it could not be rebuilt (a write that failed damaged it). The checkpoint is whole: continue "
                       "it into a new folder with --out NEW_DIR (its run.h5 starts at the checkpoint)");
    }
    RunFile r = reopen_intact(path, series_rows, snapshots);
    r.salvaged_ = std::string(damaged.what());
    return r;
  }
}

RunFile RunFile::reopen_intact(const std::string& path, std::size_t series_rows, std::size_t snapshots) {
  RunFile r;
  r.file_ = h5::File::open(path, true);
  r.open_tables(false);
  for (auto& [name, t] : r.tables_) {
    if (t.rows() < series_rows)
      throw std::runtime_error(path + ": series/" + name + " has fewer rows than the checkpoint expects");
    t.truncate(series_rows);
  }
  // Snapshots written after the checkpoint belong to the lost part of the run.
  for (std::size_t k = snapshots;; ++k) {
    const std::string g = snapshot_group(k);
    if (!h5::exists(r.file_.id(), g)) break;
    if (H5Ldelete(r.file_.id(), g.c_str(), H5P_DEFAULT) < 0)
      throw std::runtime_error(path + ": snapshot " + std::to_string(k) + " after the checkpoint cannot be removed");
  }
  for (std::size_t k = 0; k < snapshots; ++k)
    if (!h5::openable(r.file_.id(), snapshot_group(k)))
      throw std::runtime_error(path + ": snapshot " + std::to_string(k) + " that the checkpoint expects is missing");
  r.snapshots_ = snapshots;
  return r;
}

void RunFile::salvage(const std::string& path, std::size_t series_rows, std::size_t snapshots) {
  const std::string rebuilt = path + ".rebuilt";
  {
    h5::File old = h5::File::open(path, false);
    RunFile r = create(rebuilt, {});
    h5::copy_root_attributes(old.id(), r.file_.id());
    for (auto& [name, t] : r.tables_) {
      const h5::Table from = h5::Table::open(old.id(), "series/" + name);
      t.append_rows(from.read_rows(series_rows).data(), series_rows);
    }
    for (std::size_t k = 0; k < snapshots; ++k) h5::copy_object(old.id(), r.file_.id(), snapshot_group(k));
    r.flush();
  }
  std::filesystem::rename(path, path + ".damaged");
  std::filesystem::rename(rebuilt, path);
}

std::size_t RunFile::series_rows() const { return tables_.empty() ? 0 : tables_.begin()->second.rows(); }

void RunFile::append(const SeriesRow& row) {
  const Mat3 total = row.stress.total();
  const Rheology rh = rheology_of(total);
  const double rate = row.shear_rate;
  const std::map<std::string, double> scalars = {
      {"step", static_cast<double>(row.step)}, {"time", row.time}, {"strain", row.strain},
      {"accumulated_strain", row.accumulated_strain},
      {"shear_rate", rate}, {"dt", row.dt}, {"contacts", row.contacts}, {"max_overlap", row.max_overlap},
      {"eta_r", rh.shear / rate}, {"N1", rh.n1}, {"N2", rh.n2}, {"Pi", rh.pressure},
      {"solver_iterations", row.solver_iterations}, {"solver_residual", row.solver_residual}};
  for (const auto& [name, v] : scalars) tables_.at(name).append(&v);
  tables_.at("stress/total").append(components_of(total).data());
  for (std::size_t c = 0; c < contribution_count; ++c)
    tables_.at("stress/" + std::string(contribution_names[c])).append(components_of(row.stress.part[c]).data());
}

void RunFile::write_snapshot(const Snapshot& s) {
  const std::string g = snapshot_group(snapshots_);
  h5::create_groups(file_.id(), g);
  const Particles& p = *s.particles;
  const std::size_t n = p.size();
  auto vectors = [&](const std::vector<Vec3>& v) {
    std::vector<double> out(3 * n);
    for (std::size_t i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a) out[3 * i + a] = v[i][a];
    return out;
  };
  h5::write(file_.id(), g + "/position", vectors(p.position), {n, 3});
  h5::write(file_.id(), g + "/velocity", vectors(p.velocity), {n, 3});
  h5::write(file_.id(), g + "/angular_velocity", vectors(p.angular_velocity), {n, 3});
  h5::write(file_.id(), g + "/radius", p.radius, {n});
  h5::write(file_.id(), g + "/species", std::vector<std::int64_t>(p.species.begin(), p.species.end()), {n});
  const std::size_t m = s.contact_pairs.size() / 2;
  h5::write(file_.id(), g + "/contact_pairs", s.contact_pairs, {m, 2});
  h5::write(file_.id(), g + "/contact_force", s.contact_force, {m, 3});
  if (s.contact_gap.size() == m) {  // the contacts' own quantities (a Snapshot built by hand may leave them out)
    h5::write(file_.id(), g + "/contact_gap", s.contact_gap, {m});
    h5::write(file_.id(), g + "/contact_normal_force", s.contact_normal_force, {m});
    h5::write(file_.id(), g + "/contact_tangential_force", s.contact_tangential_force, {m, 3});
    h5::write(file_.id(), g + "/contact_sliding", s.contact_sliding, {m});
  }
  // The network as line segments for ParaView (run.xdmf): r_i and r_i + d, d the minimum image, so that a contact
  // through a periodic or sheared face is drawn at its length instead of across the box.
  std::vector<double> segments(6 * m);
  std::vector<std::int64_t> nodes(2 * m);
  for (std::size_t k = 0; k < m; ++k) {
    const Vec3& ri = p.position[static_cast<std::size_t>(s.contact_pairs[2 * k])];
    const Vec3 rj = ri + s.box.minimum_image(ri, p.position[static_cast<std::size_t>(s.contact_pairs[2 * k + 1])]).d;
    for (int a = 0; a < 3; ++a) segments[6 * k + a] = ri[a], segments[6 * k + 3 + a] = rj[a];
    nodes[2 * k] = static_cast<std::int64_t>(2 * k), nodes[2 * k + 1] = static_cast<std::int64_t>(2 * k + 1);
  }
  h5::write(file_.id(), g + "/contact_segments", segments, {2 * m, 3});
  h5::write(file_.id(), g + "/contact_segment_nodes", nodes, {m, 2});
  h5::set_attribute(file_.id(), g, "step", s.step);
  h5::set_attribute(file_.id(), g, "time", s.time);
  h5::set_attribute(file_.id(), g, "strain", s.strain);
  h5::set_attribute(file_.id(), g, "accumulated_strain", s.accumulated_strain);
  h5::set_attribute(file_.id(), g, "shear_offset", s.box.shear_offset());
  h5::write(file_.id(), g + "/box", std::vector<double>{s.box.length().x(), s.box.length().y(), s.box.length().z()},
            {3});
  ++snapshots_;
}

std::vector<SnapshotInfo> RunFile::snapshots() const {
  std::vector<SnapshotInfo> out;
  for (std::size_t k = 0; k < snapshots_; ++k) {
    const std::string g = snapshot_group(k);
    SnapshotInfo info{g, h5::double_attribute(file_.id(), g, "time"), h5::double_attribute(file_.id(), g, "strain"),
                      static_cast<std::size_t>(h5::shape_of(file_.id(), g + "/radius")[0]),
                      static_cast<std::size_t>(h5::shape_of(file_.id(), g + "/contact_pairs")[0])};
    const std::vector<double> box = h5::read_doubles(file_.id(), g + "/box");
    info.box = Vec3(box.at(0), box.at(1), box.at(2));
    info.shear_offset = h5::double_attribute(file_.id(), g, "shear_offset");
    info.segments = h5::exists(file_.id(), g + "/contact_segments") && h5::exists(file_.id(), g + "/contact_gap");
    out.push_back(info);
  }
  return out;
}

std::vector<double> read_series(hid_t file, const std::string& name, int component) {
  std::vector<hsize_t> shape;
  std::vector<double> all = h5::read_doubles(file, "series/" + name, &shape);
  if (component < 0) return all;
  std::vector<double> out(shape[0]);
  for (hsize_t r = 0; r < shape[0]; ++r) out[r] = all[r * shape[1] + component];
  return out;
}

}  // namespace suspend::io
