#include "dem/packing.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numbers>
#include <numeric>
#include <random>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "dem/neighbour_search.hpp"

namespace suspend {

namespace {

constexpr double four_thirds_pi = 4.0 * std::numbers::pi / 3.0;

// FIRE parameters (Bitzek et al. 2006, with the N_delay and half-step backtrack of Guenole et al.,
// Comput. Mater. Sci. 175, 109584 (2020)); time in units sqrt(m / k) with unit mass and unit spring constant.
struct Fire {
  double dt_start = 0.05;
  double dt_max = 0.4;
  double dt_min = 1e-3;
  double f_inc = 1.1;
  double f_dec = 0.5;
  double alpha_start = 0.1;
  double f_alpha = 0.99;
  int n_delay = 5;
};

// A stage ends when the largest overlap drops below its tolerance, or when the system is jammed: net forces balanced
// (largest net force below this fraction of the largest overlap) while overlaps remain.
constexpr double jammed_force_ratio = 1e-7;
// Reductions are summed in blocks of this many particles, then block by block in order: the result does not
// depend on the thread count.
constexpr std::size_t reduction_block = 256;
// Intermediate stages stop at this largest overlap (units of the scaled smallest radius).
constexpr double intermediate_overlap = 1e-3;
// A stage closer than this to the target volume fraction is replaced by the final stage.
constexpr double snap_to_target = 1e-4;
// After a jam: expand to this much below the last overlap-free volume fraction, shake centres by up to this
// fraction of the smallest radius, and compress again.
constexpr double retry_backoff = 0.02;
constexpr double shake_amplitude = 0.2;
// OpenMP only pays off above this many particles.
constexpr std::size_t parallel_threshold = 4096;

enum class StageOutcome { converged, jammed, out_of_iterations };

// Harmonic soft spheres in a plain periodic box, relaxed with FIRE over a Verlet list built from the cell list.
class SoftSphereRelaxation {
 public:
  // The Verlet skin adapts between skin_min and skin_max to the rate at which the lists expire.
  SoftSphereRelaxation(std::vector<Vec3> position, const Box& box, double skin_min, double skin_max)
      : box_(box), length_(box.length()), x_(std::move(position)), skin_(skin_min), skin_min_(skin_min),
        skin_max_(skin_max) {
    half_length_ = 0.5 * length_;
    v_.assign(x_.size(), Vec3::Zero());
    f_.assign(x_.size(), Vec3::Zero());
    partial_.resize(3 * ((x_.size() + reduction_block - 1) / reduction_block));
  }

  // Radii only grow between stages; the list stays valid while growth plus displacement fit in half the skin.
  void set_radii(std::vector<double> radius) {
    a_ = std::move(radius);
    if (a_built_.size() != a_.size()) {
      rebuild();
      return;
    }
    growth_ = 0.0;
    for (std::size_t i = 0; i < a_.size(); ++i) growth_ = std::max(growth_, a_[i] - a_built_[i]);
  }

  // FIRE until the largest overlap is below tol, the system jams or the step budget is used up.
  StageOutcome relax(double tol, long& budget) {
    Fire fire;
    double dt = fire.dt_start, alpha = fire.alpha_start;
    int n_positive = 0;
    std::fill(v_.begin(), v_.end(), Vec3::Zero());
    double displacement = max_displacement();
    while (true) {
      if (displacement + growth_ > 0.5 * skin_) {
        adapt_skin();
        rebuild();
      }
      const Evaluation e = evaluate();
      if (e.max_overlap < tol) return StageOutcome::converged;
      if (e.max_force < jammed_force_ratio * e.max_overlap) return StageOutcome::jammed;
      if (budget <= 0) return StageOutcome::out_of_iterations;
      --budget;
      ++iterations_;

      // FIRE: downhill, mix the velocity towards the force; uphill, step back half a step and stop.
      const bool uphill = !(e.power > 0.0);
      const double keep = uphill ? 0.0 : 1.0 - alpha;
      const double mix = (uphill || e.ff == 0.0) ? 0.0 : alpha * std::sqrt(e.vv / e.ff);
      if (uphill) {
        n_positive = 0;
        dt = std::max(dt * fire.f_dec, fire.dt_min);
        alpha = fire.alpha_start;
      } else if (++n_positive > fire.n_delay) {
        dt = std::min(dt * fire.f_inc, fire.dt_max);
        alpha *= fire.f_alpha;
      }
      displacement = step(uphill ? 0.5 * dt : 0.0, keep, mix, dt);
    }
  }

