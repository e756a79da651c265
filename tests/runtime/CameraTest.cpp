// The camera's default framing and its checks (runtime/Camera.h).

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "runtime/Camera.h"

namespace mxc::test {
namespace {

TEST(Camera, FramingTheUnitSphereIsTheDefaultView) {
  const rt::Camera framed = rt::frameBounds(rt::meshBounds(rt::makeSphere()), {0, 0, 1}, 45.0f, 1.0f);
  const rt::Camera plain;
  EXPECT_NEAR(glm::length(framed.eye - plain.eye), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(framed.target - plain.target), 0.0f, 1e-5f);
  EXPECT_FALSE(rt::cameraProblem(framed));
  // The clip planes hold the whole sphere.
  EXPECT_LT(framed.nearPlane, 3.4f - 1.0f);
  EXPECT_GT(framed.farPlane, 3.4f + 1.0f);
}

TEST(Camera, FramingScalesWithTheMeshAndTheNarrowerSide) {
  const rt::MeshBounds bounds{{1, 2, 3}, 10.0f};
  const rt::Camera square = rt::frameBounds(bounds, {0, 0, 2}, 45.0f, 1.0f);
  EXPECT_NEAR(glm::length(square.eye - bounds.center), 34.0f, 1e-3f);
  EXPECT_EQ(square.target, bounds.center);
  // Twice as tall as wide: the horizontal half-angle's tangent halves, the distance doubles.
  const rt::Camera portrait = rt::frameBounds(bounds, {0, 0, 1}, 45.0f, 0.5f);
  EXPECT_NEAR(glm::length(portrait.eye - bounds.center), 68.0f, 1e-2f);
  // Wider than tall: the vertical side decides, as for a square.
  const rt::Camera landscape = rt::frameBounds(bounds, {0, 0, 1}, 45.0f, 2.0f);
  EXPECT_NEAR(glm::length(landscape.eye - bounds.center), 34.0f, 1e-3f);
  // Looking straight down, up is not +y (it would be along the view).
  const rt::Camera above = rt::frameBounds(bounds, {0, 1, 0}, 45.0f, 1.0f);
  EXPECT_FALSE(rt::cameraProblem(above));
}

TEST(Camera, RefusesDegenerateCameras) {
  rt::Camera camera;
  camera.up = glm::vec3(0, 0, -2);  // along the view direction
  EXPECT_TRUE(rt::cameraProblem(camera));
  camera = rt::Camera{};
  camera.target = camera.eye;
  EXPECT_TRUE(rt::cameraProblem(camera));
  camera = rt::Camera{};
  camera.up = glm::vec3(0.0f);
  EXPECT_TRUE(rt::cameraProblem(camera));
  camera = rt::Camera{};
  camera.fovDegrees = 180.0f;
  EXPECT_TRUE(rt::cameraProblem(camera));
}

}  // namespace
}  // namespace mxc::test
