// Image files through the OpenImageIO module (runtime/ImageIO.h): what a render writes to EXR
// comes back as it was.

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <unistd.h>

#include "runtime/ImageIO.h"

namespace mxc::rt {
namespace {

// Radiance above half's largest value (65504: an emitter, a firefly) and below its smallest
// normal one stays what it is: the EXR holds 32-bit floats, not Inf or 0.
TEST(ImageIO, ExrKeepsEveryFiniteFloat) {
  RgbaImage image;
  image.width = 3;
  image.height = 2;
  image.pixels = {1e6f, 123456.7f, 65505.0f, 1.0f,  1e-8f, 0.5f, 3.0e38f, 0.25f,
                  0.0f, -2.0f,     7.0f,     0.75f, 1.0f,  2.0f, 3.0f,    1.0f,
                  std::numeric_limits<float>::min(), 65504.0f, 1e-30f, 0.0f, 4.0f, 5.0f, 6.0f, 1.0f};
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("mxc_imageio_" + std::to_string(::getpid()) + ".exr");
  ASSERT_FALSE(writeImage(path, image).has_value());
  auto read = readImage(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(std::holds_alternative<RgbaImage>(read)) << std::get<std::string>(read);
  const RgbaImage& back = std::get<RgbaImage>(read);
  ASSERT_EQ(back.width, image.width);
  ASSERT_EQ(back.height, image.height);
  ASSERT_EQ(back.pixels.size(), image.pixels.size());
  for (size_t i = 0; i < image.pixels.size(); ++i) EXPECT_EQ(back.pixels[i], image.pixels[i]) << "value " << i;
}

}  // namespace
}  // namespace mxc::rt