  // Uniform random displacement of every centre, each component in [-amplitude, amplitude]; serial, so the
  // random sequence does not depend on the thread count.
  void shake(Rng& rng, double amplitude) {
    std::uniform_real_distribution<double> u(-amplitude, amplitude);
    for (auto& r : x_) {
      const double dx = u(rng), dy = u(rng), dz = u(rng);
      r += Vec3(dx, dy, dz);
    }
    rebuild();
  }

  // Smallest surface gap |r_ij| - a_i - a_j over all pairs, for the radii given (infinite for a single sphere).
  double min_gap(const std::vector<double>& radius) {
    wrap();
    double cutoff = skin_;
    while (true) {
      search_.find_pairs(x_, radius, box_, cutoff, pairs_);
      if (!pairs_.empty() || cutoff > length_.maxCoeff()) break;
      cutoff *= 2.0;
    }
    double gap = std::numeric_limits<double>::infinity();
    for (const auto& p : pairs_) gap = std::min(gap, separation(p.i, p.j).norm() - radius[p.i] - radius[p.j]);
    return gap;
  }

  const std::vector<Vec3>& positions() {
    wrap();
    return x_;
  }
  long iterations() const { return iterations_; }
  int rebuilds() const { return rebuilds_; }

 private:
  Vec3 separation(std::size_t i, std::size_t j) const {
    Vec3 d = x_[j] - x_[i];
    // Positions stay within a skin of the primary cell between rebuilds, so one image shift suffices.
    for (int k = 0; k < 3; ++k) {
      if (d[k] > half_length_[k])
        d[k] -= length_[k];
      else if (d[k] < -half_length_[k])
        d[k] += length_[k];
    }
    return d;
  }

  void wrap() {
    for (auto& r : x_) box_.wrap(r);
  }

  // Large moves (early stages) would rebuild the list every few steps, and a rebuild costs tens of force
  // evaluations: widen the skin then, narrow it again once the particles barely move.
  void adapt_skin() {
    const long interval = iterations_ - built_at_;
    if (interval < 10)
      skin_ = std::min(1.5 * skin_, skin_max_);
    else if (interval > 100)
      skin_ = std::max(skin_ / 1.5, skin_min_);
  }

  // Verlet list: every pair closer than skin, stored for both partners (CSR) so that each particle gathers its own
  // force in a fixed order.
  void rebuild() {
    wrap();
    search_.find_pairs(x_, a_, box_, skin_, pairs_);
    const std::size_t n = x_.size();
    start_.assign(n + 1, 0);
    for (const auto& p : pairs_) {
      ++start_[p.i + 1];
      ++start_[p.j + 1];
    }
    std::partial_sum(start_.begin(), start_.end(), start_.begin());
    neighbour_.resize(2 * pairs_.size());
    fill_.assign(start_.begin(), start_.end() - 1);
    for (const auto& p : pairs_) {
      neighbour_[fill_[p.i]++] = p.j;
      neighbour_[fill_[p.j]++] = p.i;
    }
    x_ref_ = x_;
    a_built_ = a_;
    growth_ = 0.0;
    built_at_ = iterations_;
    ++rebuilds_;
  }

  double max_displacement() const {
    double d2 = 0.0;
    const std::size_t n = x_.size();
#pragma omp parallel for schedule(static) reduction(max : d2) if (n > parallel_threshold)
    for (std::size_t i = 0; i < n; ++i) d2 = std::max(d2, (x_[i] - x_ref_[i]).squaredNorm());
    return std::sqrt(d2);
  }

  struct Evaluation {
    double max_overlap, max_force;  // largest pair overlap and net force
    double power, vv, ff;           // F.v, v.v, F.F
  };

