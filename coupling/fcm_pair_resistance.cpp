#include "coupling/fcm_pair_resistance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <sstream>

#include <unistd.h>

#include "core/error.hpp"
#include "coupling/pair_tensors.hpp"
#include "fcm/direct_sum.hpp"
#include "fcm/envelope.hpp"

namespace suspend::coupling {
using std::numbers::pi;
namespace {

constexpr int format_version = 1;

// All ResistanceScalars members written to and read from the cache, in this order.
constexpr std::array<double hydro::ResistanceScalars::*, 16> stored = correction_functions;

int grid_nodes(const FcmPairTableParams& p) {
  return static_cast<int>(std::ceil(p.box_factor * (p.a_i + p.a_j) / p.grid_spacing - 1e-9));
}

std::string header(const FcmPairTableParams& p) {
  std::ostringstream s;
  s << std::setprecision(17);
  s << "# suspend FCM-resolved two-sphere resistance (coupling/fcm_pair_resistance.hpp)\n"
    << "format " << format_version << "\n"
    << "a_i " << p.a_i << "\na_j " << p.a_j << "\ngrid_spacing " << p.grid_spacing << "\ntruncation_widths "
    << p.truncation_widths << "\ns_min " << p.s_min << "\ns_max " << p.s_max << "\nds " << p.ds << "\nbox_factor "
    << p.box_factor << "\nrigidity_tolerance " << p.rigidity_tolerance << "\n";
  return s.str();
}

}  // namespace

void FcmPairTableParams::validate() const {
  if (!(a_i > 0.0) || !(a_j > 0.0)) throw InputError("fcm.pair_table: radii must be > 0");
  if (!(grid_spacing > 0.0)) throw InputError("fcm.grid_spacing must be > 0");
  if (!(truncation_widths >= 2.0)) throw InputError("fcm.truncation_widths must be >= 2");
  if (!(s_min > 0.0 && s_max > s_min)) throw InputError("fcm.subgrid: need 0 < s_min < s_max (subgrid_cutoff)");
  if (!(ds > 0.0 && ds <= s_max - s_min + 1e-12)) throw InputError("fcm.subgrid: table spacing ds out of range");
  if (!(box_factor >= 6.0)) throw InputError("fcm.subgrid: box_factor must be >= 6");
  if (!(rigidity_tolerance > 0.0 && rigidity_tolerance < 1e-3))
    throw InputError("fcm.subgrid: pair-table rigidity tolerance must lie in (0, 1e-3)");
}

void measure_fcm_pair(fcm::Solver& solver, double a_i, double a_j, double r, hydro::ResistanceScalars& from_i,
                      hydro::ResistanceScalars& from_j) {
  using Mat12 = Eigen::Matrix<double, 12, 12>;
  const double l = solver.grid().length.x();
  const Vec3 c = Vec3::Constant(0.5 * l) + Vec3(0.137, 0.291, 0.373);
  const std::vector<Vec3> pos{c - Vec3(0.5 * r, 0.0, 0.0), c + Vec3(0.5 * r, 0.0, 0.0)};
  const std::vector<double> rad{a_i, a_j};
  Mat12 m = Mat12::Zero();
  std::array<std::array<Mat3, 12>, 2> sigma;  // stresslet of each sphere per unit load column
  Mat12 images = Mat12::Zero();
  for (int col = 0; col < 12; ++col) {
    const std::size_t who = col < 6 ? 0 : 1;
    const int k = col % 6;
    std::vector<Vec3> f(2, Vec3::Zero()), t(2, Vec3::Zero());
    (k < 3 ? f : t)[who][k % 3] = 1.0;
    const fcm::MobilityResult res = solver.solve({.positions = pos, .radii = rad, .forces = f, .torques = t});
    m.block<3, 1>(0, col) = res.velocities[0];
    m.block<3, 1>(3, col) = res.angular_velocities[0];
    m.block<3, 1>(6, col) = res.velocities[1];
    m.block<3, 1>(9, col) = res.angular_velocities[1];
    sigma[0][col] = res.stresslets[0];
    sigma[1][col] = res.stresslets[1];
    if (k < 3) {
      const fcm::Disturbance d = solver.apply(pos, rad, f, {}, {}, 0.0);
      images.block<3, 1>(0, col) = d.velocities[0];
      images.block<3, 1>(6, col) = d.velocities[1];
    }
  }
  // Periodic images of the monopoles: periodic minus free-space monopole mobility (translational block only).
  const double si = fcm::monopole_width(a_i), sj = fcm::monopole_width(a_j);
  const Mat3 pair = fcm::regularised_stokeslet(Vec3(r, 0.0, 0.0), si * si + sj * sj);
  images.block<3, 3>(0, 0) -= Mat3::Identity() / (6.0 * pi * a_i);
  images.block<3, 3>(6, 6) -= Mat3::Identity() / (6.0 * pi * a_j);
  images.block<3, 3>(0, 6) -= pair;
  images.block<3, 3>(6, 0) -= pair;
  for (int a : {0, 6})
    for (int b : {0, 6}) m.block<3, 3>(a, b) -= images.block<3, 3>(a, b);
  const Mat12 res = m.inverse();
  // dS/dV = Sigma R.
  std::array<std::array<Mat3, 12>, 2> dsdv;
  for (int a = 0; a < 2; ++a)
    for (int col = 0; col < 12; ++col) {
      Mat3 s = Mat3::Zero();
      for (int q = 0; q < 12; ++q) s += sigma[a][q] * res(q, col);
      dsdv[a][col] = s;
    }
  from_i = {};
  from_j = {};
  scalars_along_x(a_i, a_j, res, dsdv, from_i, from_j);
}

FcmPairTable::FcmPairTable(const FcmPairTableParams& params) : params_(params) {
  params_.validate();
  if (params_.a_i > params_.a_j) throw InputError("fcm.pair_table: store pairs with a_i <= a_j");
  const int n = grid_nodes(params_);
  const double l = n * params_.grid_spacing;
  fcm::SolverOptions o;
  o.truncation_widths = params_.truncation_widths;
  o.rigidity_tolerance = params_.rigidity_tolerance;
  o.max_rigidity_iterations = 1000;
  o.planning = fcm::FftPlanning::estimate;
  fcm::Solver solver(Vec3::Constant(l), {n, n, n}, o);
  const int count = static_cast<int>(std::floor((params_.s_max - params_.s_min) / params_.ds + 1e-9)) + 1;
  const double half_sum = 0.5 * (params_.a_i + params_.a_j);
  for (int k = 0; k < count; ++k) {
    const double s = params_.s_min + k * params_.ds;
    hydro::ResistanceScalars fi, fj;
    measure_fcm_pair(solver, params_.a_i, params_.a_j, s * half_sum, fi, fj);
    fi.xi = fj.xi = s - 2.0;
    s_.push_back(s);
    from_i_.push_back(fi);
    from_j_.push_back(fj);
  }
  // The last node must reach s_max so that the correction's cutoff lies inside the table.
  if (s_.back() < params_.s_max - 1e-12) {
    hydro::ResistanceScalars fi, fj;
    measure_fcm_pair(solver, params_.a_i, params_.a_j, (s_.back() + params_.ds) * half_sum, fi, fj);
    s_.push_back(s_.back() + params_.ds);
    from_i_.push_back(fi);
    from_j_.push_back(fj);
  }
  pack();
}

void FcmPairTable::pack() {
  packed_.resize(s_.size());
  for (std::size_t k = 0; k < s_.size(); ++k)
    for (std::size_t q = 0; q < stored.size(); ++q) {
      packed_[k][q] = from_i_[k].*stored[q];
      packed_[k][stored.size() + q] = from_j_[k].*stored[q];
    }
}

std::string FcmPairTable::file_name() const {
  std::ostringstream s;
  s << std::setprecision(6) << "fcm_pair_ai" << params_.a_i << "_aj" << params_.a_j << "_h" << params_.grid_spacing
    << "_t" << params_.truncation_widths << "_s" << params_.s_max << ".txt";
  return s.str();
}

void FcmPairTable::scalars(double s, hydro::ResistanceScalars& from_i, hydro::ResistanceScalars& from_j) const {
  const double ds = params_.ds;
  const double u = std::clamp((s - s_.front()) / ds, 0.0, static_cast<double>(s_.size() - 1));
  const std::size_t last = s_.size() - 1;
  const std::size_t k = std::min(static_cast<std::size_t>(u), last == 0 ? 0 : last - 1);
  const double t = u - static_cast<double>(k);
  // Catmull-Rom through nodes k-1, k, k+1, k+2 (end nodes repeated).
  const std::size_t k0 = k == 0 ? 0 : k - 1, k1 = k, k2 = std::min(k + 1, last), k3 = std::min(k + 2, last);
  const double t2 = t * t, t3 = t2 * t;
  const double w0 = 0.5 * (-t3 + 2.0 * t2 - t), w1 = 0.5 * (3.0 * t3 - 5.0 * t2 + 2.0);
  const double w2 = 0.5 * (-3.0 * t3 + 4.0 * t2 + t), w3 = 0.5 * (t3 - t2);
  const std::array<double, 32>&p0 = packed_[k0], &p1 = packed_[k1], &p2 = packed_[k2], &p3 = packed_[k3];
  std::array<double, 32> v;
  for (std::size_t q = 0; q < v.size(); ++q) v[q] = w0 * p0[q] + w1 * p1[q] + w2 * p2[q] + w3 * p3[q];
  from_i = {};
  from_j = {};
  from_i.xi = from_j.xi = s - 2.0;
  for (std::size_t q = 0; q < stored.size(); ++q) {
    from_i.*stored[q] = v[q];
    from_j.*stored[q] = v[stored.size() + q];
  }
}

void FcmPairTable::write(const std::string& path) const {
  // A private temporary name: tests running in parallel may write the same table at once.
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(tmp);
    if (!out) throw InputError("fcm.cache_dir: cannot write " + tmp);
    out << header(params_) << "rows " << s_.size() << "\n# s'";
    for (const char* name : correction_function_names) out << " " << name << "_i";
    for (const char* name : correction_function_names) out << " " << name << "_j";
    out << "\n" << std::setprecision(17);
    for (std::size_t k = 0; k < s_.size(); ++k) {
      out << s_[k];
      for (auto f : stored) out << " " << from_i_[k].*f;
      for (auto f : stored) out << " " << from_j_[k].*f;
      out << "\n";
    }
    if (!out) throw InputError("fcm.cache_dir: write failed for " + tmp);
  }
  std::filesystem::rename(tmp, path);
}

