#include "fcm/rigidity_preconditioner.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/box.hpp"
#include "core/error.hpp"
#include "fcm/direct_sum.hpp"
#include "fcm/envelope.hpp"

namespace suspend::fcm {
namespace {

// Orthonormal basis of the traceless symmetric matrices under A:B = sum A_ij B_ij.
const std::array<Mat3, 5>& basis() {
  static const std::array<Mat3, 5> b = [] {
    std::array<Mat3, 5> m;
    for (Mat3& x : m) x.setZero();
    m[0](0, 0) = 1.0 / std::sqrt(2.0);
    m[0](1, 1) = -1.0 / std::sqrt(2.0);
    m[1](0, 0) = m[1](1, 1) = 1.0 / std::sqrt(6.0);
    m[1](2, 2) = -2.0 / std::sqrt(6.0);
    m[2](0, 1) = m[2](1, 0) = 1.0 / std::sqrt(2.0);
    m[3](0, 2) = m[3](2, 0) = 1.0 / std::sqrt(2.0);
    m[4](1, 2) = m[4](2, 1) = 1.0 / std::sqrt(2.0);
    return m;
  }();
  return b;
}

// Candidate pairs i < j closer than cutoff (a_i + a_j) on the Lees-Edwards lattice, with their minimum-image
// separation Y_i - Y_j. A cell list in sheared coordinates x' = x - gamma_t y, where the lattice is a plain
// periodic box (sheared_grid.hpp); a physical separation below r_c has |dx'| < (1 + |gamma_t|) r_c.
struct Pair {
  std::uint32_t i, j;
  Vec3 r;
};

std::vector<Pair> near_pairs(const ShearedGrid& g, std::span<const Vec3> pos, std::span<const double> rad,
                             double cutoff) {
  const std::size_t n = pos.size();
  const double gt = g.shear_fraction;
  const Vec3 len = g.length;
  double rmax = 0.0;
  for (double a : rad) rmax = std::max(rmax, a);
  const double rc = 2.0 * cutoff * rmax;  // the largest pair cutoff
  std::array<int, 3> nc{};
  const double width[3] = {rc * (1.0 + std::abs(gt)), rc, rc};
  for (int d = 0; d < 3; ++d) {
    nc[d] = static_cast<int>(std::floor(len[d] / width[d]));
    if (nc[d] < 3) nc[d] = 1;  // a single cell: every particle is a candidate in that direction
  }
  std::vector<Vec3> s(n);
  std::vector<int> cell(n);
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 x(pos[i].x() - gt * pos[i].y(), pos[i].y(), pos[i].z());
    int c[3];
    for (int d = 0; d < 3; ++d) {
      x[d] -= len[d] * std::floor(x[d] / len[d]);
      c[d] = std::min(static_cast<int>(x[d] / len[d] * nc[d]), nc[d] - 1);
    }
    s[i] = x;
    cell[i] = (c[2] * nc[1] + c[1]) * nc[0] + c[0];
  }
  const int ncell = nc[0] * nc[1] * nc[2];
  std::vector<std::size_t> start(static_cast<std::size_t>(ncell) + 1, 0);
  for (int c : cell) ++start[static_cast<std::size_t>(c) + 1];
  for (int c = 0; c < ncell; ++c) start[c + 1] += start[c];
  std::vector<std::uint32_t> members(n);
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) members[fill[cell[i]]++] = static_cast<std::uint32_t>(i);
  }
  std::vector<Pair> pairs;
  for (std::size_t i = 0; i < n; ++i) {
    const int c0 = cell[i] % nc[0], c1 = (cell[i] / nc[0]) % nc[1], c2 = cell[i] / (nc[0] * nc[1]);
    const int lo[3] = {nc[0] > 1 ? -1 : 0, nc[1] > 1 ? -1 : 0, nc[2] > 1 ? -1 : 0};
    for (int oz = lo[2]; oz <= -lo[2]; ++oz)
      for (int oy = lo[1]; oy <= -lo[1]; ++oy)
        for (int ox = lo[0]; ox <= -lo[0]; ++ox) {
          const int c = (periodic_index(c2 + oz, nc[2]) * nc[1] + periodic_index(c1 + oy, nc[1])) * nc[0] +
                        periodic_index(c0 + ox, nc[0]);
          for (std::size_t k = start[c]; k < start[c + 1]; ++k) {
            const std::uint32_t j = members[k];
            if (j <= i) continue;
            Vec3 ds = s[i] - s[j];
            ds.y() = wrap_centered(ds.y(), len.y());
            ds.z() = wrap_centered(ds.z(), len.z());
            const Vec3 r(wrap_centered(ds.x() + gt * ds.y(), len.x()), ds.y(), ds.z());
            if (r.norm() < cutoff * (rad[i] + rad[j])) pairs.push_back({static_cast<std::uint32_t>(i), j, r});
          }
        }
  }
  return pairs;
}

}  // namespace

