// The matrix-free explicit hydrodynamics of the inertial integrator (dem/integrate/explicit_hydrodynamics.hpp)
// against the assembled resistance matrix (ResistanceSolver::explicit_forces and relaxation_rate): forces, torques,
// both lubrication stress forms and the Gershgorin rate bound agree to round-off on a dense polydisperse
// configuration with a Lees-Edwards offset in wavy shear; the result does not depend on the thread count.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <numbers>
#include <random>

#include "dem/integrate/explicit_hydrodynamics.hpp"
#include "dem/integrate/resistance_solver.hpp"
#include "dem/neighbour_search.hpp"
#include "dem/packing.hpp"

using namespace suspend;
using std::numbers::pi;

namespace {

// Three species (a = 1, 1.4, 2.2) packed at phi = 0.5, then sheared: the Lees-Edwards offset of 0.37 L_x moves
// the images across the y faces, so those pairs have random gaps (some overlap and saturate at h_in).
struct Configuration {
  std::vector<double> radii{1.0, 1.4, 2.2};
  Particles p;
  Box box;
  std::vector<ActivePair> pairs;
  Eigen::VectorXd dv;
  std::vector<double> mass, moment;
};

Configuration dense_sheared(std::size_t n) {
  Configuration c;
  std::vector<double> a(n);
  c.p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    c.p.species[i] = i % 7 == 0 ? 2 : (i % 2 ? 1 : 0);
    a[i] = c.p.radius[i] = c.radii[c.p.species[i]];
  }
  c.box = cube_for_volume_fraction(a, 0.5);
  PackingParams pp;
  pp.seed = 5;
  c.p.position = random_packing(a, c.box, pp).position;
  c.box.set_shear_offset(0.37 * c.box.length().x());
  std::vector<NeighbourPair> list;
  CellListSearch search;
  const double gap_cutoff = 0.4;  // the list reaches beyond the lubrication cutoff 0.25: those pairs are skipped
  search.find_pairs(c.p.position, c.p.radius, c.box, gap_cutoff, list);
  compact_active_pairs(list, c.p, c.box, gap_cutoff, c.pairs);
  std::mt19937_64 rng(17);
  std::normal_distribution<double> g;
  c.dv.resize(6 * static_cast<Eigen::Index>(n));
  for (Eigen::Index k = 0; k < c.dv.size(); ++k) c.dv[k] = g(rng);
  for (std::size_t i = 0; i < n; ++i) {
    c.mass.push_back(1e-3 * (4.0 / 3.0) * pi * std::pow(a[i], 3));
    c.moment.push_back(0.4 * c.mass.back() * a[i] * a[i]);
  }
  return c;
}

double max_abs(const Eigen::VectorXd& v) { return v.cwiseAbs().maxCoeff(); }

}  // namespace

TEST(ExplicitHydrodynamics, MatrixFreeForcesStressAndRateEqualTheAssembledOnes) {
  Configuration c = dense_sheared(600);
  int across = 0;
  for (const ActivePair& pr : c.pairs) across += pr.y_images != 0 && pr.gap() <= 0.25 ? 1 : 0;
  ASSERT_GT(across, 10);  // lubricated pairs across the sheared faces
  const AmbientFlow flow = AmbientFlow::wavy_shear(1.3, 0.8, 1, c.box.length().y());

  for (const LubricationStress form : {LubricationStress::force_dipole, LubricationStress::stresslet}) {
    ResistanceSolverParams params;
    params.lubrication_stress = form;
    ResistanceSolver assembled(c.radii, params);
    Eigen::VectorXd force;
    SolveResult reference;
    assembled.explicit_forces(c.p, c.p.species, c.pairs, flow, c.dv, force, reference);
    const double rate = assembled.relaxation_rate(c.mass, c.moment);

    ExplicitHydrodynamics matrix_free(c.radii, params.lubrication, form);
    ExplicitHydroResult out;
    matrix_free.evaluate(c.p, c.p.species, c.pairs, flow, c.dv, c.mass, c.moment, out);

    EXPECT_GT(out.lubricated_pairs, 2 * c.p.size());  // dense: several lubrication neighbours per particle
    EXPECT_EQ(out.lubricated_pairs, reference.lubricated_pairs);
    ASSERT_EQ(out.force.size(), force.size());
    EXPECT_LT(max_abs(out.force - force), 1e-13 * max_abs(force));
    for (std::size_t i = 0; i < c.p.size(); ++i)  // each particle to round-off of its own largest term
      EXPECT_LT(max_abs(out.force.segment<6>(6 * i) - force.segment<6>(6 * i)), 1e-11 * max_abs(force)) << i;
    for (const Contribution part : {Contribution::hydrodynamic, Contribution::lubrication}) {
      const Mat3& s = reference.stress[part];
      EXPECT_GT(s.norm(), 0.0);
      EXPECT_LT((out.stress[part] - s).norm(), 1e-13 * s.norm()) << static_cast<int>(part);
    }
    EXPECT_NEAR(out.relaxation_rate, rate, 1e-14 * rate);
    EXPECT_GT(rate, 6.0 * pi / c.mass[0]);  // lubrication raises the rate above the Stokes drag's
  }
}

TEST(ExplicitHydrodynamics, ResultIsBitIdenticalForAnyThreadCount) {
  Configuration c = dense_sheared(600);
  const AmbientFlow flow = AmbientFlow::wavy_shear(1.0, 0.5, 1, c.box.length().y());
  ExplicitHydroResult out[2];
  const int threads = omp_get_max_threads();
  for (int k = 0; k < 2; ++k) {
    omp_set_num_threads(k + 1);
    ExplicitHydrodynamics h(c.radii, hydro::LubricationParams{});
    h.evaluate(c.p, c.p.species, c.pairs, flow, c.dv, c.mass, c.moment, out[k]);
  }
  omp_set_num_threads(threads);
  EXPECT_TRUE(out[0].force == out[1].force);
  EXPECT_EQ(out[0].stress[Contribution::lubrication], out[1].stress[Contribution::lubrication]);
  EXPECT_EQ(out[0].stress[Contribution::hydrodynamic], out[1].stress[Contribution::hydrodynamic]);
  EXPECT_EQ(out[0].relaxation_rate, out[1].relaxation_rate);
}