bool FcmPairTable::read(const std::string& path, const FcmPairTableParams& expected) {
  std::ifstream in(path);
  if (!in) return false;
  std::string line;
  std::getline(in, line);  // title
  std::ostringstream seen;
  seen << "# suspend FCM-resolved two-sphere resistance (coupling/fcm_pair_resistance.hpp)\n";
  const std::string want = header(expected);
  // Compare the parameter lines verbatim (17 significant digits): any difference means another table.
  std::size_t rows = 0;
  for (;;) {
    if (!std::getline(in, line)) return false;
    if (line.rfind("rows ", 0) == 0) {
      rows = std::stoul(line.substr(5));
      break;
    }
    seen << line << "\n";
  }
  if (seen.str() != want || rows < 2) return false;
  std::getline(in, line);  // column names
  std::vector<double> s(rows);
  std::vector<hydro::ResistanceScalars> fi(rows), fj(rows);
  for (std::size_t k = 0; k < rows; ++k) {
    if (!(in >> s[k])) return false;
    for (auto f : stored)
      if (!(in >> fi[k].*f)) return false;
    for (auto f : stored)
      if (!(in >> fj[k].*f)) return false;
    fi[k].xi = fj[k].xi = s[k] - 2.0;
  }
  params_ = expected;
  s_ = std::move(s);
  from_i_ = std::move(fi);
  from_j_ = std::move(fj);
  pack();
  return true;
}

FcmPairTable FcmPairTable::load_or_compute(const FcmPairTableParams& params, const std::string& cache_dir,
                                           bool* recomputed) {
  params.validate();
  FcmPairTable table;
  table.params_ = params;
  std::string path;
  if (!cache_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(cache_dir, ec);
    if (ec || !std::filesystem::is_directory(cache_dir))
      throw InputError("hydrodynamics.fcm.cache_dir: cannot create the directory '" + cache_dir + "'" +
                       (ec ? " (" + ec.message() + ")" : "") + "; give a writable folder");
    path = (std::filesystem::path(cache_dir) / table.file_name()).string();
    if (table.read(path, params)) {
      if (recomputed) *recomputed = false;
      return table;
    }
  }
  table = FcmPairTable(params);
  if (!path.empty()) {
    try {
      table.write(path);
    } catch (const std::exception& e) {
      throw InputError("hydrodynamics.fcm.cache_dir: cannot write '" + path + "' (" + e.what() +
                       "); give a writable folder");
    }
  }
  if (recomputed) *recomputed = true;
  return table;
}

}  // namespace suspend::coupling
