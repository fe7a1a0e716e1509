#include "linalg/sparse_cholesky.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace suspend {

void PatternCholesky::build_pattern(const SymmetricBlockMatrix& a) {
  const std::size_t n = a.block_rows();
  pattern_rows_ = n;
  pattern_links_ = a.link_list();
  column_start_.assign(n + 1, 0);
  lower_.clear();
  distinct_.assign(n, 0);
  std::vector<std::pair<std::uint32_t, LowerBlock>> column;  // (block row r, block), only on pattern changes
  for (std::size_t c = 0; c < n; ++c) {
    column.clear();
    for (const auto* e = a.row_begin(c); e != a.row_end(c); ++e)
      if (e->column > c) column.push_back({e->column, {e->link, !e->transposed, 0}});
    std::stable_sort(column.begin(), column.end(), [](const auto& u, const auto& v) { return u.first < v.first; });
    std::uint32_t rank = 0;
    for (std::size_t k = 0; k < column.size(); ++k) {
      if (k > 0 && column[k].first != column[k - 1].first) ++rank;
      column[k].second.rank = rank;
      lower_.push_back(column[k].second);
    }
    distinct_[c] = column.empty() ? 0 : rank + 1;
    column_start_[c + 1] = static_cast<std::uint32_t>(lower_.size());
  }

  // Compressed column storage of the lower triangle: column 6c + q holds rows 6c + q .. 6c + 5 of the diagonal
  // block, then the six rows of each distinct lower block in increasing order.
  const Eigen::Index size = static_cast<Eigen::Index>(6 * n);
  std::size_t nnz = 0;
  for (std::size_t c = 0; c < n; ++c) nnz += 21 + 36 * distinct_[c];
  matrix_.resize(size, size);
  matrix_.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  int* outer = matrix_.outerIndexPtr();
  int* inner = matrix_.innerIndexPtr();
  int pos = 0;
  for (std::size_t c = 0; c < n; ++c) {
    for (int q = 0; q < 6; ++q) {
      outer[6 * c + q] = pos;
      for (int r = q; r < 6; ++r) inner[pos++] = static_cast<int>(6 * c) + r;
      std::uint32_t last_row = 0;
      bool first = true;
      for (std::uint32_t k = column_start_[c]; k < column_start_[c + 1]; ++k) {
        const BlockLink& l = pattern_links_[lower_[k].link];
        const std::uint32_t row = l.i == c ? l.j : l.i;
        if (!first && row == last_row) continue;
        for (int r = 0; r < 6; ++r) inner[pos++] = static_cast<int>(6 * row) + r;
        last_row = row;
        first = false;
      }
    }
  }
  outer[size] = pos;
  llt_.analyzePattern(matrix_);
  ++analyses_;
  analysed_ = true;
}

void PatternCholesky::factorize(const SymmetricBlockMatrix& a) {
  if (!analysed_ || a.block_rows() != pattern_rows_ || a.link_list() != pattern_links_) build_pattern(a);
  const std::size_t n = a.block_rows();
  double* value = matrix_.valuePtr();
  const int* outer = matrix_.outerIndexPtr();
  for (std::size_t c = 0; c < n; ++c) {
    const Matrix6& d = a.diagonal()[c];
    for (int q = 0; q < 6; ++q) {
      const int base = outer[6 * c + q];
      for (int r = q; r < 6; ++r) value[base + r - q] = d(r, q);
      double* off = value + base + (6 - q);
      std::fill(off, value + outer[6 * c + q + 1], 0.0);
      for (std::uint32_t k = column_start_[c]; k < column_start_[c + 1]; ++k) {
        const LowerBlock& lb = lower_[k];
        const Matrix6& m = a.coupling()[lb.link];
        double* dst = off + 6 * lb.rank;
        for (int r = 0; r < 6; ++r) dst[r] += lb.transposed ? m(q, r) : m(r, q);
      }
    }
  }
  llt_.factorize(matrix_);
  if (llt_.info() != Eigen::Success)
    throw NumericalError("resistance solve: sparse Cholesky factorisation failed (matrix not positive definite)");
}

void PatternCholesky::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const { x = llt_.solve(b); }

}  // namespace suspend
