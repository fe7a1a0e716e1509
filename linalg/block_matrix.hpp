// Symmetric sparse matrix of 6x6 blocks: the resistance matrix R_Stokes + sum_pairs R_lub of the overdamped solve.
// One block row per particle (U_i, Omega_i); one diagonal block per particle and one coupling block per link (i, j),
// stored once as the block (i, j); the block (j, i) is its transpose, so the matrix is symmetric by construction.
//
// Diagonal scaling (factor_diagonal, for the conjugate gradient): D_i = L_i L_i^T (Cholesky), and the matrix keeps
// A' = S A S^T, S = diag(L_i^-1) (unit diagonal blocks) in place of A: coupling() then holds L_i^-1 C L_j^-T and
// diagonal() holds L_i. Products with A (multiply, coupling_transpose_times, dense) stay available from A' and L,
// A = S^-1 A' S^-T, so the scaled form replaces the plain one instead of being stored beside it (288 B a link).
//
// Storage (set_structure): dense 6x6 coupling blocks (the default), or CouplingStorage::pair_form, each block as a
// PairFormBlock (pair_form_block.hpp: n and 6 numbers, 72 B instead of 288 B; with a SlipForm for the links whose
// contact slides), for the largest systems. Its diagonal blocks are packed too (packed_diagonal(), 21 numbers; plain:
// the symmetric D_i; scaled: G_i = L_i^-1, lower, see pack_lower), and diagonal() is empty. A pair-form block cannot be
// scaled in place, so the scaled form keeps the plain blocks C: A'_ij v = G_i C_ij G_j^T v.
//
// Layout: the coupling blocks are contiguous in link order; each block row lists its links sorted by column (ties
// in link order), so the layout depends only on the link list, and the entries left of the diagonal (the strictly
// lower part L of A = L + D + L^T) come first. y = A x is a gather over block rows: threads write disjoint
// rows and sum in a fixed order, so the product is bit-identical for any thread count. set_structure reuses its
// storage: no allocation once the largest link count has been seen.
#pragma once
#include <Eigen/Dense>
#include <array>
#include <cstdint>
#include <vector>

#include "linalg/pair_form_block.hpp"

namespace suspend {

enum class CouplingStorage { dense, pair_form };

// X <- L^-1 X for a lower-triangular 6x6 L and X with 6 rows (forward substitution; fixed sizes, which Eigen's
// general triangular solvers do not specialise).
template <class X>
inline void solve_lower(const Matrix6& l, X&& x) {
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < r; ++c) x.row(r) -= l(r, c) * x.row(c);
    x.row(r) /= l(r, r);
  }
}

// X <- L^-T X (back substitution with the transpose of the lower-triangular L).
template <class X>
inline void solve_lower_transpose(const Matrix6& l, X&& x) {
  for (int r = 5; r >= 0; --r) {
    for (int c = r + 1; c < 6; ++c) x.row(r) -= l(c, r) * x.row(c);
    x.row(r) /= l(r, r);
  }
}

// A symmetric 6x6 block stored as its upper triangle, row by row. The self blocks of R_lub are exactly symmetric
// (hydro::PairLubrication::assemble builds them from n n^T and from transposed copies), so packing loses nothing
// and adding the packed block gives the same bits as adding the full one.
struct PackedSymmetric6 {
  std::array<double, 21> upper;
  // Index of (r, r) in upper.
  static constexpr int diagonal_index(int r) { return 6 * r - r * (r - 1) / 2; }
  void pack(const Matrix6& m) {
    int k = 0;
    for (int r = 0; r < 6; ++r)
      for (int c = r; c < 6; ++c) upper[k++] = m(r, c);
  }
  Matrix6 unpacked() const {
    Matrix6 m;
    int k = 0;
    for (int r = 0; r < 6; ++r)
      for (int c = r; c < 6; ++c) m(r, c) = m(c, r) = upper[k++];
    return m;
  }
  void add_to(PackedSymmetric6& d) const {
    for (std::size_t k = 0; k < upper.size(); ++k) d.upper[k] += upper[k];
  }
  void add_to(Matrix6& d) const {
    int k = 0;
    for (int r = 0; r < 6; ++r) {
      d(r, r) += upper[k++];
      for (int c = r + 1; c < 6; ++c, ++k) {
        d(r, c) += upper[k];
        d(c, r) += upper[k];
      }
    }
  }
};