  // F_i = sum_j delta_ij n_ji, the force of E = sum (1/2) delta^2, with the FIRE sums taken in fixed blocks.
  Evaluation evaluate() {
    double max_overlap = 0.0, max_force2 = 0.0;
    const std::size_t n = x_.size();
    const std::size_t blocks = partial_.size() / 3;
#pragma omp parallel for schedule(static) reduction(max : max_overlap, max_force2) if (n > parallel_threshold)
    for (std::size_t b = 0; b < blocks; ++b) {
      double power = 0.0, vv = 0.0, ff = 0.0;
      for (std::size_t i = b * reduction_block; i < std::min(n, (b + 1) * reduction_block); ++i) {
        Vec3 force = Vec3::Zero();
        const Vec3 xi = x_[i];
        const double ai = a_[i];
        for (std::uint32_t k = start_[i]; k < start_[i + 1]; ++k) {
          const std::uint32_t j = neighbour_[k];
          Vec3 d = x_[j] - xi;
          for (int c = 0; c < 3; ++c) {  // one image shift suffices: positions stay within a skin of the cell
            if (d[c] > half_length_[c])
              d[c] -= length_[c];
            else if (d[c] < -half_length_[c])
              d[c] += length_[c];
          }
          const double contact = ai + a_[j];
          const double r2 = d.squaredNorm();
          if (r2 >= contact * contact) continue;
          const double r = std::sqrt(r2);
          const double overlap = contact - r;
          force -= (overlap / r) * d;
          max_overlap = std::max(max_overlap, overlap);
        }
        f_[i] = force;
        max_force2 = std::max(max_force2, force.squaredNorm());
        power += force.dot(v_[i]);
        vv += v_[i].squaredNorm();
        ff += force.squaredNorm();
      }
      partial_[3 * b] = power;
      partial_[3 * b + 1] = vv;
      partial_[3 * b + 2] = ff;
    }
    Evaluation e{max_overlap, std::sqrt(max_force2), 0.0, 0.0, 0.0};
    for (std::size_t b = 0; b < blocks; ++b) {
      e.power += partial_[3 * b];
      e.vv += partial_[3 * b + 1];
      e.ff += partial_[3 * b + 2];
    }
    return e;
  }

  // x -= back v; v = keep v + mix F; then semi-implicit Euler v += dt F, x += dt v. Returns the largest
  // displacement since the list was built.
  double step(double back, double keep, double mix, double dt) {
    double d2 = 0.0;
    const std::size_t n = x_.size();
#pragma omp parallel for schedule(static) reduction(max : d2) if (n > parallel_threshold)
    for (std::size_t i = 0; i < n; ++i) {
      x_[i] -= back * v_[i];
      v_[i] = keep * v_[i] + mix * f_[i];
      v_[i] += dt * f_[i];
      x_[i] += dt * v_[i];
      d2 = std::max(d2, (x_[i] - x_ref_[i]).squaredNorm());
    }
    return std::sqrt(d2);
  }

