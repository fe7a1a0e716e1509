// Threaded real-to-complex 3-D FFT of a three-component field (FFTW3), plans made once and reused.
// Layout: component c, real index (iz * ny + iy) * nx + ix (x fastest); complex index
// (iz * ny + iy) * (nx/2 + 1) + kx, so the halved dimension is x. FFTW transforms are unnormalised; every call
// names its scaling so the normalisation is visible at the call site.
#pragma once
#include <array>
#include <complex>
#include <cstddef>
#include <span>

namespace suspend::fcm {

enum class FftScaling { none, inverse_size };  // none: raw FFTW sums; inverse_size: multiply the output by 1/N
enum class FftPlanning { estimate, measure };

class VectorFft {
 public:
  // n = {nx, ny, nz}; threads <= 0 means omp_get_max_threads().
  VectorFft(std::array<int, 3> n, int threads, FftPlanning planning);
  ~VectorFft();
  VectorFft(const VectorFft&) = delete;
  VectorFft& operator=(const VectorFft&) = delete;

  std::size_t real_size() const { return real_size_; }        // per component
  std::size_t complex_size() const { return complex_size_; }  // per component
  const std::array<int, 3>& n() const { return n_; }

  std::span<double> real(int component) { return {real_ + component * real_size_, real_size_}; }
  std::span<std::complex<double>> spectrum(int component) {
    return {spectrum_ + component * complex_size_, complex_size_};
  }
  double* real_data() { return real_; }
  // Sets the three real components to zero (OpenMP-parallel, plain vector stores).
  void zero_real();

  // real -> spectrum, all three components. spectrum = scaling * sum_x f(x) exp(-i k x).
  void forward(FftScaling scaling);
  // spectrum -> real, all three components (destroys the spectrum). real = scaling * sum_k f(k) exp(+i k x).
  void inverse(FftScaling scaling);

 private:
  std::array<int, 3> n_;
  std::size_t real_size_;
  std::size_t complex_size_;
  double* real_ = nullptr;
  std::complex<double>* spectrum_ = nullptr;
  // One batched plan for all three components with one thread; with more, one plan per component run in turn:
  // FFTW splits a batch of three between two threads 2 : 1 (measured with callgrind, docs/fcm.md), while a single
  // transform is split evenly over its planes.
  std::array<void*, 3> forward_plans_{};
  std::array<void*, 3> inverse_plans_{};
};

}  // namespace suspend::fcm
