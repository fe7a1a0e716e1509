#include "linalg/block_matrix.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <string>

#include "core/capacity.hpp"
#include "core/error.hpp"

namespace suspend {

void SymmetricBlockMatrix::set_structure(std::size_t n, const std::vector<BlockLink>& links,
                                         CouplingStorage storage) {
  links_ = links;
  set_structure(n, storage);
}

void SymmetricBlockMatrix::set_structure(std::size_t n, CouplingStorage storage) {
  const std::vector<BlockLink>& links = links_;
  scaled_ = false;
  storage_ = storage;
  rows_ = n;
  if (storage == CouplingStorage::dense) {
    diagonal_.resize(n);
    resize_with_headroom(coupling_, links.size());
  } else {
    packed_diagonal_.resize(n);
    resize_with_headroom(pair_form_, links.size());
    resize_with_headroom(slip_of_, links.size());
  }
  // Counting sort of the link ends by row: row r lists its links in link order.
  row_start_.assign(n + 1, 0);
  for (const BlockLink& l : links) {
    if (l.i == l.j || l.i >= n || l.j >= n)
      throw InputError("block link (" + std::to_string(l.i) + ", " + std::to_string(l.j) + ") is invalid for " +
                       std::to_string(n) + " particles");
    ++row_start_[l.i + 1];
    ++row_start_[l.j + 1];
  }
  for (std::size_t r = 0; r < n; ++r) row_start_[r + 1] += row_start_[r];
  resize_with_headroom(entries_, 2 * links.size());
  // Fill using row_start_[r] as a cursor, then shift back.
  for (std::size_t k = 0; k < links.size(); ++k) {
    const BlockLink& l = links[k];
    entries_[row_start_[l.i]++] = {l.j, static_cast<std::uint32_t>(k), false};
    entries_[row_start_[l.j]++] = {l.i, static_cast<std::uint32_t>(k), true};
  }
  for (std::size_t r = n; r > 0; --r) row_start_[r] = row_start_[r - 1];
  row_start_[0] = 0;
  row_split_.resize(n);
  for (std::size_t r = 0; r < n; ++r) {
    RowEntry* begin = entries_.data() + row_start_[r];
    RowEntry* end = entries_.data() + row_start_[r + 1];
    std::sort(begin, end, [](const RowEntry& a, const RowEntry& b) {
      return a.column != b.column ? a.column < b.column : a.link < b.link;
    });
    row_split_[r] = static_cast<std::uint32_t>(
        std::partition_point(begin, end, [r](const RowEntry& e) { return e.column < r; }) - entries_.data());
  }
}

bool SymmetricBlockMatrix::factor_diagonal() {
  if (scaled_) return true;  // already in scaled form
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(rows_);
  bool spd = true;
  if (storage_ == CouplingStorage::pair_form) {  // G_i = L_i^-1, packed, in place of D_i; the blocks stay plain
#pragma omp parallel for schedule(static) if (n > 512) reduction(&& : spd)
    for (std::ptrdiff_t r = 0; r < n; ++r) {
      const Eigen::LLT<Matrix6> llt(packed_diagonal_[r].unpacked());
      spd = spd && llt.info() == Eigen::Success;
      Matrix6 g = Matrix6::Identity();
      const Matrix6 l = llt.matrixL();
      solve_lower(l, g);
      pack_lower(g, packed_diagonal_[r].upper);
    }
    scaled_ = spd;
    return spd;
  }
#pragma omp parallel for schedule(static) if (n > 512) reduction(&& : spd)
  for (std::ptrdiff_t r = 0; r < n; ++r) {
    const Eigen::LLT<Matrix6> llt(diagonal_[r]);
    spd = spd && llt.info() == Eigen::Success;
    diagonal_[r] = llt.matrixL();
    diagonal_[r].triangularView<Eigen::StrictlyUpper>().setZero();  // the dense products below rely on it
  }
  if (!spd) return false;
  const std::ptrdiff_t nl = static_cast<std::ptrdiff_t>(links_.size());
#pragma omp parallel for schedule(static) if (nl > 512)
  for (std::ptrdiff_t k = 0; k < nl; ++k) {  // L_i^-1 C L_j^-T: (L_j^-1 (L_i^-1 C)^T)^T
    Matrix6& c = coupling_[k];
    solve_lower(diagonal_[links_[k].i], c);
    solve_lower(diagonal_[links_[k].j], c.transpose());
  }
  scaled_ = true;
  return true;
}

Vector6 SymmetricBlockMatrix::coupling_transpose_times(std::size_t k, const Vector6& v) const {
  if (storage_ == CouplingStorage::pair_form) return transpose_times(pair_form_[k], slip(k), v);
  if (!scaled_) return coupling_[k].transpose() * v;
  const Matrix6& l_i = diagonal_[links_[k].i];
  const Matrix6& l_j = diagonal_[links_[k].j];
  const Vector6 w = l_i.transpose() * v;  // L stored with zeros above its diagonal
  return l_j * Vector6(coupling_[k].transpose() * w);
}

void SymmetricBlockMatrix::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(rows_);
  y.resize(x.size());
  if (storage_ == CouplingStorage::pair_form) {  // D_r x_r = G_r^-1 G_r^-T x_r once scaled
#pragma omp parallel for schedule(static) if (n > 512)
    for (std::ptrdiff_t r = 0; r < n; ++r) {
      Vector6 acc = x.segment<6>(6 * r);
      if (scaled_) {
        const Matrix6 g = unpack_lower(packed_diagonal_[r].upper);
        solve_lower_transpose(g, acc);
        solve_lower(g, acc);
      } else {
        acc = packed_diagonal_[r].unpacked() * Vector6(acc);
      }
      for (const RowEntry* e = row_begin(r); e != row_end(r); ++e) acc += pair_form_times(*e, x);
      y.segment<6>(6 * r) = acc;
    }
    return;
  }
  if (!scaled_) {
#pragma omp parallel for schedule(static) if (n > 512)
    for (std::ptrdiff_t r = 0; r < n; ++r) {
      Vector6 acc = diagonal_[r] * x.segment<6>(6 * r);
      for (const RowEntry* e = row_begin(r); e != row_end(r); ++e) acc += apply(*e, x);
      y.segment<6>(6 * r) = acc;
    }
    return;
  }
  // A x = S^-1 (I + N + N^T) S^-T x: w = L^T x, then row r is L_r (w_r + sum_c A'_rc w_c). L_r is stored with
  // zeros above its diagonal, so the full 6x6 products (vectorised) give the triangular ones.
  scaled_x_.resize(x.size());
#pragma omp parallel for schedule(static) if (n > 512)
  for (std::ptrdiff_t r = 0; r < n; ++r)
    scaled_x_.segment<6>(6 * r).noalias() = diagonal_[r].transpose() * x.segment<6>(6 * r);
#pragma omp parallel for schedule(static) if (n > 512)
  for (std::ptrdiff_t r = 0; r < n; ++r) {
    Vector6 acc = scaled_x_.segment<6>(6 * r);
    for (const RowEntry* e = row_begin(r); e != row_end(r); ++e) acc += apply(*e, scaled_x_);
    y.segment<6>(6 * r).noalias() = diagonal_[r] * acc;
  }
}

