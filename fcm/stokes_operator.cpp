#include "fcm/stokes_operator.hpp"

#include <cmath>
#include <complex>
#include <cstring>
#include <numbers>

namespace suspend::fcm {
namespace {

// Signed mode number of index i of an n-point transform.
int mode(int i, int n) { return i <= n / 2 ? i : i - n; }

// As in spreading.cpp: on x86-64 with GCC also compiled for AVX2 + FMA, chosen at load time.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__) && \
    !defined(__SANITIZE_THREAD__) && !defined(__SANITIZE_ADDRESS__)
#define SUSPEND_SIMD_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define SUSPEND_SIMD_CLONES
#endif

// Two complex modes (re, im, re, im) per vector: every factor of the Green's function is real, so a mode's real
// and imaginary parts are scaled alike and the loop needs no complex products.
typedef double Lanes __attribute__((vector_size(32)));

[[gnu::always_inline]] inline void load(const std::complex<double>* p, Lanes& v) { std::memcpy(&v, p, sizeof v); }
[[gnu::always_inline]] inline void store(std::complex<double>* p, const Lanes& v) {
  std::memcpy(static_cast<void*>(p), &v, sizeof v);
}

// One z plane of the spectrum.
template <bool Windowed>
SUSPEND_SIMD_CLONES void green_plane(const ShearedGrid& grid, std::complex<double>* f1, std::complex<double>* f2,
                                     std::complex<double>* f3, int iz, double scale, const double* wxy,
                                     const double* wz, const double* k1_pairs) {
  const int nx = grid.n[0], ny = grid.n[1], nz = grid.n[2];
  const int hx = nx / 2 + 1;
  const double twopi = 2.0 * std::numbers::pi;
  const double c1 = twopi / grid.length.x(), c2 = twopi / grid.length.y(), c3 = twopi / grid.length.z();
  const double gt = grid.shear_fraction;
  const int m3 = mode(iz, nz);
  const bool nyq3 = nz % 2 == 0 && iz == nz / 2;
  const double k3 = c3 * m3;
  const double sz = Windowed ? scale * wz[iz] : scale;
  for (int iy = 0; iy < ny; ++iy) {
    const int m2 = mode(iy, ny);
    const bool nyq2 = ny % 2 == 0 && iy == ny / 2;
    const std::size_t row = (static_cast<std::size_t>(iz) * ny + iy) * hx;
    const double* w = Windowed ? wxy + static_cast<std::size_t>(iy) * hx : nullptr;
    // Zeroed: Nyquist planes, the Nyquist x mode and k = 0; the loops below see only k^2 > 0.
    const int m_end = nx % 2 == 0 ? nx / 2 : hx;
    const int m_begin = nyq2 || nyq3 ? m_end : (m2 == 0 && m3 == 0 ? 1 : 0);
    for (int m1 = 0; m1 < m_begin; ++m1) f1[row + m1] = f2[row + m1] = f3[row + m1] = 0.0;
    for (int m1 = m_end; m1 < hx; ++m1) f1[row + m1] = f2[row + m1] = f3[row + m1] = 0.0;
    const double k2 = c2 * m2;
    int m1 = m_begin;
    const Lanes k3v{k3, k3, k3, k3}, k2v{k2, k2, k2, k2}, gtv{gt, gt, gt, gt}, szv{sz, sz, sz, sz};
    for (; m1 + 2 <= m_end; m1 += 2) {
      const std::size_t i = row + m1;
      Lanes k1;  // (c1 m1, c1 m1, c1 (m1 + 1), c1 (m1 + 1))
      std::memcpy(&k1, k1_pairs + 2 * m1, sizeof k1);
      const Lanes k2s = k2v - gtv * k1;
      const Lanes inv = 1.0 / (k1 * k1 + k2s * k2s + k3v * k3v);
      Lanes a, b, c;
      load(f1 + i, a);
      load(f2 + i, b);
      load(f3 + i, c);
      const Lanes kf = (k1 * a + k2s * b + k3v * c) * inv;
      Lanes g = szv * inv;
      if constexpr (Windowed) g *= Lanes{w[m1], w[m1], w[m1 + 1], w[m1 + 1]};
      store(f1 + i, g * (a - k1 * kf));
      store(f2 + i, g * (b - k2s * kf));
      store(f3 + i, g * (c - k3v * kf));
    }
    for (; m1 < m_end; ++m1) {
      const std::size_t i = row + m1;
      const double k1 = c1 * m1, k2s = k2 - gt * k1;
      const double inv = 1.0 / (k1 * k1 + k2s * k2s + k3 * k3);
      const std::complex<double> kf = (k1 * f1[i] + k2s * f2[i] + k3 * f3[i]) * inv;
      double g = sz * inv;
      if constexpr (Windowed) g *= w[m1];
      f1[i] = g * (f1[i] - k1 * kf);
      f2[i] = g * (f2[i] - k2s * kf);
      f3[i] = g * (f3[i] - k3 * kf);
    }
  }
}

template <bool Windowed>
void green(const ShearedGrid& grid, VectorFft& fft, double scale, const double* wxy, const double* wz) {
  std::complex<double>* f1 = fft.spectrum(0).data();
  std::complex<double>* f2 = fft.spectrum(1).data();
  std::complex<double>* f3 = fft.spectrum(2).data();
  const int nz = grid.n[2], hx = grid.n[0] / 2 + 1;
  // k1 of every x mode, each twice (the real and imaginary lane of a mode).
  std::vector<double> k1_pairs(2 * static_cast<std::size_t>(hx) + 2);
  const double c1 = 2.0 * std::numbers::pi / grid.length.x();
  for (int m1 = 0; m1 <= hx; ++m1) k1_pairs[2 * m1] = k1_pairs[2 * m1 + 1] = c1 * m1;
#pragma omp parallel for schedule(static)
  for (int iz = 0; iz < nz; ++iz) green_plane<Windowed>(grid, f1, f2, f3, iz, scale, wxy, wz, k1_pairs.data());
}

}  // namespace

void SplitWindow::update(const ShearedGrid& grid, double c) {
  if (c == split && grid.shear_fraction == shear_fraction_ && grid.n == n_ && grid.length == length_ &&
      (c == 0.0 || !xy.empty()))
    return;
  split = c;
  shear_fraction_ = grid.shear_fraction;
  n_ = grid.n;
  length_ = grid.length;
  if (c == 0.0) {
    xy.clear();
    z.clear();
    return;
  }
  const int nx = grid.n[0], ny = grid.n[1], nz = grid.n[2], hx = nx / 2 + 1;
  const double twopi = 2.0 * std::numbers::pi;
  const double c1 = twopi / grid.length.x(), c2 = twopi / grid.length.y(), c3 = twopi / grid.length.z();
  const double gt = grid.shear_fraction, c2s = c * c;
  xy.resize(static_cast<std::size_t>(ny) * hx);
  z.resize(static_cast<std::size_t>(nz));
  for (int iy = 0; iy < ny; ++iy)
    for (int m1 = 0; m1 < hx; ++m1) {
      const double k1 = c1 * m1, k2s = c2 * mode(iy, ny) - gt * k1;
      xy[static_cast<std::size_t>(iy) * hx + m1] = std::exp(-c2s * (k1 * k1 + k2s * k2s));
    }
  for (int iz = 0; iz < nz; ++iz) {
    const double k3 = c3 * mode(iz, nz);
    z[static_cast<std::size_t>(iz)] = std::exp(-c2s * k3 * k3);
  }
}

void apply_stokes_green(const ShearedGrid& grid, VectorFft& fft, double scale, const SplitWindow* window) {
  if (window != nullptr && window->split != 0.0)
    green<true>(grid, fft, scale, window->xy.data(), window->z.data());
  else
    green<false>(grid, fft, scale, nullptr, nullptr);
}

}  // namespace suspend::fcm
