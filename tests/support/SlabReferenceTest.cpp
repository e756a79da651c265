// The independent CPU slab walk (support/SlabReference.h) on its own, against closed forms that
// come from neither walk (support/ClosedForms.h; ../shared/reference/physics-notes.md): before
// it is the check of the shader walk (runtime/ReferenceAgreementTest.cpp), it is checked itself.

#include "support/SlabReference.h"

#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

namespace mxc::test::slab {
namespace {

constexpr int kWalks = 200000;

Vec view(double degrees) {
  const double t = degrees * kPi / 180.0;
  return {std::sin(t), 0.0, std::cos(t)};
}

Layer dielectric(double n, double alpha, Layer::Under under) {
  Layer l;
  l.top.kind = Interface::Kind::Dielectric;
  l.top.n = n;
  l.top.ax = l.top.ay = alpha;
  l.under = under;
  return l;
}

Layer lambert(double rho) {
  Layer l;
  l.top.kind = Interface::Kind::Lambert;
  l.top.albedo = rho;
  return l;
}

/// Within 4 standard errors and a slack.
void expectNear(double value, double expected, double error, double slack, const std::string& what) {
  EXPECT_NEAR(value, expected, 4.0 * error + slack) << what << " (standard error " << error << ")";
}

// Physics notes 2.3: a smooth dielectric reflects the Fresnel factor; what enters the clear bulk
// is transmitted.
TEST(SlabReference, SmoothDielectricReflectsFresnel) {
  const Stack s{{dielectric(1.5, 0.0, Layer::Under::ClearBulk)}, 1.0};
  for (double degrees : {0.0, 45.0, 80.0}) {
    const Albedo a = albedo(s, view(degrees), kWalks, 1);
    expectNear(a.reflected, closed::fresnel(std::cos(degrees * kPi / 180.0), 1.5), a.reflectedError, 0.0,
               fmt::format("{} degrees", degrees));
    expectNear(a.reflected + a.transmitted, 1.0, 0.0, 1e-12, "R + T");
  }
}

// Physics notes 2.1: a rough dielectric without absorption and a white rough metal lose nothing.
TEST(SlabReference, RoughInterfacesConserveEnergy) {
  Layer metal;
  metal.top.kind = Interface::Kind::F82;
  metal.top.f0 = 1.0;
  metal.top.ax = metal.top.ay = 0.6;
  for (const Stack& s : {Stack{{dielectric(1.5, 0.5, Layer::Under::ClearBulk)}, 1.0}, Stack{{metal}, 1.0}}) {
    const Albedo a = albedo(s, view(60), kWalks / 4, 2);
    EXPECT_NEAR(a.reflected + a.transmitted, 1.0, 1e-12);
    EXPECT_EQ(a.cut, 0.0);
  }
}

// Physics notes 2.9: a Lambertian under a smooth dielectric, the interfaced Lambertian.
TEST(SlabReference, LambertianUnderSmoothDielectricMatchesClosedForm) {
  const Stack s{{dielectric(1.5, 0.0, Layer::Under::Nothing), lambert(0.6)}, 1.0};
  for (double degrees : {0.0, 60.0}) {
    const Albedo a = albedo(s, view(degrees), kWalks, 3);
    expectNear(a.reflected, closed::interfacedLambertian(std::cos(degrees * kPi / 180.0), 0.6, 1.5), a.reflectedError,
               0.0, fmt::format("{} degrees", degrees));
  }
}

// Physics notes 2.9: a semi-infinite isotropic medium without an interface, Chandrasekhar; and
// with g = 0.6, the same albedo falls (forward scattering carries light deeper).
TEST(SlabReference, SemiInfiniteMediumMatchesChandrasekhar) {
  Layer medium;
  medium.under = Layer::Under::HalfSpace;
  medium.sigmaS = 0.9;
  medium.sigmaA = 0.1;
  const Stack s{{medium}, 1.0};
  for (double degrees : {0.0, 60.0}) {
    const Albedo a = albedo(s, view(degrees), kWalks, 4);
    expectNear(a.reflected, closed::semiInfiniteAlbedo(0.9, std::cos(degrees * kPi / 180.0)), a.reflectedError, 0.0,
               fmt::format("{} degrees", degrees));
  }
  medium.g = 0.6;
  const Albedo forward = albedo(Stack{{medium}, 1.0}, view(0), kWalks / 4, 5);
  EXPECT_LT(forward.reflected, closed::semiInfiniteAlbedo(0.9, 1.0) - 0.05);
}

// Beer-Lambert along the refracted path: an absorbing layer of optical depth tau under a smooth
// interface over a mirror reflects F + (1 - F)^2 T^2 / (1 - F T^2), T = exp(-tau / mu_t).
TEST(SlabReference, AbsorbingLayerFollowsBeerLambert) {
  Layer coat = dielectric(1.5, 0.0, Layer::Under::Finite);
  coat.sigmaA = 0.4;
  coat.thickness = 1.0;
  Layer mirror;
  mirror.top.kind = Interface::Kind::F82;
  mirror.top.f0 = 1.0;
  const Stack s{{coat, mirror}, 1.0};
  for (double degrees : {0.0, 50.0}) {
    const double mu = std::cos(degrees * kPi / 180.0), mut = std::sqrt(1.0 - (1.0 - mu * mu) / 2.25);
    const double f = closed::fresnel(mu, 1.5), t = std::exp(-0.4 / mut);
    const Albedo a = albedo(s, view(degrees), kWalks, 6);
    expectNear(a.reflected, f + (1.0 - f) * (1.0 - f) * t * t / (1.0 - f * t * t), a.reflectedError, 0.0,
               fmt::format("{} degrees", degrees));
  }
}

// OpenPBR "Fuzz": white fuzz transmits what it does not reflect, so over a white Lambertian
// nothing is lost; a coloured fuzz absorbs only in what it reflects, E (1 - colour).
TEST(SlabReference, FuzzConservesAndTintsOnlyItsReflection) {
  Layer fuzz;
  fuzz.top.kind = Interface::Kind::Fuzz;
  fuzz.top.roughness = 0.5;
  const Albedo white = albedo(Stack{{fuzz, lambert(1.0)}, 1.0}, view(70), kWalks / 4, 7);
  EXPECT_NEAR(white.reflected, 1.0, 1e-12);
  // Over a black base: only the fuzz's reflection, E(mu) times the colour.
  fuzz.top.albedo = 0.5;
  const Albedo alone = albedo(Stack{{fuzz, lambert(0.0)}, 1.0}, view(70), kWalks, 8);
  expectNear(alone.reflected, 0.5 * fuzzReflectance(std::cos(70.0 * kPi / 180.0), 0.5), alone.reflectedError, 0.0,
             "coloured fuzz over black");
}

}  // namespace
}  // namespace mxc::test::slab
