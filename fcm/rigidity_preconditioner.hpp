// Near-field preconditioner of the rigidity solve (solver.hpp): an approximation P of the stresslet mobility K,
// K S = -e'(S) (5 traceless-symmetric unknowns per particle, symmetric positive definite), that keeps the exact
// isolated-sphere diagonal blocks plus the free-space FCM coupling of every pair closer than
// cutoff (a_m + a_q), factorised once per configuration by incomplete block Cholesky without fill (IC(0) on the
// 5 x 5 blocks; a full sparse Cholesky takes seconds at N = 3000 and gains little, docs/fcm.md).
//
// Pair block (Maxey & Patel 2001; Lomholt & Maxey 2003; fcm/direct_sum.hpp): the strain rate at m due to the
// stresslet S at q in unbounded fluid is e_m,ik = sym_ik(H_ijkl S_jl), H_ijkl = d_k d_l M_ij(Y_m - Y_q), with M the
// Gaussian-regularised Stokeslet of variance sD_m^2 + sD_q^2 (regularised_stokeslet). The Hessian is taken by
// second-order central differences with step 1e-2 sqrt(variance) (relative error ~1e-5: a preconditioner need
// not be exact). Diagonal: K_mm = I / ((20/3) pi a_m^3) (the isolated-sphere e = -S / ((20/3) pi a^3)) (envelope.hpp). eta = 1, lengths in a_1.
//
// Why it helps: in a random suspension nearby (even overlapping) envelopes make K nearly singular along the
// pair's relative stresslet; the isolated-sphere (Jacobi) preconditioner cannot see that, the pair blocks do.
// The periodic images and the grid error (~0.3% at h = a/2) are left to the outer CG, so the rigid solution is
// unchanged: only the iteration count depends on P.
// P = L L^T is symmetric positive definite by construction, as the CG needs. An incomplete factorisation can
// meet a non-positive pivot; the diagonal is then raised by 5%, 10%, 20%, ... until it succeeds (shifts()).
#pragma once
#include <array>
#include <cstddef>
#include <memory>
#include <span>

#include "core/vec.hpp"
#include "fcm/sheared_grid.hpp"

namespace suspend::fcm {

// Coordinates of a traceless symmetric matrix in an orthonormal (Frobenius) basis, and back.
std::array<double, 5> stresslet_coordinates(const Mat3& s);
Mat3 stresslet_from_coordinates(const std::array<double, 5>& c);

// The 5 x 5 block K_mq (row: coordinates of -e_m, column: coordinates of S_q) for r = Y_m - Y_q, free space.
std::array<std::array<double, 5>, 5> stresslet_pair_block(const Vec3& r, double radius_m, double radius_q);

class NearFieldPreconditioner {
 public:
  NearFieldPreconditioner();
  ~NearFieldPreconditioner();
  NearFieldPreconditioner(NearFieldPreconditioner&&) noexcept;
  NearFieldPreconditioner& operator=(NearFieldPreconditioner&&) noexcept;

  // Pairs are found on the grid's Lees-Edwards lattice (length, shear_fraction), minimum image. OpenMP-parallel
  // pair blocks; the factorisation and the triangular solves are serial.
  void build(const ShearedGrid& grid, std::span<const Vec3> positions, std::span<const double> radii,
             double cutoff);
  // z = P^-1 r (both traceless symmetric, indexed by particle).
  void apply(std::span<const Mat3> r, std::span<Mat3> z) const;

  std::size_t pairs() const { return pairs_; }
  int shifts() const { return shifts_; }

 private:
  struct Factor;
  std::unique_ptr<Factor> factor_;
  std::size_t pairs_ = 0;
  int shifts_ = 0;
};

}  // namespace suspend::fcm
