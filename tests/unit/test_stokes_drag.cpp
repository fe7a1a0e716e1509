// Isolated-sphere Stokes drag with Faxen corrections (dem/hydro/stokes_drag.hpp) in simple and wavy shear
// (paper 000 eqs. A.1, 9a, 17), against closed-form values.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/ambient_flow.hpp"
#include "dem/hydro/stokes_drag.hpp"

using namespace suspend;
using namespace suspend::hydro;

namespace {
constexpr double pi = std::numbers::pi;
}

TEST(StokesDrag, StokesLawForTranslationAndRotation) {
  const AmbientFlow flow = AmbientFlow::simple_shear(0.0);  // quiescent fluid
  const double a = 1.7;
  const StokesDragResult r = stokes_drag(a, Vec3(1, 2, 3), Vec3(0.5, -1.0, 2.0), Vec3(0.1, 0.2, -0.3), flow);
  EXPECT_LT((r.force + 6.0 * pi * a * Vec3(0.5, -1.0, 2.0)).norm(), 1e-12);
  EXPECT_LT((r.torque + 8.0 * pi * a * a * a * Vec3(0.1, 0.2, -0.3)).norm(), 1e-12);
  EXPECT_EQ(r.stresslet.norm(), 0.0);
}

// Simple shear (docs/units.md, Conventions): U_inf = (gammadot y, 0, 0), Omega_inf = (0, 0, -gammadot/2),
// E_xy = gammadot/2.
// A sphere moving and spinning with the fluid feels nothing; its stresslet is (20/3) pi a^3 E (Einstein).
TEST(StokesDrag, SphereAdvectedBySimpleShearIsForceFree) {
  const double gammadot = 2.5, a = 1.3;
  const AmbientFlow flow = AmbientFlow::simple_shear(gammadot);
  const Vec3 x(0.4, -1.1, 2.0);
  const Vec3 u(gammadot * x.y(), 0.0, 0.0), omega(0.0, 0.0, -gammadot / 2.0);
  const StokesDragResult r = stokes_drag(a, x, u, omega, flow);
  EXPECT_LT(r.force.norm(), 1e-12);
  EXPECT_LT(r.torque.norm(), 1e-12);
  EXPECT_NEAR(r.stresslet(0, 1), 20.0 / 3.0 * pi * a * a * a * gammadot / 2.0, 1e-12);
  EXPECT_NEAR(r.stresslet(1, 0), r.stresslet(0, 1), 1e-15);
  EXPECT_NEAR(r.stresslet.trace(), 0.0, 1e-15);
  EXPECT_EQ(flow.velocity_laplacian(x).norm(), 0.0);  // linear flow: no Faxen term
}

// Wavy shear U_x = gammadot y + U sin(k y): a sphere held at rest at height y feels
// F_x = 6 pi a (gammadot y + U sin(k y) (1 - (k a)^2/6)), T_z = -8 pi a^3 (gammadot + U k cos(k y))/2,
// S_xy = (20/3) pi a^3 (gammadot + U k cos(k y) (1 - (k a)^2/10))/2 (Faxen's laws with lap sin = -k^2 sin).
TEST(StokesDrag, FaxenCorrectionsInWavyShear) {
  const AmbientFlow flow = AmbientFlow::wavy_shear(1.0, 20.0, 1, 12.0);  // paper 000 Table 3 (YW)
  flow.validate();
  const double k = 2.0 * pi / 12.0, a = 3.0;  // the large species of paper 000 section 3.2
  for (double y : {-4.0, 0.7, 2.5}) {
    const Vec3 x(1.0, y, -2.0);
    const StokesDragResult r = stokes_drag(a, x, Vec3::Zero(), Vec3::Zero(), flow);
    const double fx = 6.0 * pi * a * (y + 20.0 * std::sin(k * y) * (1.0 - k * k * a * a / 6.0));
    EXPECT_NEAR(r.force.x(), fx, 1e-10 * std::abs(fx) + 1e-12);
    EXPECT_NEAR(r.force.y(), 0.0, 1e-14);
    EXPECT_NEAR(r.torque.z(), -8.0 * pi * a * a * a * (1.0 + 20.0 * k * std::cos(k * y)) / 2.0, 1e-9);
    const double sxy = 20.0 / 3.0 * pi * a * a * a * (1.0 + 20.0 * k * std::cos(k * y) * (1.0 - k * k * a * a / 10.0)) / 2.0;
    EXPECT_NEAR(r.stresslet(0, 1), sxy, 1e-10 * std::abs(sxy));
    // The Faxen term is not negligible here: (k a)^2/6 = 41%.
    EXPECT_GT(std::abs(r.force.x() - 6.0 * pi * a * flow.velocity(x).x()), 0.01 * 6.0 * pi * a * 20.0 * std::abs(std::sin(k * y)));
  }
}

