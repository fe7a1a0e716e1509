// Symmetric sparse matrix of 6x6 blocks: the resistance matrix R_Stokes + sum_pairs R_lub of the overdamped solve.
// One block row per particle (U_i, Omega_i); one diagonal block per particle and one coupling block per link (i, j),
// stored once as the block (i, j); the block (j, i) is its transpose, so the matrix is symmetric by construction.
//
// Layout: the coupling blocks are contiguous in link order; each block row lists its links sorted by column (ties
// in link order), so the layout depends only on the link list, and the entries left of the diagonal (the strictly
// lower part L of A = L + D + L^T) come first. y = A x is a gather over block rows: threads write disjoint
// rows and sum in a fixed order, so the product is bit-identical for any thread count. set_structure reuses its
// storage: no allocation once the largest link count has been seen.
#pragma once
#include <Eigen/Dense>
#include <cstdint>
#include <vector>

namespace suspend {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

struct BlockLink {
  std::uint32_t i, j;  // block row and column of the stored coupling block, i != j
  friend bool operator==(const BlockLink&, const BlockLink&) = default;
};

class SymmetricBlockMatrix {
 public:
  struct RowEntry {
    std::uint32_t column;  // the other particle
    std::uint32_t link;    // index of the coupling block
    bool transposed;       // true when this row is the link's j: the block (j, i) = coupling(link)^T
  };

  // n block rows; coupling blocks for these links. Values are left unset: fill diagonal() and coupling().
  void set_structure(std::size_t n, const std::vector<BlockLink>& links);

  std::size_t block_rows() const { return diagonal_.size(); }
  std::size_t size() const { return 6 * diagonal_.size(); }
  std::size_t links() const { return links_.size(); }
  const std::vector<BlockLink>& link_list() const { return links_; }

  std::vector<Matrix6>& diagonal() { return diagonal_; }
  const std::vector<Matrix6>& diagonal() const { return diagonal_; }
  std::vector<Matrix6>& coupling() { return coupling_; }
  const std::vector<Matrix6>& coupling() const { return coupling_; }

  // Entries of block row r, by column; [row_begin, row_diagonal) are left of the diagonal, the rest right of it.
  const RowEntry* row_begin(std::size_t r) const { return entries_.data() + row_start_[r]; }
  const RowEntry* row_diagonal(std::size_t r) const { return entries_.data() + row_split_[r]; }
  const RowEntry* row_end(std::size_t r) const { return entries_.data() + row_start_[r + 1]; }
  // The block of an entry: coupling(link) or its transpose.
  Vector6 apply(const RowEntry& e, const Eigen::VectorXd& x) const {
    const auto xc = x.segment<6>(6 * static_cast<Eigen::Index>(e.column));
    return e.transposed ? Vector6(coupling_[e.link].transpose() * xc) : Vector6(coupling_[e.link] * xc);
  }

  // y = A x (x and y of length size(), distinct).
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  // Dense copy, for tests and small diagnostics only.
  Eigen::MatrixXd dense() const;

 private:
  std::vector<BlockLink> links_;
  std::vector<Matrix6> diagonal_, coupling_;
  std::vector<std::uint32_t> row_start_, row_split_;
  std::vector<RowEntry> entries_;
};

}  // namespace suspend
