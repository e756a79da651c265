// MikkTSpace-compatible tangents (runtime/Tangents.h): the direction of increasing u, summed
// over a vertex's corners weighted by angle, split at mirror seams.

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "runtime/Tangents.h"

namespace mxc::test {
namespace {

using rt::Mesh;
using rt::Vertex;

Vertex vertex(glm::vec3 p, glm::vec2 uv, glm::vec3 n = {0, 0, 1}) { return Vertex{p, n, glm::vec4(0.0f), uv}; }

TEST(Tangents, FollowIncreasingUOnAPlanarMapping) {
  // A quad whose u runs along (1, 1, 0) / sqrt 2 and v along (-1, 1, 0) / sqrt 2.
  Mesh mesh;
  const glm::vec3 du = glm::normalize(glm::vec3(1, 1, 0)), dv = glm::normalize(glm::vec3(-1, 1, 0));
  for (glm::vec2 uv : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)}) {
    mesh.vertices.push_back(vertex(uv.x * du + uv.y * dv, uv));
  }
  mesh.indices = {0, 1, 2, 0, 2, 3};
  rt::generateTangents(mesh);
  ASSERT_EQ(mesh.vertices.size(), 4u);  // nothing to split
  for (const Vertex& v : mesh.vertices) {
    EXPECT_NEAR(glm::dot(glm::vec3(v.tangent), du), 1.0f, 1e-6f);
    EXPECT_EQ(v.tangent.w, 1.0f);  // w * cross(n, t) = +dv: along increasing v
  }
}

TEST(Tangents, WeighACornerByItsAngle) {
  // Two triangles meet at the origin: A spans 90 degrees there with tangent +x, B spans 135
  // degrees with tangent +y; both have the same area (1/2). MikkTSpace weighs by angle:
  // (pi/2) x + (3 pi/4) y, along (2, 3, 0). Area weights or none would give (1, 1, 0).
  Mesh mesh;
  mesh.vertices = {vertex({0, 0, 0}, {0, 0}), vertex({1, 0, 0}, {1, 0}), vertex({0, 1, 0}, {0, 1}),
                   vertex({0, 1, 0}, {1, 0}), vertex({-1, -1, 0}, {0, 1})};
  mesh.indices = {0, 1, 2, 0, 3, 4};
  rt::generateTangents(mesh);
  const glm::vec3 expected = glm::normalize(glm::vec3(2, 3, 0));
  EXPECT_NEAR(glm::dot(glm::vec3(mesh.vertices[0].tangent), expected), 1.0f, 1e-6f);
  EXPECT_NEAR(mesh.vertices[1].tangent.x, 1.0f, 1e-6f);  // only A's
  EXPECT_NEAR(mesh.vertices[4].tangent.y, 1.0f, 1e-6f);  // only B's
}

TEST(Tangents, SplitAMirrorSeam) {
  // Two quads side by side sharing the edge x = 1, their u mirrored about it (u = 1 - |x - 1|):
  // the seam's vertices get w = +1 on the left and w = -1 on the right, so they split.
  Mesh mesh;
  for (float x : {0.0f, 1.0f, 2.0f}) {
    for (float y : {0.0f, 1.0f}) mesh.vertices.push_back(vertex({x, y, 0}, {1.0f - std::abs(x - 1.0f), y}));
  }
  // Vertex index = 2 * column + row.
  mesh.indices = {0, 2, 3, 0, 3, 1, 2, 4, 5, 2, 5, 3};
  rt::generateTangents(mesh);
  EXPECT_EQ(mesh.vertices.size(), 8u);  // the two seam vertices split
  for (size_t t = 0; t < 4; ++t) {
    const bool right = t >= 2;
    for (int k = 0; k < 3; ++k) {
      const Vertex& v = mesh.vertices[mesh.indices[3 * t + k]];
      EXPECT_EQ(v.tangent.w, right ? -1.0f : 1.0f) << "triangle " << t;
      // u increases towards the seam from both sides.
      EXPECT_NEAR(v.tangent.x, right ? -1.0f : 1.0f, 1e-6f) << "triangle " << t;
    }
  }
}

TEST(Tangents, MatchTheSphereAnalyticFrame) {
  // The UV sphere's tangents are d/du in closed form; MikkTSpace on the same mesh agrees away
  // from the poles (where u degenerates) and from the u = 0/1 seam it keeps (its vertices are
  // distinct there, with identical tangents).
  const Mesh analytic = rt::makeSphere(64, 32);
  Mesh computed = analytic;
  rt::generateTangents(computed);
  ASSERT_EQ(computed.vertices.size(), analytic.vertices.size());
  for (size_t v = 0; v < analytic.vertices.size(); ++v) {
    if (std::abs(analytic.vertices[v].position.y) > 0.9f) continue;  // the chords turn fastest near the poles
    EXPECT_GT(glm::dot(glm::vec3(computed.vertices[v].tangent), glm::vec3(analytic.vertices[v].tangent)), 0.999f) << v;
    EXPECT_EQ(computed.vertices[v].tangent.w, 1.0f);
  }
}

TEST(Tangents, GiveAFrameWhereThereIsNoMapping) {
  // All texture coordinates equal: no triangle has a mapping. Each vertex still gets a unit
  // tangent perpendicular to its normal.
  Mesh mesh;
  mesh.vertices = {vertex({0, 0, 0}, {0.5f, 0.5f}, {0, 1, 0}), vertex({1, 0, 0}, {0.5f, 0.5f}, {0, 1, 0}),
                   vertex({0, 0, -1}, {0.5f, 0.5f}, {0, 1, 0})};
  mesh.indices = {0, 1, 2};
  rt::generateTangents(mesh);
  for (const Vertex& v : mesh.vertices) {
    EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(glm::vec3(v.tangent), v.normal), 0.0f, 1e-6f);
    EXPECT_EQ(v.tangent.w, 1.0f);
  }
}

}  // namespace
}  // namespace mxc::test
