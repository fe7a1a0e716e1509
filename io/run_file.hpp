// DIR/run.h5: the record of a run (docs/output.md).
//   /                      attributes: case (resolved YAML), version, git_commit, threads
//   /series/{step,time,strain,shear_rate,dt,contacts,max_overlap,eta_r,N1,N2,Pi}      one row per record
//   /series/stress/{total,hydrodynamic,lubrication,...}   (rows, 6): xx yy zz xy xz yz, units eta_0 gammadot_ref
//   /snapshots/NNNNNN/{position,radius,species,velocity,angular_velocity,
//                      contact_pairs,contact_force,contact_gap,contact_normal_force,contact_tangential_force,contact_sliding,
//                      contact_segments,contact_segment_nodes}
//                          plus box (3 lengths); attributes: step, time, strain, shear_offset
// The file grows during the run and is flushed at every checkpoint; a restart truncates it back to the rows and
// snapshots the checkpoint knew about, so a killed-and-restarted run ends with the same file as an unbroken one.
#pragma once
#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/box.hpp"
#include "core/particles.hpp"
#include "core/stress.hpp"
#include "io/hdf5.hpp"

namespace suspend::io {

inline constexpr std::array<const char*, 6> tensor_components = {"xx", "yy", "zz", "xy", "xz", "yz"};

struct SeriesRow {
  std::int64_t step = 0;
  double time = 0.0, strain = 0.0, shear_rate = 1.0, dt = 0.0;
  double accumulated_strain = 0.0;  // integral of |gammadot| dt (core/flow.hpp)
  double contacts = 0.0, max_overlap = 0.0;
  // Iterations and relative residual of the step's hydrodynamic solve (pairwise: conjugate gradient; FCM: GMRES,
  // both parts under stress control); zero without a solve.
  double solver_iterations = 0.0, solver_residual = 0.0;
  StressTensors stress;
};

struct Snapshot {
  std::int64_t step = 0;
  double time = 0.0, strain = 0.0, accumulated_strain = 0.0;
  Box box;
  const Particles* particles = nullptr;
  // The contacts only (pairs on which the contact law exerts a normal force, docs/output.md), in pair order:
  std::vector<std::int64_t> contact_pairs;    // 2 per contact
  std::vector<double> contact_force;          // 3 per contact: every pair force on the second particle
  std::vector<double> contact_gap;            // surface gap r - a_i - a_j (negative: overlap)
  std::vector<double> contact_normal_force;   // contact law's normal force on j along n = d/|d| (> 0: repulsive)
  std::vector<double> contact_tangential_force;  // 3 per contact: its tangential force on j
  std::vector<std::int64_t> contact_sliding;  // 1 where the tangential force is at its Coulomb limit
};

struct SnapshotInfo {
  std::string group;
  double time, strain;
  std::size_t particles, contacts;
  Vec3 box = Vec3::Ones();
  double shear_offset = 0.0;
  bool segments = false;  // contact_segments written (files before them draw no contact network)
};

struct RunAttributes {
  std::string case_yaml;
  int threads = 1;
};

class RunFile {
 public:
  static RunFile create(const std::string& path, const RunAttributes& attributes);
  // Reopens for a restart and cuts the series and snapshots back to the given counts. A file damaged by a failed
  // write (disk full) is rebuilt from those rows and snapshots first, the damaged one kept as PATH.damaged
  // (salvaged() then says what was wrong).
  static RunFile reopen(const std::string& path, std::size_t series_rows, std::size_t snapshots);

  void append(const SeriesRow& row);
  void write_snapshot(const Snapshot& snapshot);
  void flush() const { file_.flush(); }
  void close() { tables_.clear(), file_.close(); }

  std::size_t series_rows() const;
  std::size_t snapshot_count() const { return snapshots_; }
  std::vector<SnapshotInfo> snapshots() const;
  hid_t id() const { return file_.id(); }
  const std::string& salvaged() const { return salvaged_; }

 private:
  static RunFile reopen_intact(const std::string& path, std::size_t series_rows, std::size_t snapshots);
  static void salvage(const std::string& path, std::size_t series_rows, std::size_t snapshots);
  void open_tables(bool create);
  h5::File file_;
  std::map<std::string, h5::Table> tables_;
  std::size_t snapshots_ = 0;
  std::string salvaged_;
};

std::string snapshot_group(std::size_t index);

// One column of the series, e.g. "eta_r" or "stress/contact_normal" (then `component` picks xx..yz).
std::vector<double> read_series(hid_t file, const std::string& name, int component = -1);

}  // namespace suspend::io
