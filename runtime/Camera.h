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

/// The sizes a render takes, in world units: the scene's bounding radius, how far it reaches from
/// the origin, and the camera's distance from the origin. The shaders compute in 32-bit floats:
/// squared lengths of 1e20 overflow (FLT_MAX is 3.4e38), and below a radius of 1e-6 the
/// framing's floors and the shaders' offsets are larger than the scene; both rendered a blank
/// image. Measured on the framed unit sphere scaled by 1e-5 to 1e9: the image of the unit one
/// within 6e-5; from 1e10 its shading is wrong (0.49 at worst), from 1e20 and below 1e-7 blank.
constexpr float kSmallestSceneRadius = 1e-5f;
constexpr float kLargestSceneRadius = 1e9f;
constexpr float kLargestCameraDistance = 1e10f;

/// Why a scene of `bounds` seen by `camera` is outside those sizes (naming the size and the
/// range), or nullopt.
std::optional<std::string> scaleProblem(const MeshBounds& bounds, const Camera& camera);

/// Why a camera cannot render ("the eye is at the target", "up is along the view direction",
/// "the field of view must be in (0, 180) degrees"), or nullopt.
std::optional<std::string> cameraProblem(const Camera& camera);

}  // namespace mxc::rt
