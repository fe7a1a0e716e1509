#include "linalg/block_matrix.hpp"

#include <algorithm>
#include <string>

#include "core/capacity.hpp"
#include "core/error.hpp"

namespace suspend {

void SymmetricBlockMatrix::set_structure(std::size_t n, const std::vector<BlockLink>& links) {
  links_ = links;
  diagonal_.resize(n);
  resize_with_headroom(coupling_, links.size());
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

void SymmetricBlockMatrix::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(diagonal_.size());
  y.resize(x.size());
#pragma omp parallel for schedule(static) if (n > 512)
  for (std::ptrdiff_t r = 0; r < n; ++r) {
    Vector6 acc = diagonal_[r] * x.segment<6>(6 * r);
    for (const RowEntry* e = row_begin(r); e != row_end(r); ++e) acc += apply(*e, x);
    y.segment<6>(6 * r) = acc;
  }
}

Eigen::MatrixXd SymmetricBlockMatrix::dense() const {
  const std::size_t n = diagonal_.size();
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(6 * n, 6 * n);
  for (std::size_t r = 0; r < n; ++r) a.block<6, 6>(6 * r, 6 * r) = diagonal_[r];
  for (std::size_t k = 0; k < links_.size(); ++k) {
    const BlockLink& l = links_[k];
    a.block<6, 6>(6 * l.i, 6 * l.j) += coupling_[k];
    a.block<6, 6>(6 * l.j, 6 * l.i) += coupling_[k].transpose();
  }
  return a;
}

}  // namespace suspend
