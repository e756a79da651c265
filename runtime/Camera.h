#pragma once
/// \file
/// The renderer's pinhole camera, and the framing that fits a mesh into the view by default.

#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "runtime/Mesh.h"

namespace mxc::rt {

struct Camera {
  glm::vec3 eye{0.0f, 0.0f, 3.4f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fovDegrees = 45.0f;  ///< vertical field of view
  float nearPlane = 0.05f;   ///< distances along the view direction; 0 < near < far
  float farPlane = 100.0f;
};

/// The camera that frames `bounds` from `direction` (from the mesh towards the eye; need not
/// be unit, must not be zero) with a vertical field of view `fovDegrees` in an image of
/// width/height `aspect`: looking at the centre, up +y (or -z when looking along y), at the
/// distance where the bounding sphere fills the same share of the narrower side as the unit
/// sphere at distance 3.4 under 45 degrees (so that camera is the unit sphere's framing), with
/// clip planes fitted to it (fitClipPlanes).
Camera frameBounds(const MeshBounds& bounds, glm::vec3 direction, float fovDegrees, float aspect);

/// Sets the near and far planes around `bounds` as seen from the camera's eye: near at half the
/// distance to the bounding sphere (or a ten-thousandth of the far plane from inside it), far
/// past the sphere's back.
void fitClipPlanes(Camera& camera, const MeshBounds& bounds);

/// Why a camera cannot render ("the eye is at the target", "up is along the view direction",
/// "the field of view must be in (0, 180) degrees"), or nullopt.
std::optional<std::string> cameraProblem(const Camera& camera);

}  // namespace mxc::rt
