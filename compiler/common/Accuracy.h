#pragma once
/// \file
/// The accuracy tier of a compilation: how exactly the generated shader evaluates layering and
/// multiple scattering. One option of the compile request, read by the back end and visible to
/// the IR passes (PassContext); the IR itself does not change with it.

#include <cstdint>
#include <string_view>

namespace mxc {

enum class Accuracy : uint8_t {
  /// Albedo scaling through the slabs with tabulated single-scattering albedos, coat darkening
  /// and view-dependent absorption (OpenPBR "Reduction to a mixture of lobes").
  Balanced,
};

inline std::string_view accuracyName(Accuracy accuracy) {
  switch (accuracy) {
    case Accuracy::Balanced: return "balanced";
  }
  return "?";
}

}  // namespace mxc