void SymmetricBlockMatrix::set_diagonal(std::size_t r, const Vector6& values) {
  if (storage_ == CouplingStorage::pair_form) {
    PackedSymmetric6& d = packed_diagonal_[r];
    d.upper.fill(0.0);
    for (int c = 0; c < 6; ++c) d.upper[PackedSymmetric6::diagonal_index(c)] = values[c];
  } else {
    diagonal_[r].setZero();
    diagonal_[r].diagonal() = values;
  }
}

void SymmetricBlockMatrix::add_to_diagonal(std::size_t r, const PackedSymmetric6& block) {
  if (storage_ == CouplingStorage::pair_form)
    block.add_to(packed_diagonal_[r]);
  else
    block.add_to(diagonal_[r]);
}

Matrix6 SymmetricBlockMatrix::plain_diagonal(std::size_t r) const {
  if (storage_ == CouplingStorage::pair_form) {
    if (!scaled_) return packed_diagonal_[r].unpacked();
    const Matrix6 l = unpack_lower(packed_diagonal_[r].upper).inverse();
    return l * l.transpose();
  }
  return scaled_ ? Matrix6(diagonal_[r] * diagonal_[r].transpose()) : diagonal_[r];
}

Matrix6 SymmetricBlockMatrix::plain_coupling(std::size_t k) const {
  if (storage_ == CouplingStorage::pair_form) return expand(pair_form_[k], slip(k));
  const BlockLink& l = links_[k];
  return scaled_ ? Matrix6(diagonal_[l.i] * coupling_[k] * diagonal_[l.j].transpose()) : coupling_[k];
}

Eigen::MatrixXd SymmetricBlockMatrix::dense() const {
  const std::size_t n = rows_;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(6 * n, 6 * n);
  for (std::size_t r = 0; r < n; ++r) a.block<6, 6>(6 * r, 6 * r) = plain_diagonal(r);
  for (std::size_t k = 0; k < links_.size(); ++k) {
    const BlockLink& l = links_[k];
    const Matrix6 c = plain_coupling(k);
    a.block<6, 6>(6 * l.i, 6 * l.j) += c;
    a.block<6, 6>(6 * l.j, 6 * l.i) += c.transpose();
  }
  return a;
}

}  // namespace suspend
