#pragma once
/// \file
/// An equirectangular environment image's sampling distribution: a grid of cells, equal in
/// longitude and latitude, each with a density per steradian proportional to the largest
/// luminance the bilinear lookup returns in it, drawn through an alias table. The renderer's shaders read it
/// (compiler/glsl/stages/mxc_environment.glsl, whose mapping and cell layout are the ones here);
/// built once per image, on the CPU, in time linear in its texels.

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "runtime/ImageIO.h"

namespace mxc::rt {

/// Map-space direction (unit, y up) to image coordinates in [0, 1]^2: u = 0.5 + atan(x, -z) /
/// (2 pi), v = acos(y) / pi. The image's centre lies along -z, u grows towards +x, the top row
/// looks up.
glm::vec2 equirectUv(const glm::vec3& direction);
/// The inverse of equirectUv: the unit direction at image coordinates (u, v).
glm::vec3 equirectDirection(const glm::vec2& uv);

/// World to map space for an image turned by `radians` about +y (counter-clockwise seen from
/// above), and back: as mxc_env_to_map and mxc_env_to_world.
glm::vec3 environmentToMap(const glm::vec3& world, float radians);
glm::vec3 environmentToWorld(const glm::vec3& map, float radians);

struct EnvironmentDistribution {
  uint32_t width = 1;   ///< cells across
  uint32_t height = 1;  ///< cells down
  /// Per cell, row by row: x the probability of keeping the cell when it is drawn, y its alias
  /// (uint bits), z its density per steradian, w 0. All densities are 0 for a black image.
  std::vector<glm::vec4> cells{glm::vec4(1.0f, 0.0f, 0.0f, 0.0f)};

  /// The distribution of `radiance` (RGBA, top row first; negative values count as 0), at the
  /// image's resolution or, for larger images, at most maxWidth x maxWidth / 2 cells, each
  /// weighted by the largest luminance of the texels whose centres it holds and their neighbours.
  static EnvironmentDistribution build(const RgbaImage& radiance, uint32_t maxWidth = 1024);

  /// The density per steradian of map-space direction `direction`.
  float pdf(const glm::vec3& direction) const;
  /// The solid angle of one cell in row `row`.
  double cellSolidAngle(uint32_t row) const;
  /// The bytes of the storage buffer the shaders read: uvec4 (width, height, 0, 0), then cells.
  std::vector<uint8_t> bufferBytes() const;
};

/// Radiance from map-space direction `direction` by bilinear interpolation, repeating across
/// and clamped down, as the renderer's sampler reads the image.
glm::vec3 equirectLookup(const RgbaImage& radiance, const glm::vec3& direction);

}  // namespace mxc::rt
