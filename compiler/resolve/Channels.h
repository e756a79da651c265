#pragma once
/// \file
/// MaterialX 1.38 channel swizzles on connections (the `channels` attribute).

#include <optional>
#include <string>
#include <string_view>

namespace mxc::resolve {

/// Checks a 1.38 swizzle: one channel per component of `toType` (float takes one), each a
/// channel of `fromType` (r, g, b, a for colours; x, y, z, w for vectors; r or x for a float)
/// or a constant 0 or 1. Returns why it is invalid, or nullopt when it is valid.
std::optional<std::string> checkChannels(std::string_view channels, std::string_view fromType, std::string_view toType);

}  // namespace mxc::resolve
