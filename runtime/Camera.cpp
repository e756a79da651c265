#include "runtime/Camera.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace mxc::rt {

namespace {

/// tan(22.5 degrees) times 3.4: the default sphere's framing, as a distance in radii for a
/// half-angle whose tangent is 1.
constexpr float kFramingDistance = 3.4f * 0.41421356f;

}  // namespace

Camera frameBounds(const MeshBounds& bounds, glm::vec3 direction, float fovDegrees, float aspect) {
  Camera camera;
  camera.fovDegrees = fovDegrees;
  const float length = glm::length(direction);
  const glm::vec3 toEye = length > 0.0f ? direction / length : glm::vec3(0, 0, 1);  // length checked
  // The narrower side decides: horizontally tan(half) is aspect times the vertical one.
  const float tanHalf = std::tan(glm::radians(0.5f * std::clamp(fovDegrees, 1e-3f, 179.0f))) * std::min(1.0f, aspect);
  const float radius = std::max(bounds.radius, 1e-6f);  // a mesh of one point still gets a view
  const float distance = kFramingDistance * radius / tanHalf;  // tanHalf > 0: the angle is in (0, 90) degrees
  camera.target = bounds.center;
  camera.eye = bounds.center + toEye * distance;
  camera.up = std::abs(toEye.y) > 0.999f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
  fitClipPlanes(camera, {bounds.center, radius});
  return camera;
}

void fitClipPlanes(Camera& camera, const MeshBounds& bounds) {
  const float distance = glm::length(camera.eye - bounds.center);
  const float radius = std::max(bounds.radius, 1e-6f);
  camera.farPlane = 1.5f * (distance + radius);  // > 0
  // In front of the sphere: half the gap, so nothing of the mesh is clipped; from inside it,
  // a fixed share of the far plane keeps the depth buffer's precision bounded.
  camera.nearPlane = std::max(0.5f * (distance - radius), 1e-4f * camera.farPlane);
}

std::optional<std::string> scaleProblem(const MeshBounds& bounds, const Camera& camera) {
  // Each component is compared before any length is taken: a length of 1e20 squares to inf.
  // Written so that NaN fails each test: a bound computed from an overflowed transform is NaN.
  auto largestComponent = [](glm::vec3 v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); };
  const float reach = largestComponent(bounds.center) + bounds.radius;
  if (!(std::isfinite(reach) && reach <= kLargestSceneRadius)) {
    const std::string size = std::isfinite(reach) ? fmt::format("reaches {:g} units from the origin", double(reach))
                                                  : std::string("overflows 32-bit floats (its transforms or its mesh)");
    return fmt::format("the scene {}, and mxc renders scenes within {:g} units of the origin (the shaders compute in "
                       "32-bit floats): scale it down",
                       size, double(kLargestSceneRadius));
  }
  if (!(bounds.radius >= kSmallestSceneRadius)) {
    return fmt::format("the scene's bounding sphere has a radius of {:g} units, and mxc renders radii of {:g} units and "
                       "more (the shaders compute in 32-bit floats): scale it up",
                       double(bounds.radius), double(kSmallestSceneRadius));
  }
  for (const auto& [point, name] : {std::pair{camera.eye, "position"}, std::pair{camera.target, "target"}}) {
    if (!(largestComponent(point) <= kLargestCameraDistance)) {
      return fmt::format("the camera's {} is {:g} units from the origin, and mxc renders within {:g} (the shaders "
                         "compute in 32-bit floats)",
                         name, double(largestComponent(point)), double(kLargestCameraDistance));
    }
  }
  return std::nullopt;
}

std::optional<std::string> cameraProblem(const Camera& camera) {
  const glm::vec3 view = camera.target - camera.eye;
  if (!(glm::length(view) > 1e-6f)) return "the camera position is at its target";
  if (!(glm::length(camera.up) > 1e-6f)) return "the camera's up vector is zero";
  // Normalised only after the checks above: both lengths are > 0.
  if (glm::length(glm::cross(glm::normalize(view), glm::normalize(camera.up))) < 1e-3f) {
    return "the camera's up vector is along its view direction";
  }
  if (!(camera.fovDegrees > 0.0f && camera.fovDegrees < 180.0f)) return "the field of view must be between 0 and 180 degrees";
  if (!(camera.nearPlane > 0.0f && camera.farPlane > camera.nearPlane)) return "the clip planes must satisfy 0 < near < far";
  return std::nullopt;
}

}  // namespace mxc::rt
