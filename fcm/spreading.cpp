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

// Row kernels. A row's node weights are w_M = zm m[i] and w_D = zd d[i] (support_plan.hpp: the tables carry the
// y factor, the plane the z factor); with the plane's and row's constants folded into coefficients, a node update
// is three multiply-adds per component:
//   f_c[i] += a_c m[i] + b_c d[i] + c_c dd[i],   dd[i] = dx_i d[i],  dx_i = dx0_j + t_i h_x
// a = zm F, b = gs_c1 zd dy + gs_c2 zd dz, c = zd gs_c0, gs = -G / sD^2 (d_j Delta_D = -d_j/sD^2 Delta_D): a and c
// are per plane, b per row; t_i is the node's index in its y row's tables (dd is formed here, not tabulated: one
// multiply-add per vector instead of a third table to stream). Rows are short (~7 nodes at h = a/2), so the row
// loop is instantiated for every length up to kMaxFixed: the compiler unrolls and vectorises each one without loop
// prologue or remainder.
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

// What a kernel needs of one visit of the plan.
struct Visit {
  const SupportPlane* planes;
  const SupportPlane* planes_end;
  const SupportRow* rows;
  const double* tables;
  int width;
  const double* dy;   // of y row j
  const double* dx0;  // of y row j
  std::size_t table_begin;
  double hx;
};

Visit visit_of(const SupportPlan& plan, std::size_t k) {
  return {plan.planes.data() + plan.plane_begin[k], plan.planes.data() + plan.plane_end[k], plan.rows.data(),
          plan.tables.data(), plan.width[k], plan.dy.data() + plan.dy_begin[k], plan.dx0.data() + plan.dy_begin[k],
          plan.table_begin[k], plan.spacing_x};
}

// Index of a row's first node in its y row's tables (support_plan.hpp), as a double.
// (An int: a 64-bit unsigned conversion to double is a long sequence without AVX-512; offsets fit 32 bits.)
[[gnu::always_inline]] inline double first_table_node(const Visit& v, const SupportRow& r) {
  return static_cast<double>(static_cast<int>(r.table - v.table_begin) - 2 * v.width * static_cast<int>(r.j));
}

// x offsets x + l h_x of the row's first four nodes, x = dx0_j + t h_x its first node's (once per row) ...
[[gnu::always_inline]] inline void x_offsets(const Visit& v, const SupportRow& r, Lanes& dx) {
  Lanes x;
  broadcast(v.dx0[r.j] + first_table_node(v, r) * v.hx, x);
  dx = x + Lanes{0.0, v.hx, 2.0 * v.hx, 3.0 * v.hx};
}
// ... and of the four nodes i .. i + 3 of the row from them.
[[gnu::always_inline]] inline void x_offsets_from(const Lanes& first, double hx, int i, Lanes& dx) {
  Lanes shift;
  broadcast(i * hx, shift);
  dx = first + shift;
}

// The next visit's tables are streamed from memory (~2 kB per visit at h = a/2, 6 MB per 64^3 pass at phi = 0.4);
// fetching them while the present visit is processed takes their latency off the critical path. (Inlined by force:
// GCC's interprocedural analysis finds a function that only prefetches free of side effects and drops its calls.)
[[gnu::always_inline]] inline void prefetch_tables(const SupportPlan& plan, std::size_t k) {
  if (k >= plan.visits()) return;
  const char* p = reinterpret_cast<const char*>(plan.tables.data() + plan.table_begin[k]);
  const char* end = reinterpret_cast<const char*>(plan.tables.data() + plan.table_begin[k + 1]);
  for (; p < end; p += 64) __builtin_prefetch(p);
}

struct RowCoefficients {
  double a[3], b[3], c[3];
};