// The analytic derivatives of the wavy flow against central finite differences of the velocity field.
TEST(StokesDrag, WavyFlowDerivativesMatchFiniteDifferences) {
  AmbientFlow flow = AmbientFlow::wavy_shear(0.7, 3.0, 2, 10.0);
  const double h = 1e-4;
  for (double y : {-3.0, 0.1, 4.2}) {
    const Vec3 x(0.3, y, 0.5), dy(0.0, h, 0.0);
    const double dudy = (flow.velocity(x + dy).x() - flow.velocity(x - dy).x()) / (2.0 * h);
    const double d2udy2 = (flow.velocity(x + dy).x() - 2.0 * flow.velocity(x).x() + flow.velocity(x - dy).x()) / (h * h);
    EXPECT_NEAR(flow.strain_rate(x)(0, 1), 0.5 * dudy, 1e-7);
    EXPECT_NEAR(flow.angular_velocity(x).z(), -0.5 * dudy, 1e-7);
    EXPECT_NEAR(flow.velocity_laplacian(x).x(), d2udy2, 1e-4);
    const double d2e = (flow.strain_rate(x + dy)(0, 1) - 2.0 * flow.strain_rate(x)(0, 1) + flow.strain_rate(x - dy)(0, 1)) / (h * h);
    EXPECT_NEAR(flow.strain_rate_laplacian(x)(0, 1), d2e, 1e-4);
  }
}

TEST(StokesDrag, FlowParametersAreValidated) {
  EXPECT_THROW((AmbientFlow::wavy_shear(1.0, 1.0, 1, 0.0).validate()), InputError);
  EXPECT_THROW((AmbientFlow::wavy_shear(1.0, 1.0, -1, 5.0).validate()), InputError);
  EXPECT_NO_THROW((AmbientFlow::wavy_shear(1.0, 20.0, 1, 5.0).validate()));
}

// The ambient flow is a velocity gradient L (core/ambient_flow.hpp): E = sym L, Omega = (1/2) curl (L x).
TEST(AmbientFlow, AnyVelocityGradientGivesItsStrainRateVorticityAndVelocity) {
  const AmbientFlow shear = AmbientFlow::simple_shear(2.0);
  EXPECT_TRUE(shear.velocity(Vec3(1.0, 3.0, 5.0)).isApprox(Vec3(6.0, 0.0, 0.0)));
  EXPECT_EQ(shear.strain_rate()(0, 1), 1.0);
  EXPECT_EQ(shear.angular_velocity(), Vec3(0.0, 0.0, -1.0));  // docs/units.md: Omega_z = -gammadot / 2
  EXPECT_EQ(shear.ambient_stress()(0, 1), 2.0);
  EXPECT_TRUE(shear.is_simple_shear());
  // Solid-body rotation at w about z, U = w e_z x r: no strain, Omega = w e_z.
  AmbientFlow rotation;
  rotation.gradient(0, 1) = -0.7;
  rotation.gradient(1, 0) = 0.7;
  const Vec3 x(0.3, -1.2, 2.0);
  EXPECT_TRUE(rotation.velocity(x).isApprox(Vec3(0.0, 0.0, 0.7).cross(x)));
  EXPECT_TRUE(rotation.strain_rate().isZero(1e-15));
  EXPECT_TRUE(rotation.angular_velocity().isApprox(Vec3(0.0, 0.0, 0.7)));
  EXPECT_FALSE(rotation.is_simple_shear());
  // Planar extension L = diag(r, -r, 0): E = L, no rotation.
  AmbientFlow extension;
  extension.gradient.diagonal() = Vec3(0.5, -0.5, 0.0);
  EXPECT_TRUE(extension.strain_rate().isApprox(extension.gradient));
  EXPECT_TRUE(extension.angular_velocity().isZero(0.0));
  EXPECT_FALSE(extension.is_simple_shear());
  // The wave adds U k cos(k y) to dU_x/dy at every point (paper 000 eq. 17).
  const AmbientFlow wavy = AmbientFlow::wavy_shear(1.0, 2.0, 1, 10.0);
  const double k = 2.0 * pi / 10.0, y = 1.7;
  EXPECT_NEAR(wavy.strain_rate(Vec3(0.0, y, 0.0))(0, 1), 0.5 * (1.0 + 2.0 * k * std::cos(k * y)), 1e-15);
  EXPECT_FALSE(wavy.is_simple_shear());
}
