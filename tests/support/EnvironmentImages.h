#pragma once
/// \file
/// Synthetic environment images for the tests of runtime/EnvironmentDistribution and
/// runtime/EnvironmentMap.

#include <cstdint>
#include <vector>

#include "runtime/ImageIO.h"

namespace mxc::test {

/// A `width` x `width / 2` equirectangular image: a dim sky, brighter towards the ground, with
/// one bright patch of radiance `patch` up and to the left.
inline rt::RgbaImage patchImage(uint32_t width, float patch) {
  rt::RgbaImage image{width, width / 2, std::vector<float>(size_t{width} * (width / 2) * 4, 1.0f)};
  for (uint32_t y = 0; y < image.height; ++y) {
    for (uint32_t x = 0; x < image.width; ++x) {
      float* p = image.at(x, y);
      const float sky = 0.2f + 0.8f * float(y) / float(image.height);
      p[0] = sky, p[1] = 0.9f * sky, p[2] = 0.7f * sky;
      if (x >= width / 8 && x < width / 8 + width / 16 && y >= width / 16 && y < width / 16 + width / 32) {
        p[0] = p[1] = p[2] = patch;
      }
    }
  }
  return image;
}

}  // namespace mxc::test
