#pragma once
/// \file
/// An environment image on the device: the equirectangular radiance as a sampled image and its
/// sampling distribution (runtime/EnvironmentDistribution.h) as a storage buffer, bound as the
/// renderer's environment set (compiler/glsl/Contract.h, kEnvironmentSet).

#include <filesystem>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <glm/vec4.hpp>

#include "runtime/Descriptors.h"
#include "runtime/EnvironmentDistribution.h"
#include "runtime/ImageIO.h"

namespace mxc::rt {

class EnvironmentMap {
 public:
  /// Reads an equirectangular image (any format OpenImageIO reads, within the device's image
  /// size: larger ones are box-filtered down, a warning). Refused with a message naming the
  /// file: unreadable, not about twice as wide as high (1.8 to 2.2), or holding NaN or infinite
  /// values. Negative values are clamped to 0: the undershoot of lossy compression (studio.exr
  /// holds about 2000 of them, DWAB), not light.
  static std::variant<RgbaImage, std::string> read(const std::filesystem::path& path, uint32_t maxDimension,
                                                   std::vector<std::string>& warnings);

  /// Uploads `radiance` (linear RGB, top row first) and its distribution. An empty image is a
  /// black environment (1 x 1), which the renderer binds when no image is used.
  EnvironmentMap(VulkanContext& context, RgbaImage radiance);
  ~EnvironmentMap();
  EnvironmentMap(const EnvironmentMap&) = delete;
  EnvironmentMap& operator=(const EnvironmentMap&) = delete;

  const RgbaImage& radiance() const { return radiance_; }
  const EnvironmentDistribution& distribution() const { return distribution_; }
  /// The descriptor set: radiance at kEnvironmentRadianceBinding, distribution at
  /// kEnvironmentDistributionBinding.
  const DescriptorSet& set() const { return *set_; }

  /// `count` directions drawn on the device by the shaders' sampler (mxc_env_sample), with
  /// `seed`: per direction (map space xyz, the pdf it was drawn with) and the pdf mxc_env_pdf
  /// gives for it. For the test of the sampler against its density.
  struct Drawn {
    glm::vec4 sample;
    float pdf = 0.0f;
  };
  std::vector<Drawn> sample(uint32_t count, uint32_t seed) const;

 private:
  VulkanContext& context_;
  RgbaImage radiance_;
  EnvironmentDistribution distribution_;
  Image image_;
  Buffer buffer_;
  std::unique_ptr<DescriptorSet> set_;
};

}  // namespace mxc::rt