std::array<double, 5> stresslet_coordinates(const Mat3& s) {
  std::array<double, 5> c{};
  for (int a = 0; a < 5; ++a) c[a] = (basis()[a].array() * s.array()).sum();
  return c;
}

Mat3 stresslet_from_coordinates(const std::array<double, 5>& c) {
  Mat3 s = Mat3::Zero();
  for (int a = 0; a < 5; ++a) s += c[a] * basis()[a];
  return s;
}

std::array<std::array<double, 5>, 5> stresslet_pair_block(const Vec3& r, double radius_m, double radius_q) {
  const double sm = dipole_width(radius_m), sq = dipole_width(radius_q);
  const double variance = sm * sm + sq * sq, h = 1e-2 * std::sqrt(variance);
  // H[k][l] = d_k d_l M(r) by central differences.
  Mat3 hess[3][3];
  const Mat3 m0 = regularised_stokeslet(r, variance);
  for (int k = 0; k < 3; ++k) {
    const Vec3 ek = h * Vec3::Unit(k);
    hess[k][k] = (regularised_stokeslet(r + ek, variance) - 2.0 * m0 + regularised_stokeslet(r - ek, variance)) /
                 (h * h);
    for (int l = k + 1; l < 3; ++l) {
      const Vec3 el = h * Vec3::Unit(l);
      hess[k][l] = hess[l][k] =
          (regularised_stokeslet(r + ek + el, variance) - regularised_stokeslet(r + ek - el, variance) -
           regularised_stokeslet(r - ek + el, variance) + regularised_stokeslet(r - ek - el, variance)) /
          (4.0 * h * h);
    }
  }
  // K_ab = -B_a,ik H_ijkl B_b,jl.
  std::array<std::array<double, 5>, 5> block{};
  for (int b = 0; b < 5; ++b) {
    Mat3 e = Mat3::Zero();  // e_ik = H_ijkl B_b,jl
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) e.col(k) += hess[k][l] * basis()[b].col(l);
    for (int a = 0; a < 5; ++a) block[a][b] = -(basis()[a].array() * e.array()).sum();
  }
  return block;
}

// Incomplete block Cholesky, zero fill (IC(0)): L has the block pattern of the near-field matrix, row i holding
// L_ij for the neighbours j < i sorted by j (lower[row_begin[i] .. row_begin[i + 1])), and the Cholesky factor of
// the diagonal pivot block L_ii.
struct NearFieldPreconditioner::Factor {
  using Block = Eigen::Matrix<double, 5, 5>;
  std::vector<std::size_t> row_begin;
  std::vector<std::uint32_t> col;
  std::vector<Block> lower;
  std::vector<Eigen::LLT<Block>> pivot;
};

NearFieldPreconditioner::NearFieldPreconditioner() : factor_(std::make_unique<Factor>()) {}
NearFieldPreconditioner::~NearFieldPreconditioner() = default;
NearFieldPreconditioner::NearFieldPreconditioner(NearFieldPreconditioner&&) noexcept = default;
NearFieldPreconditioner& NearFieldPreconditioner::operator=(NearFieldPreconditioner&&) noexcept = default;

