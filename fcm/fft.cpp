#include "fcm/fft.hpp"

#include <fftw3.h>
#include <omp.h>

#include <algorithm>
#include <cstring>
#include <mutex>

#include "core/error.hpp"

namespace suspend::fcm {
namespace {
// FFTW's planner is not thread-safe and fftw_init_threads must run once per process.
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}
void init_threads_once() {
  static const bool ok = fftw_init_threads() != 0;
  if (!ok) throw NumericalError("fcm: fftw_init_threads failed");
}
}  // namespace

VectorFft::VectorFft(std::array<int, 3> n, int threads, FftPlanning planning) : n_(n) {
  for (int d = 0; d < 3; ++d)
    if (n[d] < 2) throw InputError("fcm: grid size must be at least 2 in every direction");
  real_size_ = static_cast<std::size_t>(n[0]) * n[1] * n[2];
  complex_size_ = static_cast<std::size_t>(n[0] / 2 + 1) * n[1] * n[2];
  std::lock_guard<std::mutex> lock(planner_mutex());
  init_threads_once();
  real_ = fftw_alloc_real(3 * real_size_);
  spectrum_ = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(3 * complex_size_));
  if (real_ == nullptr || spectrum_ == nullptr) throw NumericalError("fcm: cannot allocate the FFT grid");
  const int nthreads = threads > 0 ? threads : omp_get_max_threads();
  fftw_plan_with_nthreads(nthreads);
  const int dims[3] = {n[2], n[1], n[0]};  // row-major, x fastest
  const unsigned flags = planning == FftPlanning::measure ? FFTW_MEASURE : FFTW_ESTIMATE;
  auto* c = reinterpret_cast<fftw_complex*>(spectrum_);
  const int rdist = static_cast<int>(real_size_), cdist = static_cast<int>(complex_size_);
  const int batch = nthreads > 1 ? 1 : 3;
  for (int k = 0; k < 3 / batch; ++k) {
    double* r = real_ + k * real_size_;
    fftw_complex* s = c + k * complex_size_;
    forward_plans_[k] = fftw_plan_many_dft_r2c(3, dims, batch, r, nullptr, 1, rdist, s, nullptr, 1, cdist, flags);
    inverse_plans_[k] = fftw_plan_many_dft_c2r(3, dims, batch, s, nullptr, 1, cdist, r, nullptr, 1, rdist, flags);
    if (forward_plans_[k] == nullptr || inverse_plans_[k] == nullptr)
      throw NumericalError("fcm: FFTW planning failed");
  }
  // Planning with FFTW_MEASURE overwrites the arrays.
  std::fill(real_, real_ + 3 * real_size_, 0.0);
}

VectorFft::~VectorFft() {
  std::lock_guard<std::mutex> lock(planner_mutex());
  for (void* p : forward_plans_)
    if (p != nullptr) fftw_destroy_plan(static_cast<fftw_plan>(p));
  for (void* p : inverse_plans_)
    if (p != nullptr) fftw_destroy_plan(static_cast<fftw_plan>(p));
  fftw_free(real_);
  fftw_free(spectrum_);
}

// Plain 32-byte stores rather than memset (which GCC makes of a zeroing loop): the same speed, and callgrind counts
// them as what they are (a `rep stosb` it counts once per byte, 6.3 M "instructions" per 64^3 field, docs/fcm.md).
#if defined(__GNUC__) && !defined(__clang__)
__attribute__((optimize("no-tree-loop-distribute-patterns")))
#endif
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__) && \
    !defined(__SANITIZE_THREAD__) && !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("arch=x86-64-v3", "default")))
#endif
void VectorFft::zero_real() {
  typedef double Lanes __attribute__((vector_size(32)));
  const std::ptrdiff_t size = static_cast<std::ptrdiff_t>(3 * real_size_);
  const std::ptrdiff_t vectors = size / 4;
  double* r = real_;
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < vectors; ++i) {
    const Lanes z{};
    std::memcpy(r + 4 * i, &z, sizeof z);
  }
  for (std::ptrdiff_t i = 4 * vectors; i < size; ++i) r[i] = 0.0;
}

void VectorFft::forward(FftScaling scaling) {
  for (void* p : forward_plans_)
    if (p != nullptr) fftw_execute(static_cast<fftw_plan>(p));
  if (scaling == FftScaling::inverse_size) {
    const double s = 1.0 / static_cast<double>(real_size_);
    const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(3 * complex_size_);
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t i = 0; i < m; ++i) spectrum_[i] *= s;
  }
}

void VectorFft::inverse(FftScaling scaling) {
  for (void* p : inverse_plans_)
    if (p != nullptr) fftw_execute(static_cast<fftw_plan>(p));
  if (scaling == FftScaling::inverse_size) {
    const double s = 1.0 / static_cast<double>(real_size_);
    const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(3 * real_size_);
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t i = 0; i < m; ++i) real_[i] *= s;
  }
}

}  // namespace suspend::fcm
