#include "compiler/resolve/Channels.h"

#include <fmt/format.h>

#include "compiler/document/Value.h"

namespace mxc::resolve {

std::optional<std::string> checkChannels(std::string_view channels, std::string_view fromType, std::string_view toType) {
  const doc::ValueType from = doc::valueTypeOf(fromType);
  const doc::ValueType to = doc::valueTypeOf(toType);
  const int fromCount = doc::componentCount(from);
  const int toCount = doc::componentCount(to);
  if (fromCount == 0 || fromCount > 4) return fmt::format("a {} has no channels to select", fromType);
  if (toCount == 0 || toCount > 4) return fmt::format("channels cannot make a {}", toType);
  if (static_cast<int>(channels.size()) != toCount) {
    return fmt::format("a {} needs {} channel{}, \"{}\" gives {}", toType, toCount, toCount == 1 ? "" : "s", channels,
                       channels.size());
  }
  const bool color = from == doc::ValueType::Color3 || from == doc::ValueType::Color4;
  const std::string_view names = fromCount == 1 ? (std::string_view("rx")) : color ? "rgba" : "xyzw";
  for (char c : channels) {
    if (c == '0' || c == '1') continue;
    const size_t index = fromCount == 1 ? (c == 'r' || c == 'x' ? 0 : std::string_view::npos) : names.find(c);
    if (index == std::string_view::npos || static_cast<int>(index) >= fromCount) {
      return fmt::format("'{}' is not a channel of a {}", c, fromType);
    }
  }
  return std::nullopt;
}

}  // namespace mxc::resolve