void NearFieldPreconditioner::build(const ShearedGrid& grid, std::span<const Vec3> positions,
                                    std::span<const double> radii, double cutoff) {
  using Block = Factor::Block;
  const std::size_t n = positions.size();
  std::vector<Pair> pairs = near_pairs(grid, positions, radii, cutoff);
  // Row j > i holds K_ji; rows sorted by column for the merges of the factorisation.
  std::sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) { return x.j != y.j ? x.j < y.j : x.i < y.i; });
  pairs_ = pairs.size();
  Factor& f = *factor_;
  f.row_begin.assign(n + 1, 0);
  for (const Pair& p : pairs) ++f.row_begin[p.j + 1];
  for (std::size_t i = 0; i < n; ++i) f.row_begin[i + 1] += f.row_begin[i];
  f.col.resize(pairs.size());
  std::vector<Block> k(pairs.size());  // K_ji = K_ij^T (stresslet_pair_block of r = Y_i - Y_j)
  const std::ptrdiff_t np = static_cast<std::ptrdiff_t>(pairs.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t p = 0; p < np; ++p) {
    const auto b = stresslet_pair_block(pairs[p].r, radii[pairs[p].i], radii[pairs[p].j]);
    for (int a = 0; a < 5; ++a)
      for (int c = 0; c < 5; ++c) k[p](a, c) = b[c][a];
    f.col[p] = pairs[p].i;
  }
  f.lower.resize(pairs.size());
  f.pivot.resize(n);
  // Up-looking IC(0): L_ij = (K_ij - sum_c L_ic L_jc^T) L_jj^-T over the common neighbours c < j, then
  // L_ii L_ii^T = K_ii - sum_j L_ij L_ij^T. An incomplete factor can meet a non-positive pivot: then the
  // diagonal is raised by 5%, 10%, 20%, ... and the factorisation restarted.
  shifts_ = 0;
  for (double raise = 0.0;; raise = raise == 0.0 ? 0.05 : 2.0 * raise) {
    bool ok = true;
    for (std::size_t i = 0; i < n && ok; ++i) {
      const std::size_t b = f.row_begin[i], e = f.row_begin[i + 1];
      Block d = (1.0 + raise) * stresslet_self_mobility(radii[i]) * Block::Identity();
      for (std::size_t q = b; q < e; ++q) {
        const std::uint32_t j = f.col[q];
        Block x = k[q];
        for (std::size_t u = b, v = f.row_begin[j], ve = f.row_begin[j + 1]; u < q && v < ve;) {
          if (f.col[u] < f.col[v]) {
            ++u;
          } else if (f.col[v] < f.col[u]) {
            ++v;
          } else {
            x.noalias() -= f.lower[u] * f.lower[v].transpose();
            ++u;
            ++v;
          }
        }
        f.lower[q] = f.pivot[j].matrixL().solve(x.transpose()).transpose();
        d.noalias() -= f.lower[q] * f.lower[q].transpose();
      }
      f.pivot[i].compute(d);
      ok = f.pivot[i].info() == Eigen::Success;
    }
    if (ok) break;
    if (++shifts_ > 20) throw NumericalError("fcm: near-field preconditioner cannot be factorised");
  }
}

void NearFieldPreconditioner::apply(std::span<const Mat3> r, std::span<Mat3> z) const {
  using V5 = Eigen::Matrix<double, 5, 1>;
  const Factor& f = *factor_;
  const std::size_t n = r.size();
  std::vector<V5> y(n);
  for (std::size_t i = 0; i < n; ++i) {  // L y = r
    const auto c = stresslet_coordinates(r[i]);
    V5 v = Eigen::Map<const V5>(c.data());
    for (std::size_t q = f.row_begin[i]; q < f.row_begin[i + 1]; ++q) v.noalias() -= f.lower[q] * y[f.col[q]];
    y[i] = f.pivot[i].matrixL().solve(v);
  }
  for (std::size_t i = n; i-- > 0;) {  // L^T z = y, column by column
    y[i] = f.pivot[i].matrixU().solve(y[i]);
    for (std::size_t q = f.row_begin[i]; q < f.row_begin[i + 1]; ++q)
      y[f.col[q]].noalias() -= f.lower[q].transpose() * y[i];
  }
  for (std::size_t i = 0; i < n; ++i) {
    std::array<double, 5> c{};
    Eigen::Map<V5>(c.data()) = y[i];
    z[i] = stresslet_from_coordinates(c);
  }
}

}  // namespace suspend::fcm