// A lower-triangular 6x6 factor stored as its lower triangle row by row (entry (r, c), c <= r, at r (r + 1) / 2 + c),
// in the storage of a PackedSymmetric6.
inline Matrix6 unpack_lower(const std::array<double, 21>& g) {
  Matrix6 m = Matrix6::Zero();
  for (int r = 0, k = 0; r < 6; ++r)
    for (int c = 0; c <= r; ++c) m(r, c) = g[k++];
  return m;
}
inline void pack_lower(const Matrix6& m, std::array<double, 21>& g) {
  for (int r = 0, k = 0; r < 6; ++r)
    for (int c = 0; c <= r; ++c) g[k++] = m(r, c);
}
inline Vector6 lower_times(const std::array<double, 21>& g, const Vector6& v) {
  Vector6 y;
  for (int r = 0, k = 0; r < 6; ++r) {
    double s = 0.0;
    for (int c = 0; c <= r; ++c) s += g[k++] * v[c];
    y[r] = s;
  }
  return y;
}
inline Vector6 lower_transpose_times(const std::array<double, 21>& g, const Vector6& v) {
  Vector6 y = Vector6::Zero();
  for (int r = 0, k = 0; r < 6; ++r)
    for (int c = 0; c <= r; ++c) y[c] += g[k++] * v[r];
  return y;
}

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

  // n block rows; coupling blocks for these links. Values are left unset: fill diagonal() and coupling() (dense) or
  // pair_form() and slip_of() (pair form: slip_of()[k] is -1 or link k's entry in slips(), sized by the caller).
  // The matrix is then plain (not scaled).
  void set_structure(std::size_t n, const std::vector<BlockLink>& links,
                     CouplingStorage storage = CouplingStorage::dense);
  // The same for the links written into links_to_set() (no second copy of the link list).
  std::vector<BlockLink>& links_to_set() { return links_; }
  void set_structure(std::size_t n, CouplingStorage storage);
  // Replaces A by its scaled form (see above; nothing to do if it is already). Returns false, leaving the matrix
  // unusable, if a diagonal block is not positive definite.
  bool factor_diagonal();
  bool scaled() const { return scaled_; }
  CouplingStorage storage() const { return storage_; }

  std::size_t block_rows() const { return rows_; }
  std::size_t size() const { return 6 * rows_; }
  std::size_t links() const { return links_.size(); }
  const std::vector<BlockLink>& link_list() const { return links_; }

  std::vector<Matrix6>& diagonal() { return diagonal_; }
  const std::vector<Matrix6>& diagonal() const { return diagonal_; }
  std::vector<Matrix6>& coupling() { return coupling_; }
  const std::vector<Matrix6>& coupling() const { return coupling_; }
  // Assembly of the plain matrix, either storage: diagonal block r set to diag(values), and a symmetric block added.
  void set_diagonal(std::size_t r, const Vector6& values);
  void add_to_diagonal(std::size_t r, const PackedSymmetric6& block);
  // The plain (unscaled) blocks, either storage: diagonal block r and coupling block k (for diagnostics, dense()).
  Matrix6 plain_diagonal(std::size_t r) const;
  Matrix6 plain_coupling(std::size_t k) const;
  std::vector<PackedSymmetric6>& packed_diagonal() { return packed_diagonal_; }
  const std::vector<PackedSymmetric6>& packed_diagonal() const { return packed_diagonal_; }
  // Pair form, scaled: G_r v and G_r^T v.
  Vector6 g_times(std::size_t r, const Vector6& v) const { return lower_times(packed_diagonal_[r].upper, v); }
  Vector6 g_transpose_times(std::size_t r, const Vector6& v) const {
    return lower_transpose_times(packed_diagonal_[r].upper, v);
  }
  std::vector<PairFormBlock>& pair_form() { return pair_form_; }
  const std::vector<PairFormBlock>& pair_form() const { return pair_form_; }
  std::vector<std::int32_t>& slip_of() { return slip_of_; }
  const std::vector<std::int32_t>& slip_of() const { return slip_of_; }
  std::vector<SlipForm>& slips() { return slips_; }
  const SlipForm* slip(std::size_t k) const { return slip_of_[k] < 0 ? nullptr : &slips_[slip_of_[k]]; }
  // Pair form: the plain block of an entry times x's column.
  Vector6 pair_form_times(const RowEntry& e, const Eigen::VectorXd& x) const {
    const auto xc = x.segment<6>(6 * static_cast<Eigen::Index>(e.column));
    return e.transposed ? transpose_times(pair_form_[e.link], slip(e.link), xc)
                        : times(pair_form_[e.link], slip(e.link), xc);
  }

  // Entries of block row r, by column; [row_begin, row_diagonal) are left of the diagonal, the rest right of it.
  const RowEntry* row_begin(std::size_t r) const { return entries_.data() + row_start_[r]; }
  const RowEntry* row_diagonal(std::size_t r) const { return entries_.data() + row_split_[r]; }
  const RowEntry* row_end(std::size_t r) const { return entries_.data() + row_start_[r + 1]; }
  // The block of an entry: coupling(link) or its transpose (of the stored form, plain or scaled).
  Vector6 apply(const RowEntry& e, const Eigen::VectorXd& x) const {
    const auto xc = x.segment<6>(6 * static_cast<Eigen::Index>(e.column));
    return e.transposed ? Vector6(coupling_[e.link].transpose() * xc) : Vector6(coupling_[e.link] * xc);
  }
  // C_k^T v for the coupling block C_k of A (block (j, i) of link k = (i, j)), plain or scaled.
  Vector6 coupling_transpose_times(std::size_t k, const Vector6& v) const;

  // y = A x (x and y of length size(), distinct), plain or scaled.
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  // Dense copy of A, for tests and small diagnostics only.
  Eigen::MatrixXd dense() const;

 private:
  std::vector<BlockLink> links_;
  std::vector<Matrix6> diagonal_, coupling_;
  std::vector<PairFormBlock> pair_form_;
  std::vector<PackedSymmetric6> packed_diagonal_;
  std::size_t rows_ = 0;
  std::vector<std::int32_t> slip_of_;
  std::vector<SlipForm> slips_;
  CouplingStorage storage_ = CouplingStorage::dense;
  std::vector<std::uint32_t> row_start_, row_split_;
  std::vector<RowEntry> entries_;
  bool scaled_ = false;
  mutable Eigen::VectorXd scaled_x_;  // multiply's L^T x in scaled form
};

}  // namespace suspend
