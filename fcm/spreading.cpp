#include "fcm/spreading.hpp"

#include <omp.h>

#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "fcm/envelope.hpp"

namespace suspend::fcm {

Envelope make_envelope(const Vec3& centre, double radius, double truncation_widths, double split) {
  const double sm = monopole_width(radius), sd = dipole_width(radius);
  const double tm = std::sqrt(sm * sm - split * split), td = std::sqrt(sd * sd - split * split);
  return {centre, tm, td, truncation_widths * tm};
}

Mat3 dipole_tensor(const Vec3& torque, const Mat3& stresslet) {
  Mat3 rot;
  rot << 0.0, torque.z(), -torque.y(),  //
      -torque.z(), 0.0, torque.x(),     //
      torque.y(), -torque.x(), 0.0;
  return stresslet + 0.5 * rot;
}

Vec3 angular_velocity_of(const Mat3& a) {
  return 0.5 * Vec3(a(1, 2) - a(2, 1), a(2, 0) - a(0, 2), a(0, 1) - a(1, 0));
}

Mat3 strain_rate_of(const Mat3& a) { return -0.5 * (a + a.transpose()); }

namespace {

// Thread t of `threads` owns the z planes [begin, end) holding the t-th share of the support nodes.
std::pair<int, int> balanced_slab(const std::vector<std::size_t>& plane_nodes, int t, int threads) {
  std::size_t total = 0;
  for (std::size_t c : plane_nodes) total += c;
  const int nz = static_cast<int>(plane_nodes.size());
  auto boundary = [&](int s) {  // first plane after the first s/threads of the work
    if (s <= 0) return 0;
    if (s >= threads) return nz;
    const double target = static_cast<double>(total) * s / threads;
    std::size_t sum = 0;
    int z = 0;
    while (z < nz && static_cast<double>(sum + plane_nodes[z]) <= target) sum += plane_nodes[z++];
    return z;
  };
  return {boundary(t), boundary(t + 1)};
}

// Row kernels. A row's node weights are w_M = yz_m m[i] and w_D = yz_d d[i] (support_plan.hpp); with the
// row's constants folded into coefficients, a node update is three multiply-adds per component:
//   f_c[i] += a_c m[i] + b_c d[i] + c_c dd[i],
// a = yz_m F, b = gs_c1 ydy + gs_c2 ydz, c = yz_d gs_c0, gs = -G / sD^2 (d_j Delta_D = -d_j/sD^2 Delta_D).
// Rows are short (~7 nodes at h = a/2), so the row loop is instantiated for every length up to kMaxFixed: the
// compiler unrolls and vectorises each one without loop prologue or remainder.
constexpr int kMaxFixed = 16;

// On x86-64 with GCC the per-particle loops are also compiled for AVX2 + FMA and chosen at load time (ifunc), so
// the portable baseline binary still uses the 4-wide units where the CPU has them. Not under the thread or address
// sanitizer: their instrumentation of the ifunc resolver runs before the sanitizer runtime is up.
// Where the CPU also has AVX-512, 8-lane kernels with masked loads and stores (below) replace them: a row of up to
// 8 nodes is one masked vector, with no per-length instances and no tail handling.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__) && \
    !defined(__SANITIZE_THREAD__) && !defined(__SANITIZE_ADDRESS__)
#define SUSPEND_SIMD_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#define SUSPEND_WIDE_KERNELS 1
#define SUSPEND_AVX512 __attribute__((target("avx512f,avx512vl,avx512dq,avx2,fma")))
#else
#define SUSPEND_SIMD_CLONES
#define SUSPEND_WIDE_KERNELS 0
#endif

std::atomic<bool> wide_kernels_on{true};

typedef double Lanes __attribute__((vector_size(32)));

// (Lanes are passed by reference: by value GCC warns that the AVX calling convention differs, -Wpsabi.)
[[gnu::always_inline]] inline void load_lanes(const double* p, Lanes& v) { std::memcpy(&v, p, sizeof v); }
template <int N>
[[gnu::always_inline]] inline void load_short(const double* p, Lanes& v) {  // N < 4 values, zero-filled
  v = Lanes{p[0], N > 1 ? p[1] : 0.0, N > 2 ? p[2] : 0.0, 0.0};
}

[[gnu::always_inline]] inline void broadcast(double x, Lanes& v) { v = Lanes{x, x, x, x}; }

struct RowCoefficients {
  double a[3], b[3], c[3];
};

template <bool Monopole, int N>
[[gnu::always_inline]] inline void spread_run(const double* __restrict m, const double* __restrict d,
                                              const double* __restrict dd, const RowCoefficients& k,
                                              double* __restrict px, double* __restrict py, double* __restrict pz,
                                              int count) {
  const int n = N > 0 ? N : count;
  const double a0 = k.a[0], a1 = k.a[1], a2 = k.a[2], b0 = k.b[0], b1 = k.b[1], b2 = k.b[2];
  const double c0 = k.c[0], c1 = k.c[1], c2 = k.c[2];
#pragma omp simd
  for (int i = 0; i < n; ++i) {
    if constexpr (Monopole) {
      px[i] += a0 * m[i] + b0 * d[i] + c0 * dd[i];
      py[i] += a1 * m[i] + b1 * d[i] + c1 * dd[i];
      pz[i] += a2 * m[i] + b2 * d[i] + c2 * dd[i];
    } else {
      px[i] += b0 * d[i] + c0 * dd[i];
      py[i] += b1 * d[i] + c1 * dd[i];
      pz[i] += b2 * d[i] + c2 * dd[i];
    }
  }
}

// Rows of N >= 4 nodes (N = 0: any such length) in 4-lane vectors: whole vectors from the row start, then one
// vector ending at the last node whose already-updated lanes get zero-weighted tables (so they are stored back
// unchanged). Every load and store stays inside the row, which lies in one z plane: a thread's slab.
template <bool Monopole, bool Masked>
[[gnu::always_inline]] inline void spread_chunk(const double* tm, const double* td, const double* tdd,
                                                const Lanes& keep, const Lanes (&k)[9], double* px, double* py,
                                                double* pz) {
  Lanes m, d, dd;
  load_lanes(td, d);
  load_lanes(tdd, dd);
  if constexpr (Monopole) load_lanes(tm, m);
  if constexpr (Masked) {
    d *= keep;
    dd *= keep;
    if constexpr (Monopole) m *= keep;
  }
  double* p[3] = {px, py, pz};
  for (int c = 0; c < 3; ++c) {
    Lanes f;
    load_lanes(p[c], f);
    f += k[3 + c] * d + k[6 + c] * dd;
    if constexpr (Monopole) f += k[c] * m;
    std::memcpy(p[c], &f, sizeof f);
  }
}

template <bool Monopole, int N>
[[gnu::always_inline]] inline void spread_lanes(const double* m, const double* d, const double* dd,
                                                const Lanes (&k)[9], double* px, double* py, double* pz,
                                                int count) {
  const int n = N > 0 ? N : count;
  int i = 0;
  for (; i + 4 <= n; i += 4) spread_chunk<Monopole, false>(m + i, d + i, dd + i, k[0], k, px + i, py + i, pz + i);
  if (i < n) {
    const int o = n - 4, old = 4 - (n - i);
    const Lanes keep{old <= 0 ? 1.0 : 0.0, old <= 1 ? 1.0 : 0.0, old <= 2 ? 1.0 : 0.0, 1.0};
    spread_chunk<Monopole, true>(m + o, d + o, dd + o, keep, k, px + o, py + o, pz + o);
  }
}

// Calls f(std::integral_constant<int, N>) with N = count for count <= kMaxFixed, else N = 0 (any length).
template <class F, int... I>
[[gnu::always_inline]] inline void with_fixed_length(int count, F&& f, std::integer_sequence<int, I...>) {
  const bool fixed = ((count == I + 1 ? (f(std::integral_constant<int, I + 1>{}), true) : false) || ...);
  if (!fixed) f(std::integral_constant<int, 0>{});
}

// Spreads one particle's rows lying in planes [zb, ze).
template <bool Monopole>
SUSPEND_SIMD_CLONES void spread_particle(const SupportRow* rows, const SupportRow* rows_end, const double* tables,
                                         const Vec3& f, const Mat3& gs, std::uint32_t zb, std::uint32_t ze,
                                         double* fx, double* fy, double* fz) {
  // The particle's multipoles broadcast once; a row's coefficients (a, b, c of each component, RowCoefficients)
  // are then one vector product or multiply-add each.
  Lanes fm[3], g0[3], g1[3], g2[3];
  for (int i = 0; i < 3; ++i) {
    broadcast(f[i], fm[i]);
    broadcast(gs(i, 0), g0[i]);
    broadcast(gs(i, 1), g1[i]);
    broadcast(gs(i, 2), g2[i]);
  }
  for (const SupportRow* r = rows; r != rows_end; ++r) {
    if (r->iz < zb || r->iz >= ze) continue;
    Lanes ym, yd, wy, wz, k[9];
    broadcast(r->yz_m, ym);
    broadcast(r->yz_d, yd);
    broadcast(r->ydy, wy);
    broadcast(r->ydz, wz);
    for (int i = 0; i < 3; ++i) {
      k[i] = Monopole ? fm[i] * ym : Lanes{};
      k[3 + i] = g1[i] * wy + g2[i] * wz;
      k[6 + i] = g0[i] * yd;
    }
    const double* m = tables + r->table;
    const double* d = m + r->width;
    const double* dd = d + r->width;
    double* px = fx + r->first;
    double* py = fy + r->first;
    double* pz = fz + r->first;
    const int n = r->count;
    with_fixed_length(
        n,
        [&](auto len) {
          constexpr int N = decltype(len)::value;
          if constexpr (N > 0 && N < 4) {
            RowCoefficients c{};
            for (int i = 0; i < 3; ++i) {
              if constexpr (Monopole) c.a[i] = k[i][0];
              c.b[i] = k[3 + i][0];
              c.c[i] = k[6 + i][0];
            }
            spread_run<Monopole, N>(m, d, dd, c, px, py, pz, n);
          } else {
            spread_lanes<Monopole, N>(m, d, dd, k, px, py, pz, n);
          }
        },
        std::make_integer_sequence<int, kMaxFixed>{});
  }
}

// Interpolation in 4-lane vectors (GCC/Clang vector extension; two SSE halves in the baseline clone). Within a
// row, nine lane-wise sums (u_c m, u_c d, u_c dd); at the row end they are weighted by the row factors into twelve
// lane-wise particle sums, reduced across lanes once per particle. (Reducing nine sums across lanes in every row,
// as a scalar `omp simd` reduction does, cost more than the products: rows are ~7 nodes.)
// A row of N >= 4 nodes is covered by whole vectors from its start plus one vector ending at its last node, whose
// lanes already counted are multiplied by zero; every load stays inside the row. Rows of 1-3 nodes are loaded
// lane by lane.
struct LaneSums {
  Lanes m[3], d[3], t[3];
};
struct ParticleLanes {
  Lanes u[3], s0[3], s1[3], s2[3];
};

// Loads 4 lanes from each pointer (Short: the first N, zero-filled), scales the table lanes by `keep` (1 or 0) and
// adds the nine products.
template <bool Short, int N>
[[gnu::always_inline]] inline void add_chunk(const double* tm, const double* td, const double* tdd, const double* px,
                                             const double* py, const double* pz, const Lanes& keep, LaneSums& r) {
  Lanes m, d, dd, ux, uy, uz;
  if constexpr (Short) {
    load_short<N>(tm, m);
    load_short<N>(td, d);
    load_short<N>(tdd, dd);
    load_short<N>(px, ux);
    load_short<N>(py, uy);
    load_short<N>(pz, uz);
  } else {
    load_lanes(tm, m);
    load_lanes(td, d);
    load_lanes(tdd, dd);
    load_lanes(px, ux);
    load_lanes(py, uy);
    load_lanes(pz, uz);
    m *= keep;
    d *= keep;
    dd *= keep;
  }
  r.m[0] += ux * m;
  r.m[1] += uy * m;
  r.m[2] += uz * m;
  r.d[0] += ux * d;
  r.d[1] += uy * d;
  r.d[2] += uz * d;
  r.t[0] += ux * dd;
  r.t[1] += uy * dd;
  r.t[2] += uz * dd;
}

// Row sums for a row of N nodes (N = 0: any length >= 4, given by count).
template <int N>
[[gnu::always_inline]] inline void interpolate_row(const double* m, const double* d, const double* dd,
                                                   const double* ux, const double* uy, const double* uz, int count,
                                                   LaneSums& r) {
  const Lanes all{1.0, 1.0, 1.0, 1.0};
  if constexpr (N > 0 && N < 4) {
    add_chunk<true, N>(m, d, dd, ux, uy, uz, all, r);
  } else {
    const int n = N > 0 ? N : count;
    int i = 0;
    for (; i + 4 <= n; i += 4) add_chunk<false, 0>(m + i, d + i, dd + i, ux + i, uy + i, uz + i, all, r);
    if (i < n) {  // the last 4 nodes; lanes before node i were counted above
      const int o = n - 4, old = 4 - (n - i);
      const Lanes keep{old <= 0 ? 1.0 : 0.0, old <= 1 ? 1.0 : 0.0, old <= 2 ? 1.0 : 0.0, 1.0};
      add_chunk<false, 0>(m + o, d + o, dd + o, ux + o, uy + o, uz + o, keep, r);
    }
  }
}

[[gnu::always_inline]] inline double lane_sum(const Lanes& v) { return (v[0] + v[1]) + (v[2] + v[3]); }

// Interpolates one particle: returns U / dV and the columns of A / (dV (-1/sD^2)).
SUSPEND_SIMD_CLONES void interpolate_particle(const SupportRow* rows, const SupportRow* rows_end,
                                              const double* tables, const double* ux, const double* uy,
                                              const double* uz, Vec3& u, Mat3& a) {
  ParticleLanes p{};
  for (const SupportRow* r = rows; r != rows_end; ++r) {
    const double* m = tables + r->table;
    const double* d = m + r->width;
    const double* dd = d + r->width;
    const std::size_t o = r->first;
    const int n = r->count;
    LaneSums t{};
    with_fixed_length(
        n, [&](auto len) { interpolate_row<decltype(len)::value>(m, d, dd, ux + o, uy + o, uz + o, n, t); },
        std::make_integer_sequence<int, kMaxFixed>{});
    // dy and dz are constant along the row: sum u d_y w_D = ydy sum u d (support_plan.hpp).
    Lanes wm, wd, wy, wz;
    broadcast(r->yz_m, wm);
    broadcast(r->yz_d, wd);
    broadcast(r->ydy, wy);
    broadcast(r->ydz, wz);
    for (int c = 0; c < 3; ++c) {
      p.u[c] += wm * t.m[c];
      p.s0[c] += wd * t.t[c];
      p.s1[c] += wy * t.d[c];
      p.s2[c] += wz * t.d[c];
    }
  }
  for (int c = 0; c < 3; ++c) {
    u[c] = lane_sum(p.u[c]);
    a(c, 0) = lane_sum(p.s0[c]);
    a(c, 1) = lane_sum(p.s1[c]);
    a(c, 2) = lane_sum(p.s2[c]);
  }
}

#if SUSPEND_WIDE_KERNELS
// 8-lane (AVX-512) kernels: the same arithmetic as spread_particle / interpolate_particle, a row in masked vectors of
// 8 nodes (masked-off lanes are neither read from memory nor written), so rows of 1-8 nodes take one pass.
[[gnu::always_inline]] SUSPEND_AVX512 inline __mmask8 row_mask(int left) {
  return left >= 8 ? static_cast<__mmask8>(0xFF) : static_cast<__mmask8>((1u << left) - 1u);
}

template <bool Monopole>
SUSPEND_AVX512 void spread_particle_wide(const SupportRow* rows, const SupportRow* rows_end, const double* tables,
                                         const Vec3& f, const Mat3& gs, std::uint32_t zb, std::uint32_t ze,
                                         double* fx, double* fy, double* fz) {
  __m512d fm[3], g0[3], g1[3], g2[3];
  for (int i = 0; i < 3; ++i) {
    fm[i] = _mm512_set1_pd(f[i]);
    g0[i] = _mm512_set1_pd(gs(i, 0));
    g1[i] = _mm512_set1_pd(gs(i, 1));
    g2[i] = _mm512_set1_pd(gs(i, 2));
  }
  double* const field[3] = {fx, fy, fz};
  for (const SupportRow* r = rows; r != rows_end; ++r) {
    if (r->iz < zb || r->iz >= ze) continue;
    // f_c += F_c (yz_m m) + (gs_c1 ydy + gs_c2 ydz) d + gs_c0 (yz_d dd)   (RowCoefficients, as vectors)
    const __m512d ym = _mm512_set1_pd(r->yz_m), yd = _mm512_set1_pd(r->yz_d);
    const __m512d wy = _mm512_set1_pd(r->ydy), wz = _mm512_set1_pd(r->ydz);
    __m512d b[3];
    for (int c = 0; c < 3; ++c) b[c] = _mm512_fmadd_pd(g1[c], wy, _mm512_mul_pd(g2[c], wz));
    const double* m = tables + r->table;
    const double* d = m + r->width;
    const double* dd = d + r->width;
    const int n = r->count;
    for (int i = 0; i < n; i += 8) {
      const __mmask8 k = row_mask(n - i);
      const __m512d vd = _mm512_maskz_loadu_pd(k, d + i);
      const __m512d vdd = _mm512_mul_pd(yd, _mm512_maskz_loadu_pd(k, dd + i));
      __m512d vm = _mm512_setzero_pd();
      if constexpr (Monopole) vm = _mm512_mul_pd(ym, _mm512_maskz_loadu_pd(k, m + i));
      for (int c = 0; c < 3; ++c) {
        double* q = field[c] + r->first + i;
        __m512d v = _mm512_maskz_loadu_pd(k, q);
        v = _mm512_fmadd_pd(b[c], vd, v);
        v = _mm512_fmadd_pd(g0[c], vdd, v);
        if constexpr (Monopole) v = _mm512_fmadd_pd(fm[c], vm, v);
        _mm512_mask_storeu_pd(q, k, v);
      }
    }
  }
}

// (Not _mm512_reduce_add_pd: with GCC 12 its _mm256_undefined_pd trips -Wuninitialized.)
[[gnu::always_inline]] SUSPEND_AVX512 inline double lane_sum_wide(__m512d v) {
  alignas(64) double x[8];
  _mm512_store_pd(x, v);
  return ((x[0] + x[4]) + (x[1] + x[5])) + ((x[2] + x[6]) + (x[3] + x[7]));
}

SUSPEND_AVX512 void interpolate_particle_wide(const SupportRow* rows, const SupportRow* rows_end,
                                              const double* tables, const double* ux, const double* uy,
                                              const double* uz, Vec3& u, Mat3& a) {
  __m512d su[3], s0[3], s1[3], s2[3];
  for (int c = 0; c < 3; ++c) su[c] = s0[c] = s1[c] = s2[c] = _mm512_setzero_pd();
  const double* const field[3] = {ux, uy, uz};
  for (const SupportRow* r = rows; r != rows_end; ++r) {
    const __m512d wm = _mm512_set1_pd(r->yz_m), wd = _mm512_set1_pd(r->yz_d);
    const __m512d wy = _mm512_set1_pd(r->ydy), wz = _mm512_set1_pd(r->ydz);
    const double* m = tables + r->table;
    const double* d = m + r->width;
    const double* dd = d + r->width;
    const int n = r->count;
    for (int i = 0; i < n; i += 8) {
      const __mmask8 k = row_mask(n - i);
      // Node weights of the four moments: w_M m, w_D dd (x), w_D dy d, w_D dz d (support_plan.hpp).
      const __m512d vd = _mm512_maskz_loadu_pd(k, d + i);
      const __m512d wmm = _mm512_mul_pd(wm, _mm512_maskz_loadu_pd(k, m + i));
      const __m512d wdd = _mm512_mul_pd(wd, _mm512_maskz_loadu_pd(k, dd + i));
      const __m512d wyd = _mm512_mul_pd(wy, vd), wzd = _mm512_mul_pd(wz, vd);
      for (int c = 0; c < 3; ++c) {
        const __m512d v = _mm512_maskz_loadu_pd(k, field[c] + r->first + i);
        su[c] = _mm512_fmadd_pd(v, wmm, su[c]);
        s0[c] = _mm512_fmadd_pd(v, wdd, s0[c]);
        s1[c] = _mm512_fmadd_pd(v, wyd, s1[c]);
        s2[c] = _mm512_fmadd_pd(v, wzd, s2[c]);
      }
    }
  }
  for (int c = 0; c < 3; ++c) {
    u[c] = lane_sum_wide(su[c]);
    a(c, 0) = lane_sum_wide(s0[c]);
    a(c, 1) = lane_sum_wide(s1[c]);
    a(c, 2) = lane_sum_wide(s2[c]);
  }
}

bool cpu_has_avx512() {
  static const bool ok = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                         __builtin_cpu_supports("avx512dq");
  return ok;
}
#endif

bool wide() { return wide_kernels_on.load(std::memory_order_relaxed) && wide_kernels_available(); }

}  // namespace

void spread(const SupportPlan& plan, std::span<const Vec3> forces, std::span<const Mat3> dipoles, double* field,
            std::size_t stride) {
  const bool has_f = !forces.empty(), has_g = !dipoles.empty();
  if (!has_f && !has_g) return;
  const std::size_t count = plan.visits();
  double* fx = field;
  double* fy = field + stride;
  double* fz = field + 2 * stride;
  const double* tables = plan.tables.data();
  const SupportRow* rows = plan.rows.data();
  [[maybe_unused]] const bool use_wide = wide();
#pragma omp parallel
  {
    // Thread t owns z planes [z_begin, z_end): writes never collide.
    const auto [z_begin, z_end] = balanced_slab(plan.plane_nodes, omp_get_thread_num(), omp_get_num_threads());
    const auto zb = static_cast<std::uint32_t>(z_begin), ze = static_cast<std::uint32_t>(z_end);
    const auto nz = static_cast<std::uint32_t>(plan.plane_nodes.size());
    for (std::size_t k = 0; k < count; ++k) {
      if (!plan.touches_planes(k, zb, ze, nz)) continue;
      const std::size_t p = plan.particle[k];
      const Vec3 f = has_f ? forces[p] : Vec3::Zero();
      // d/dx_j Delta_D = -d_j / sigma_D^2 Delta_D, so G_ij d_j Delta_D = (G d)_i w_D (-1 / sigma_D^2).
      const Mat3 gs = has_g ? Mat3(dipoles[p] * plan.dipole_scale[k]) : Mat3::Zero();
      const SupportRow* begin = rows + plan.row_begin[k];
      const SupportRow* end = rows + plan.row_end[k];
#if SUSPEND_WIDE_KERNELS
      if (use_wide) {
        if (has_f)
          spread_particle_wide<true>(begin, end, tables, f, gs, zb, ze, fx, fy, fz);
        else
          spread_particle_wide<false>(begin, end, tables, f, gs, zb, ze, fx, fy, fz);
        continue;
      }
#endif
      if (has_f)
        spread_particle<true>(begin, end, tables, f, gs, zb, ze, fx, fy, fz);
      else
        spread_particle<false>(begin, end, tables, f, gs, zb, ze, fx, fy, fz);
    }
  }
}

void interpolate(const SupportPlan& plan, const double* field, std::size_t stride, std::span<Vec3> velocities,
                 std::span<Mat3> gradient_moments) {
  const bool want_u = !velocities.empty(), want_a = !gradient_moments.empty();
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t>(plan.visits());
  const double dv = plan.cell_volume;
  const double* tables = plan.tables.data();
  const SupportRow* rows = plan.rows.data();
  [[maybe_unused]] const bool use_wide = wide();
#pragma omp parallel for schedule(dynamic, 16)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const std::size_t ku = static_cast<std::size_t>(k);
    Vec3 u;
    Mat3 a;
#if SUSPEND_WIDE_KERNELS
    if (use_wide)
      interpolate_particle_wide(rows + plan.row_begin[ku], rows + plan.row_end[ku], tables, field, field + stride,
                                field + 2 * stride, u, a);
    else
#endif
      interpolate_particle(rows + plan.row_begin[ku], rows + plan.row_end[ku], tables, field, field + stride,
                           field + 2 * stride, u, a);
    // A_ij = sum u_i d_j Delta_D dV with d_j Delta_D = -d_j / sigma_D^2 Delta_D.
    const std::size_t p = plan.particle[ku];
    if (want_u) velocities[p] = u * dv;
    if (want_a) gradient_moments[p] = a * (dv * plan.dipole_scale[ku]);
  }
}

bool wide_kernels_available() {
#if SUSPEND_WIDE_KERNELS
  return cpu_has_avx512();
#else
  return false;
#endif
}

void use_wide_kernels(bool on) { wide_kernels_on.store(on, std::memory_order_relaxed); }

void spread(const ShearedGrid& grid, std::span<const Envelope> envelopes, std::span<const Vec3> forces,
            std::span<const Mat3> dipoles, double* field, std::size_t stride) {
  spread(plan_support(grid, envelopes, grid_order(grid, envelopes)), forces, dipoles, field, stride);
}

void interpolate(const ShearedGrid& grid, std::span<const Envelope> envelopes, const double* field,
                 std::size_t stride, std::span<Vec3> velocities, std::span<Mat3> gradient_moments) {
  interpolate(plan_support(grid, envelopes, grid_order(grid, envelopes)), field, stride, velocities,
              gradient_moments);
}

}  // namespace suspend::fcm
