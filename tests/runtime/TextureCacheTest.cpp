// Textures on the device (runtime/TextureCache.h): one read per file and decoding, 8-bit files
// kept as 8 bits in the format that decodes them, and 8-bit sRGB code values that survive the
// read's decoding to linear and the upload's re-encoding.

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

#include "runtime/TextureCache.h"
#include "support/MaterialSupport.h"

namespace mxc::rt {
namespace {

namespace fs = std::filesystem;

fs::path tempImage(const std::string& name) {
  return fs::temp_directory_path() / ("mxc_texture_" + std::to_string(::getpid()) + "_" + name);
}

TEST(TextureCache, EachFileIsReadOnceWhileInUse) {
  VulkanContext& context = test::Device::get().context;
  const RgbaImage pixels{2, 2, {0.2f, 0.4f, 0.6f, 1.0f, 1.0f, 0.0f, 0.0f, 1.0f, 0.0f, 1.0f, 0.0f, 1.0f, 0.5f, 0.5f, 0.5f, 1.0f}};
  const fs::path png = tempImage("a.png"), exr = tempImage("a.exr");
  ASSERT_FALSE(writeImage(png, pixels, ToneMapping::None).has_value());
  ASSERT_FALSE(writeImage(exr, pixels).has_value());
  {
    TextureCache cache(context);
    auto srgb = cache.get(png, true);
    auto again = cache.get(png.parent_path() / "." / png.filename(), true);  // the same file, spelt otherwise
    EXPECT_EQ(srgb.get(), again.get());
    EXPECT_EQ(cache.reads(), 1u);
    auto raw = cache.get(png, false);  // other values: another texture
    EXPECT_NE(raw.get(), srgb.get());
    auto linear = cache.get(exr, false);
    EXPECT_EQ(cache.reads(), 3u);
    for (const auto* t : {srgb.get(), raw.get(), linear.get()}) EXPECT_TRUE(t->error().empty()) << t->error();
    // An 8-bit file stays 8 bits (a quarter of the memory of floats); an EXR stays float.
    EXPECT_EQ(srgb->image().format, VK_FORMAT_R8G8B8A8_SRGB);
    EXPECT_EQ(raw->image().format, VK_FORMAT_R8G8B8A8_UNORM);
    EXPECT_EQ(linear->image().format, VK_FORMAT_R32G32B32A32_SFLOAT);
    EXPECT_EQ(srgb->image().width, 2u);
    // Released by every holder, a texture is read again when asked for.
    srgb.reset();
    again.reset();
    auto reread = cache.get(png, true);
    EXPECT_EQ(cache.reads(), 4u);
    // A file that cannot be read is a texture with the reason, so each material can say it.
    auto missing = cache.get(tempImage("missing.png"), true);
    EXPECT_FALSE(missing->error().empty());
    EXPECT_EQ(missing->image().width, 1u);
  }
  fs::remove(png);
  fs::remove(exr);
}

// Every 8-bit sRGB code, decoded to linear as the read does and re-encoded for the upload,
// comes back as itself; alpha is stored without the sRGB curve.
TEST(TextureCache, EightBitSrgbCodesRoundTrip) {
  RgbaImage pixels{256, 1, std::vector<float>(256 * 4)};
  pixels.eightBit = true;
  for (int code = 0; code < 256; ++code) {
    for (int c = 0; c < 3; ++c) pixels.pixels[code * 4 + c] = srgbToLinear(float(code) / 255.0f);
    pixels.pixels[code * 4 + 3] = float(code) / 255.0f;
  }
  const std::vector<uint8_t> texels = eightBitTexels(pixels, true);
  for (int code = 0; code < 256; ++code) {
    for (int c = 0; c < 4; ++c) ASSERT_EQ(int(texels[code * 4 + c]), code) << "channel " << c;
  }
}

// An 8-bit file read as its code values (what a texture uploads) holds what the float read
// holds: the same codes, and, decoded, the same linear values.
TEST(TextureCache, EightBitTexelsAreTheFloatReadsCodes) {
  RgbaImage pixels{5, 1, {}};
  for (float v : {0.0f, 0.1f, 0.5f, 0.73f, 1.0f}) pixels.pixels.insert(pixels.pixels.end(), {v, 1.0f - v, v * v, 1.0f});
  const fs::path png = tempImage("codes.png");
  ASSERT_FALSE(writeImage(png, pixels, ToneMapping::None).has_value());
  for (bool srgb : {false, true}) {
    ImageReadOptions options;
    options.srgbDecode = srgb;
    auto floats = readImage(png, options);
    options.eightBitTexels = true;
    auto codes = readImage(png, options);
    ASSERT_TRUE(std::holds_alternative<RgbaImage>(floats) && std::holds_alternative<RgbaImage>(codes));
    const RgbaImage& f = std::get<RgbaImage>(floats);
    const RgbaImage& c = std::get<RgbaImage>(codes);
    EXPECT_TRUE(c.pixels.empty());
    ASSERT_EQ(c.texels.size(), f.pixels.size());
    EXPECT_EQ(c.texels, eightBitTexels(f, srgb));
    const std::vector<float> decoded = floatTexels(c.texels, srgb);
    for (size_t i = 0; i < decoded.size(); ++i) EXPECT_NEAR(decoded[i], f.pixels[i], 1e-6f) << i << (srgb ? " srgb" : "");
  }
  fs::remove(png);
}

}  // namespace
}  // namespace mxc::rt
