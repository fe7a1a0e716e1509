// The free-space direct-sum reference against exact Stokes results: the isolated-sphere limit 1/(6 pi a) of the
// regularised Stokeslet, its Oseen + O(s^2/r^3) far field, and the rotlet pair couplings
// Omega_m = F_n x r / (8 pi r^3), U_m = T_n x r / (8 pi r^3) (r = Y_m - Y_n; exact outside the envelopes up
// to exponentially small terms, by the mean-value property of harmonic fields).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "fcm/direct_sum.hpp"
#include "fcm/envelope.hpp"

using namespace suspend;
using namespace suspend::fcm;

namespace {
constexpr double pi = std::numbers::pi;
}

TEST(FcmDirectSum, RegularisedStokesletAtTheOriginIsTheStokesMobility) {
  const double a = 1.3, s = monopole_width(a);
  const Mat3 m0 = regularised_stokeslet(Vec3::Zero(), 2.0 * s * s);
  EXPECT_NEAR((m0 - Mat3::Identity() / (6.0 * pi * a)).norm(), 0.0, 1e-15);
  // Series and closed form agree where they meet (x = c r = 1e-3).
  const double c = 1.0 / (2.0 * s);
  const Vec3 dir = Vec3(1.0, 2.0, -0.5).normalized();
  const Mat3 below = regularised_stokeslet(dir * (0.999e-3 / c), 2.0 * s * s);
  const Mat3 above = regularised_stokeslet(dir * (1.001e-3 / c), 2.0 * s * s);
  EXPECT_NEAR((below - above).norm() / m0.norm(), 0.0, 1e-8);
}

TEST(FcmDirectSum, FarFieldIsOseenPlusTheRegularisationQuadrupole) {
  const double var = 0.7;
  const Vec3 r(9.0, -14.0, 11.0);
  const double d = r.norm();
  const Mat3 rr = r * r.transpose() / (d * d);
  const Mat3 expect = (Mat3::Identity() + rr) / (8.0 * pi * d) + var * (Mat3::Identity() - 3.0 * rr) / (8.0 * pi * d * d * d);
  EXPECT_NEAR((regularised_stokeslet(r, var) - expect).norm() / expect.norm(), 0.0, 1e-13);
}

TEST(FcmDirectSum, RotletCouplingsBetweenDistantSpheres) {
  const std::vector<Vec3> pos{Vec3(0.0, 0.0, 0.0), Vec3(4.0, 3.0, -5.0)};
  const std::vector<double> rad{1.0, 1.4};
  const Vec3 r = pos[0] - pos[1];
  const double d3 = std::pow(r.norm(), 3);
  const std::vector<Vec3> f{Vec3::Zero(), Vec3(0.3, -1.0, 0.8)};
  const Disturbance byf = direct_sum(pos, rad, f, {}, {});
  const Vec3 om = f[1].cross(r) / (8.0 * pi * d3);
  EXPECT_NEAR((byf.angular_velocities[0] - om).norm() / om.norm(), 0.0, 1e-7);
  const std::vector<Vec3> t{Vec3::Zero(), Vec3(1.0, 0.2, -0.6)};
  const Disturbance byt = direct_sum(pos, rad, {}, t, {});
  const Vec3 u = t[1].cross(r) / (8.0 * pi * d3);
  EXPECT_NEAR((byt.velocities[0] - u).norm() / u.norm(), 0.0, 1e-7);
  // Isolated self terms: Omega = T / (8 pi a^3) on the torqued sphere.
  EXPECT_NEAR((byt.angular_velocities[1] - t[1] * rotational_self_mobility(1.4)).norm(), 0.0, 1e-3 * t[1].norm());
}