template <bool Monopole, int N>
[[gnu::always_inline]] inline void spread_run(const double* __restrict m, const double* __restrict d, double x,
                                              double hx, const RowCoefficients& k,
                                              double* __restrict px, double* __restrict py, double* __restrict pz,
                                              int count) {
  const int n = N > 0 ? N : count;
  const double a0 = k.a[0], a1 = k.a[1], a2 = k.a[2], b0 = k.b[0], b1 = k.b[1], b2 = k.b[2];
  const double c0 = k.c[0], c1 = k.c[1], c2 = k.c[2];
#pragma omp simd
  for (int i = 0; i < n; ++i) {
    const double dd = (x + i * hx) * d[i];
    if constexpr (Monopole) {
      px[i] += a0 * m[i] + b0 * d[i] + c0 * dd;
      py[i] += a1 * m[i] + b1 * d[i] + c1 * dd;
      pz[i] += a2 * m[i] + b2 * d[i] + c2 * dd;
    } else {
      px[i] += b0 * d[i] + c0 * dd;
      py[i] += b1 * d[i] + c1 * dd;
      pz[i] += b2 * d[i] + c2 * dd;
    }
  }
}

// Rows of N >= 4 nodes (N = 0: any such length) in 4-lane vectors: whole vectors from the row start, then one
// vector ending at the last node whose already-updated lanes get zero-weighted tables (so they are stored back
// unchanged). Every load and store stays inside the row, which lies in one z plane: a thread's slab.
template <bool Monopole, bool Masked>
[[gnu::always_inline]] inline void spread_chunk(const double* tm, const double* td, const Lanes& dx,
                                                const Lanes& keep, const Lanes (&k)[9], double* px, double* py,
                                                double* pz) {
  Lanes m, d;
  load_lanes(td, d);
  if constexpr (Monopole) load_lanes(tm, m);
  if constexpr (Masked) {
    d *= keep;
    if constexpr (Monopole) m *= keep;
  }
  const Lanes dd = dx * d;
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
[[gnu::always_inline]] inline void spread_lanes(const double* m, const double* d, const Lanes& first, double hx,
                                                const Lanes (&k)[9], double* px, double* py, double* pz,
                                                int count) {
  const int n = N > 0 ? N : count;
  int i = 0;
  Lanes dx = first, step;
  broadcast(4.0 * hx, step);
  for (; i + 4 <= n; i += 4, dx += step) {
    spread_chunk<Monopole, false>(m + i, d + i, dx, k[0], k, px + i, py + i, pz + i);
  }
  if (i < n) {
    const int o = n - 4, old = 4 - (n - i);
    const Lanes keep{old <= 0 ? 1.0 : 0.0, old <= 1 ? 1.0 : 0.0, old <= 2 ? 1.0 : 0.0, 1.0};
    x_offsets_from(first, hx, o, dx);
    spread_chunk<Monopole, true>(m + o, d + o, dx, keep, k, px + o, py + o, pz + o);
  }
}

// Calls f(std::integral_constant<int, N>) with N = count for count <= kMaxFixed, else N = 0 (any length). A switch,
// so that the compiler makes it one jump table (a fold over || compiled to a chain of ~7 compares per row).
template <class F>
[[gnu::always_inline]] inline void with_fixed_length(int count, F&& f) {
  static_assert(kMaxFixed == 16);
  using std::integral_constant;
  switch (count) {
    case 1: return f(integral_constant<int, 1>{});
    case 2: return f(integral_constant<int, 2>{});
    case 3: return f(integral_constant<int, 3>{});
    case 4: return f(integral_constant<int, 4>{});
    case 5: return f(integral_constant<int, 5>{});
    case 6: return f(integral_constant<int, 6>{});
    case 7: return f(integral_constant<int, 7>{});
    case 8: return f(integral_constant<int, 8>{});
    case 9: return f(integral_constant<int, 9>{});
    case 10: return f(integral_constant<int, 10>{});
    case 11: return f(integral_constant<int, 11>{});
    case 12: return f(integral_constant<int, 12>{});
    case 13: return f(integral_constant<int, 13>{});
    case 14: return f(integral_constant<int, 14>{});
    case 15: return f(integral_constant<int, 15>{});
    case 16: return f(integral_constant<int, 16>{});
    default: return f(integral_constant<int, 0>{});
  }
}

// Spreads one particle's planes lying in [zb, ze) (Inside: all of them do).
template <bool Monopole, bool Inside>
SUSPEND_SIMD_CLONES void spread_particle(const Visit& v, const Vec3& f, const Mat3& gs, std::uint32_t zb,
                                         std::uint32_t ze, double* fx, double* fy, double* fz) {
  // The particle's multipoles broadcast once; a plane's coefficients a, c and a row's b (RowCoefficients) are then
  // one vector product or multiply-add each.
  Lanes fm[3], g0[3], g1[3], g2[3];
  for (int i = 0; i < 3; ++i) {
    broadcast(f[i], fm[i]);
    broadcast(gs(i, 0), g0[i]);
    broadcast(gs(i, 1), g1[i]);
    broadcast(gs(i, 2), g2[i]);
  }
  const std::ptrdiff_t w = v.width;
  for (const SupportPlane* q = v.planes; q != v.planes_end; ++q) {
    if constexpr (!Inside)
      if (q->iz < zb || q->iz >= ze) continue;
    Lanes zm, zd, zdz, k[9], e[3];
    broadcast(q->zm, zm);
    broadcast(q->zd, zd);
    broadcast(q->zd * q->dz, zdz);
    for (int i = 0; i < 3; ++i) {
      k[i] = Monopole ? fm[i] * zm : Lanes{};
      k[6 + i] = g0[i] * zd;
      e[i] = g2[i] * zdz;
    }
    const SupportRow* rows_end = v.rows + q->row_end;
    const double plane_zd = q->zd;  // (a local: the field stores below could alias q->zd)
    for (const SupportRow* r = v.rows + q->row_begin; r != rows_end; ++r) {
      Lanes wy;
      broadcast(plane_zd * v.dy[r->j], wy);
      for (int i = 0; i < 3; ++i) k[3 + i] = g1[i] * wy + e[i];
      const double* m = v.tables + r->table;
      const double* d = m + w;
      Lanes first;
      x_offsets(v, *r, first);
      double* px = fx + r->first;
      double* py = fy + r->first;
      double* pz = fz + r->first;
      const int n = r->count;
      with_fixed_length(
          n,
          [&](auto len) __attribute__((always_inline)) {
            constexpr int N = decltype(len)::value;
            if constexpr (N > 0 && N < 4) {
              RowCoefficients c{};
              for (int i = 0; i < 3; ++i) {
                if constexpr (Monopole) c.a[i] = k[i][0];
                c.b[i] = k[3 + i][0];
                c.c[i] = k[6 + i][0];
              }
              spread_run<Monopole, N>(m, d, first[0], v.hx, c, px, py, pz, n);
            } else {
              spread_lanes<Monopole, N>(m, d, first, v.hx, k, px, py, pz, n);
            }
          });
    }
  }
}

// Interpolation in 4-lane vectors (GCC/Clang vector extension; two SSE halves in the baseline clone). Over the rows
// of a z plane, lane-wise sums of u_c m and u_c dd, and per row of u_c d (weighted by the row's dy into a fourth
// sum); at the plane end they are weighted by the plane's factors into twelve lane-wise particle sums, reduced
// across lanes once per particle. (Reducing across lanes in every row, as a scalar `omp simd` reduction does, cost
// more than the products: rows are ~7 nodes.)
// A row of N >= 4 nodes is covered by whole vectors from its start plus one vector ending at its last node, whose
// lanes already counted are multiplied by zero; every load stays inside the row. Rows of 1-3 nodes are loaded
// lane by lane.
struct PlaneSums {
  Lanes m[3], t[3], d[3], dy[3];
};
struct ParticleLanes {
  Lanes u[3], s0[3], s1[3], s2[3];
};

// Loads 4 lanes from each pointer (Short: the first N, zero-filled), scales the table lanes by `keep` (1 or 0) if
// Masked, forms dd = dx d and adds the nine products (u m and u dd into the plane sums, u d into the row's).
template <bool Short, bool Masked, int N>
[[gnu::always_inline]] inline void add_chunk(const double* tm, const double* td, const Lanes& dx, const double* px,
                                             const double* py, const double* pz, const Lanes& keep, PlaneSums& s,
                                             Lanes (&rd)[3]) {
  Lanes m, d, ux, uy, uz;
  if constexpr (Short) {
    load_short<N>(tm, m);
    load_short<N>(td, d);
    load_short<N>(px, ux);
    load_short<N>(py, uy);
    load_short<N>(pz, uz);
  } else {
    load_lanes(tm, m);
    load_lanes(td, d);
    load_lanes(px, ux);
    load_lanes(py, uy);
    load_lanes(pz, uz);
    if constexpr (Masked) {
      m *= keep;
      d *= keep;
    }
  }
  const Lanes dd = dx * d;
  s.m[0] += ux * m;
  s.m[1] += uy * m;
  s.m[2] += uz * m;
  rd[0] += ux * d;
  rd[1] += uy * d;
  rd[2] += uz * d;
  s.t[0] += ux * dd;
  s.t[1] += uy * dd;
  s.t[2] += uz * dd;
}

// Sums of a row of N nodes (N = 0: any length >= 4, given by count) whose first node is table node t.
template <int N>
[[gnu::always_inline]] inline void interpolate_row(const double* m, const double* d, const Lanes& first, double hx,
                                                   const double* ux, const double* uy, const double* uz, int count,
                                                   PlaneSums& s, Lanes (&rd)[3]) {
  const Lanes all{1.0, 1.0, 1.0, 1.0};
  Lanes dx;
  if constexpr (N > 0 && N < 4) {
    add_chunk<true, false, N>(m, d, first, ux, uy, uz, all, s, rd);
  } else {
    const int n = N > 0 ? N : count;
    int i = 0;
    Lanes step;
    broadcast(4.0 * hx, step);
    dx = first;
    for (; i + 4 <= n; i += 4, dx += step) {
      add_chunk<false, false, 0>(m + i, d + i, dx, ux + i, uy + i, uz + i, all, s, rd);
    }
    if (i < n) {  // the last 4 nodes; lanes before node i were counted above
      const int o = n - 4, old = 4 - (n - i);
      const Lanes keep{old <= 0 ? 1.0 : 0.0, old <= 1 ? 1.0 : 0.0, old <= 2 ? 1.0 : 0.0, 1.0};
      x_offsets_from(first, hx, o, dx);
      add_chunk<false, true, 0>(m + o, d + o, dx, ux + o, uy + o, uz + o, keep, s, rd);
    }
  }
}

[[gnu::always_inline]] inline double lane_sum(const Lanes& v) { return (v[0] + v[1]) + (v[2] + v[3]); }

// Interpolates one particle: returns U / dV and the columns of A / (dV (-1/sD^2)).
SUSPEND_SIMD_CLONES void interpolate_particle(const Visit& v, const double* ux, const double* uy, const double* uz,
                                              Vec3& u, Mat3& a) {
  ParticleLanes p{};
  const std::ptrdiff_t w = v.width;
  for (const SupportPlane* q = v.planes; q != v.planes_end; ++q) {
    PlaneSums s{};
    const SupportRow* rows_end = v.rows + q->row_end;
    for (const SupportRow* r = v.rows + q->row_begin; r != rows_end; ++r) {
      const double* m = v.tables + r->table;
      const double* d = m + w;
      Lanes first;
      x_offsets(v, *r, first);
      const std::size_t o = r->first;
      const int n = r->count;
      Lanes rd[3] = {};
      with_fixed_length(n, [&](auto len) __attribute__((always_inline)) {
        interpolate_row<decltype(len)::value>(m, d, first, v.hx, ux + o, uy + o, uz + o, n, s, rd);
      });
      // dy is constant along the row: sum u dy d = dy sum u d.
      Lanes dy;
      broadcast(v.dy[r->j], dy);
      for (int c = 0; c < 3; ++c) {
        s.d[c] += rd[c];
        s.dy[c] += dy * rd[c];
      }
    }
    Lanes zm, zd, zdz;
    broadcast(q->zm, zm);
    broadcast(q->zd, zd);
    broadcast(q->zd * q->dz, zdz);
    for (int c = 0; c < 3; ++c) {
      p.u[c] += zm * s.m[c];
      p.s0[c] += zd * s.t[c];
      p.s1[c] += zd * s.dy[c];
      p.s2[c] += zdz * s.d[c];
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

// dx0 + (t + l) h_x for the 8 nodes from table node t (x_offsets in 8 lanes).
[[gnu::always_inline]] SUSPEND_AVX512 inline __m512d x_offsets_wide(double t, __m512d hx, __m512d dx0) {
  const __m512d lane = _mm512_set_pd(7.0, 6.0, 5.0, 4.0, 3.0, 2.0, 1.0, 0.0);
  return _mm512_add_pd(_mm512_mul_pd(_mm512_add_pd(lane, _mm512_set1_pd(t)), hx), dx0);
}

template <bool Monopole, bool Inside>
SUSPEND_AVX512 void spread_particle_wide(const Visit& v, const Vec3& f, const Mat3& gs, std::uint32_t zb,
                                         std::uint32_t ze, double* fx, double* fy, double* fz) {
  __m512d fm[3], g0[3], g1[3], g2[3];
  for (int i = 0; i < 3; ++i) {
    fm[i] = _mm512_set1_pd(f[i]);
    g0[i] = _mm512_set1_pd(gs(i, 0));
    g1[i] = _mm512_set1_pd(gs(i, 1));
    g2[i] = _mm512_set1_pd(gs(i, 2));
  }
  double* const field[3] = {fx, fy, fz};
  const std::ptrdiff_t w = v.width;
  const __m512d hx = _mm512_set1_pd(v.hx);
  for (const SupportPlane* q = v.planes; q != v.planes_end; ++q) {
    if constexpr (!Inside)
      if (q->iz < zb || q->iz >= ze) continue;
    // f_c += (F_c zm) m + (gs_c1 zd dy + gs_c2 zd dz) d + (gs_c0 zd) dx d   (RowCoefficients, as vectors)
    const __m512d zm = _mm512_set1_pd(q->zm), zd = _mm512_set1_pd(q->zd), zdz = _mm512_set1_pd(q->zd * q->dz);
    __m512d ka[3], kc[3], ke[3];
    for (int c = 0; c < 3; ++c) {
      ka[c] = _mm512_mul_pd(fm[c], zm);
      kc[c] = _mm512_mul_pd(g0[c], zd);
      ke[c] = _mm512_mul_pd(g2[c], zdz);
    }
    const SupportRow* rows_end = v.rows + q->row_end;
    const double plane_zd = q->zd;  // (a local: the field stores below could alias q->zd)
    for (const SupportRow* r = v.rows + q->row_begin; r != rows_end; ++r) {
      const __m512d wy = _mm512_set1_pd(plane_zd * v.dy[r->j]);
      __m512d kb[3];
      for (int c = 0; c < 3; ++c) kb[c] = _mm512_fmadd_pd(g1[c], wy, ke[c]);
      const double* m = v.tables + r->table;
      const double* d = m + w;
      const double t = first_table_node(v, *r);
      const __m512d dx0 = _mm512_set1_pd(v.dx0[r->j]);
      const int n = r->count;
      double* const p0 = field[0] + r->first;  // (the stores could alias *r: read it once)
      double* const p1 = field[1] + r->first;
      double* const p2 = field[2] + r->first;
      for (int i = 0; i < n; i += 8) {
        const __mmask8 k = row_mask(n - i);
        const __m512d vd = _mm512_maskz_loadu_pd(k, d + i);
        const __m512d vdd = _mm512_mul_pd(x_offsets_wide(t + i, hx, dx0), vd);
        __m512d vm = _mm512_setzero_pd();
        if constexpr (Monopole) vm = _mm512_maskz_loadu_pd(k, m + i);
        double* const p[3] = {p0 + i, p1 + i, p2 + i};
        for (int c = 0; c < 3; ++c) {
          __m512d x = _mm512_maskz_loadu_pd(k, p[c]);
          x = _mm512_fmadd_pd(kb[c], vd, x);
          x = _mm512_fmadd_pd(kc[c], vdd, x);
          if constexpr (Monopole) x = _mm512_fmadd_pd(ka[c], vm, x);
          _mm512_mask_storeu_pd(p[c], k, x);
        }
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

// The twelve plane sums live in registers; the twelve particle sums they are folded into once per plane live in
// memory (all 24 in registers left too few for the row's operands, which GCC then spilled in every row).
SUSPEND_AVX512 void interpolate_particle_wide(const Visit& v, const double* ux, const double* uy, const double* uz,
                                              Vec3& u, Mat3& a) {
  alignas(64) double sums[12][8] = {};  // u, then the columns 0, 1, 2 of A, each per component
  const double* const field[3] = {ux, uy, uz};
  const std::ptrdiff_t w = v.width;
  const __m512d hx = _mm512_set1_pd(v.hx);
  for (const SupportPlane* q = v.planes; q != v.planes_end; ++q) {
    __m512d pm[3], pt[3], pd[3], py[3];
    for (int c = 0; c < 3; ++c) pm[c] = pt[c] = pd[c] = py[c] = _mm512_setzero_pd();
    const SupportRow* rows_end = v.rows + q->row_end;
    for (const SupportRow* r = v.rows + q->row_begin; r != rows_end; ++r) {
      const double* m = v.tables + r->table;
      const double* d = m + w;
      const double t = first_table_node(v, *r);
      const __m512d dx0 = _mm512_set1_pd(v.dx0[r->j]);
      const int n = r->count;
      const __m512d dy = _mm512_set1_pd(v.dy[r->j]);
      for (int i = 0; i < n; i += 8) {
        const __mmask8 k = row_mask(n - i);
        const __m512d vm = _mm512_maskz_loadu_pd(k, m + i);
        const __m512d vd = _mm512_maskz_loadu_pd(k, d + i);
        const __m512d vdd = _mm512_mul_pd(x_offsets_wide(t + i, hx, dx0), vd);
        const __m512d vdy = _mm512_mul_pd(dy, vd);
        for (int c = 0; c < 3; ++c) {
          const __m512d x = _mm512_maskz_loadu_pd(k, field[c] + r->first + i);
          pm[c] = _mm512_fmadd_pd(x, vm, pm[c]);
          pt[c] = _mm512_fmadd_pd(x, vdd, pt[c]);
          pd[c] = _mm512_fmadd_pd(x, vd, pd[c]);
          py[c] = _mm512_fmadd_pd(x, vdy, py[c]);
        }
      }
    }
    const __m512d zm = _mm512_set1_pd(q->zm), zd = _mm512_set1_pd(q->zd), zdz = _mm512_set1_pd(q->zd * q->dz);
    for (int c = 0; c < 3; ++c) {
      _mm512_store_pd(sums[c], _mm512_fmadd_pd(zm, pm[c], _mm512_load_pd(sums[c])));
      _mm512_store_pd(sums[3 + c], _mm512_fmadd_pd(zd, pt[c], _mm512_load_pd(sums[3 + c])));
      _mm512_store_pd(sums[6 + c], _mm512_fmadd_pd(zd, py[c], _mm512_load_pd(sums[6 + c])));
      _mm512_store_pd(sums[9 + c], _mm512_fmadd_pd(zdz, pd[c], _mm512_load_pd(sums[9 + c])));
    }
  }
  for (int c = 0; c < 3; ++c) {
    u[c] = lane_sum_wide(_mm512_load_pd(sums[c]));
    a(c, 0) = lane_sum_wide(_mm512_load_pd(sums[3 + c]));
    a(c, 1) = lane_sum_wide(_mm512_load_pd(sums[6 + c]));
    a(c, 2) = lane_sum_wide(_mm512_load_pd(sums[9 + c]));
  }
}

bool cpu_has_avx512() {
  static const bool ok = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                         __builtin_cpu_supports("avx512dq");
  return ok;
}
#endif

bool wide() { return wide_kernels_on.load(std::memory_order_relaxed) && wide_kernels_available(); }

template <bool Monopole, bool Inside>
void spread_visit(bool use_wide, const Visit& v, const Vec3& f, const Mat3& gs, std::uint32_t zb, std::uint32_t ze,
                  double* fx, double* fy, double* fz) {
#if SUSPEND_WIDE_KERNELS
  if (use_wide) {
    spread_particle_wide<Monopole, Inside>(v, f, gs, zb, ze, fx, fy, fz);
    return;
  }
#endif
  (void)use_wide;
  spread_particle<Monopole, Inside>(v, f, gs, zb, ze, fx, fy, fz);
}

}  // namespace

void spread(const SupportPlan& plan, std::span<const Vec3> forces, std::span<const Mat3> dipoles, double* field,
            std::size_t stride) {
  const bool has_f = !forces.empty(), has_g = !dipoles.empty();
  if (!has_f && !has_g) return;
  const std::size_t count = plan.visits();
  double* fx = field;
  double* fy = field + stride;
  double* fz = field + 2 * stride;
  const bool use_wide = wide();
#pragma omp parallel
  {
    // Thread t owns z planes [z_begin, z_end): writes never collide.
    const auto [z_begin, z_end] = balanced_slab(plan.plane_nodes, omp_get_thread_num(), omp_get_num_threads());
    const auto zb = static_cast<std::uint32_t>(z_begin), ze = static_cast<std::uint32_t>(z_end);
    const auto nz = static_cast<std::uint32_t>(plan.plane_nodes.size());
    for (std::size_t k = 0; k < count; ++k) {
      if (!plan.touches_planes(k, zb, ze, nz)) continue;
      prefetch_tables(plan, k + 1);
      const std::size_t p = plan.particle[k];
      const Vec3 f = has_f ? forces[p] : Vec3::Zero();
      // d/dx_j Delta_D = -d_j / sigma_D^2 Delta_D, so G_ij d_j Delta_D = (G d)_i w_D (-1 / sigma_D^2).
      const Mat3 gs = has_g ? Mat3(dipoles[p] * plan.dipole_scale[k]) : Mat3::Zero();
      const Visit v = visit_of(plan, k);
      const bool inside = plan.inside_planes(k, zb, ze);
      if (has_f) {
        if (inside)
          spread_visit<true, true>(use_wide, v, f, gs, zb, ze, fx, fy, fz);
        else
          spread_visit<true, false>(use_wide, v, f, gs, zb, ze, fx, fy, fz);
      } else {
        if (inside)
          spread_visit<false, true>(use_wide, v, f, gs, zb, ze, fx, fy, fz);
        else
          spread_visit<false, false>(use_wide, v, f, gs, zb, ze, fx, fy, fz);
      }
    }
  }
}

void interpolate(const SupportPlan& plan, const double* field, std::size_t stride, std::span<Vec3> velocities,
                 std::span<Mat3> gradient_moments) {
  const bool want_u = !velocities.empty(), want_a = !gradient_moments.empty();
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t>(plan.visits());
  const double dv = plan.cell_volume;
  [[maybe_unused]] const bool use_wide = wide();
#pragma omp parallel for schedule(dynamic, 16)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const std::size_t ku = static_cast<std::size_t>(k);
    prefetch_tables(plan, ku + 1);
    Vec3 u;
    Mat3 a;
    const Visit v = visit_of(plan, ku);
#if SUSPEND_WIDE_KERNELS
    if (use_wide)
      interpolate_particle_wide(v, field, field + stride, field + 2 * stride, u, a);
    else
#endif
      interpolate_particle(v, field, field + stride, field + 2 * stride, u, a);
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