  Box box_;
  Vec3 length_, half_length_;
  std::vector<Vec3> x_, v_, f_, x_ref_;
  std::vector<double> a_, a_built_;
  double skin_, skin_min_, skin_max_;
  double growth_ = 0.0;  // largest radius growth since the list was built
  CellListSearch search_;
  std::vector<NeighbourPair> pairs_;
  std::vector<std::uint32_t> start_, neighbour_, fill_;
  std::vector<double> partial_;
  long iterations_ = 0, built_at_ = 0;
  int rebuilds_ = 0;
};

std::string format_phi(double phi) {
  std::ostringstream s;
  s << std::setprecision(4) << std::fixed << phi;
  return s.str();
}

}  // namespace

void PackingParams::validate() const {
  if (!(min_gap >= 0.0)) throw InputError("packing.min_gap must be >= 0 (got " + std::to_string(min_gap) + ")");
  if (!(margin > 0.0 && margin < 1e-2))
    throw InputError("packing.margin must be in (0, 0.01) (got " + std::to_string(margin) + ")");
  if (!(phi_start > 0.0 && phi_start < 0.6))
    throw InputError("packing.phi_start must be in (0, 0.6) (got " + std::to_string(phi_start) + ")");
  if (!(growth > 0.0 && growth <= 1.0))
    throw InputError("packing.growth must be in (0, 1] (got " + std::to_string(growth) + ")");
  if (max_iterations <= 0) throw InputError("packing.max_iterations must be positive");
  if (stage_iterations <= 0) throw InputError("packing.stage_iterations must be positive");
  if (max_retries < 0) throw InputError("packing.max_retries must be >= 0");
}

double volume_fraction(const std::vector<double>& radius, double volume) {
  double v = 0.0;
  for (double a : radius) v += four_thirds_pi * a * a * a;
  return v / volume;
}

Box cube_for_volume_fraction(const std::vector<double>& radius, double phi) {
  if (!(phi > 0.0 && phi < 1.0)) throw InputError("packing: volume fraction phi must be in (0, 1)");
  const double edge = std::cbrt(volume_fraction(radius, 1.0) / phi);
  return Box(edge, edge, edge);
}

Packing random_packing(const std::vector<double>& radius, const Box& box, const PackingParams& params) {
  params.validate();
  const auto clock_start = std::chrono::steady_clock::now();
  if (box.shear_offset() != 0.0) throw InputError("packing: the box must have zero shear offset");
  Packing out;
  const std::size_t n = radius.size();
  const double phi_target = volume_fraction(radius, box.volume());
  out.report.phi_target = phi_target;
  out.report.phi = phi_target;
  if (n == 0) return out;
  if (n > std::numeric_limits<std::uint32_t>::max()) throw InputError("packing: too many particles");
  const auto [a_min_it, a_max_it] = std::minmax_element(radius.begin(), radius.end());
  const double a_min = *a_min_it, a_max = *a_max_it;
  if (!(a_min > 0.0)) throw InputError("packing: every radius must be positive");
  if (box.length().minCoeff() <= 2.0 * a_max + params.min_gap)
    throw InputError("packing: the box edge must exceed the largest diameter plus min_gap");
  if (phi_target >= 1.0)
    throw InputError("packing: volume fraction " + format_phi(phi_target) + " is unreachable (>= 1)");

  Rng rng(params.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> start(n);
  const Vec3& L = box.length();
  for (auto& r : start) {
    const double u = unit(rng), v = unit(rng), w = unit(rng);
    r = Vec3(u * L.x(), v * L.y(), w * L.z());
  }
  // The skin bounds how far particles move between Verlet-list rebuilds; measured in the smallest radius it keeps the
  // lists short for wide size distributions.
  SoftSphereRelaxation relaxation(std::move(start), box, 0.3 * a_min, 1.0 * a_min);

  long budget = params.max_iterations;
  double phi_stage = std::min(params.phi_start, phi_target);
  double phi_reached = 0.0, phi_highest = 0.0;  // last and highest overlap-free stage
  while (true) {
    const double s = std::cbrt(phi_stage / phi_target);
    const bool final_stage = (phi_stage == phi_target);
    std::vector<double> a(n);
    for (std::size_t i = 0; i < n; ++i) a[i] = s * (radius[i] * (1.0 + params.margin) + 0.5 * params.min_gap);
    relaxation.set_radii(std::move(a));
    ++out.report.stages;
    // Intermediate stages only need to be nearly overlap-free; the last one must leave every true gap >= min_gap.
    const double tol = final_stage ? params.margin * a_min : intermediate_overlap * s * a_min;
    long stage_budget = std::min(budget, params.stage_iterations);
    const long stage_start = stage_budget;
    const StageOutcome outcome = relaxation.relax(tol, stage_budget);
    budget -= stage_start - stage_budget;
    if (outcome == StageOutcome::converged) {
      phi_reached = phi_stage;
      phi_highest = std::max(phi_highest, phi_stage);
      if (final_stage) break;
      phi_stage += params.growth * (phi_target - phi_stage);
      if (phi_target - phi_stage < snap_to_target) phi_stage = phi_target;
      continue;
    }
    // Jammed (or stalled) short of the target: this basin of the energy landscape cannot hold the target. Expand
    // back below the last good density, shake the centres and compress again into another basin.
    if (budget <= 0 || out.report.retries == params.max_retries) {
      const std::string why = outcome == StageOutcome::jammed ? "the packing jammed at phi = " + format_phi(phi_stage)
                                                              : "the overlaps were not removed at phi = " +
                                                                    format_phi(phi_stage) + " within the iterations";
      throw InputError("packing: volume fraction " + format_phi(phi_target) +
                       " is unreachable for this box and particle count (" + why + " after " +
                       std::to_string(out.report.retries) + " retries; highest reached without overlap: " +
                       format_phi(phi_highest) + "); lower phi or use a wider size distribution");
    }
    ++out.report.retries;
    phi_stage = std::max(std::min(params.phi_start, phi_target), phi_reached - retry_backoff);
    relaxation.shake(rng, shake_amplitude * a_min);
  }

  out.position = relaxation.positions();
  out.report.min_gap = relaxation.min_gap(radius);
  out.report.iterations = relaxation.iterations();
  out.report.neighbour_rebuilds = relaxation.rebuilds();
  out.report.phi = volume_fraction(radius, box.volume());
  out.report.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  if (!(out.report.min_gap >= params.min_gap))
    throw NumericalError("packing: final minimum gap " + std::to_string(out.report.min_gap) + " below min_gap");
  return out;
}

// --- species bookkeeping ---------------------------------------------------------------------------------------

namespace {
void validate_species(const std::vector<Species>& species) {
  if (species.empty()) throw InputError("species: at least one species is needed");
  double total = 0.0;
  for (const auto& s : species) {
    if (!(s.radius > 0.0)) throw InputError("species: radius must be positive");
    if (!(s.volume_share >= 0.0)) throw InputError("species: volume_share must be >= 0");
    total += s.volume_share;
  }
  if (std::abs(total - 1.0) > 1e-9) throw InputError("species: volume shares must sum to 1");
}

double share_error(const std::vector<Species>& species, const std::vector<std::size_t>& counts) {
  double total = 0.0;
  for (std::size_t k = 0; k < species.size(); ++k) total += counts[k] * std::pow(species[k].radius, 3);
  if (total == 0.0) return std::numeric_limits<double>::infinity();
  double err = 0.0;
  for (std::size_t k = 0; k < species.size(); ++k) {
    const double e = counts[k] * std::pow(species[k].radius, 3) / total - species[k].volume_share;
    err += e * e;
  }
  return err;
}
}  // namespace

std::vector<std::size_t> species_counts(const std::vector<Species>& species, std::size_t total) {
  validate_species(species);
  // n_k proportional to share_k / a_k^3; floor, then hand out the remaining particles one at a time to the species
  // that brings the volume shares closest to the request.
  double norm = 0.0;
  for (const auto& s : species) norm += s.volume_share / std::pow(s.radius, 3);
  std::vector<std::size_t> counts(species.size());
  std::size_t assigned = 0;
  for (std::size_t k = 0; k < species.size(); ++k) {
    counts[k] = static_cast<std::size_t>(
        std::floor(static_cast<double>(total) * species[k].volume_share / std::pow(species[k].radius, 3) / norm));
    assigned += counts[k];
  }
  for (; assigned < total; ++assigned) {
    std::size_t best = 0;
    double best_err = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < species.size(); ++k) {
      if (species[k].volume_share == 0.0) continue;
      ++counts[k];
      const double err = share_error(species, counts);
      --counts[k];
      if (err < best_err) {
        best_err = err;
        best = k;
      }
    }
    ++counts[best];
  }
  return counts;
}

std::vector<std::size_t> species_counts(const std::vector<Species>& species, double phi, const Box& box) {
  validate_species(species);
  if (!(phi > 0.0 && phi < 1.0)) throw InputError("species: volume fraction phi must be in (0, 1)");
  std::vector<std::size_t> counts;
  for (const auto& s : species)
    counts.push_back(static_cast<std::size_t>(
        std::llround(phi * box.volume() * s.volume_share / (four_thirds_pi * std::pow(s.radius, 3)))));
  return counts;
}

std::vector<double> species_radii(const std::vector<Species>& species, const std::vector<std::size_t>& counts) {
  if (counts.size() != species.size()) throw InputError("species: one count per species is needed");
  std::vector<double> radius;
  for (std::size_t k = 0; k < species.size(); ++k) radius.insert(radius.end(), counts[k], species[k].radius);
  return radius;
}

}  // namespace suspend
