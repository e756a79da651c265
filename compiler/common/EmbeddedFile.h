#pragma once
/// \file
/// Data files compiled into the binary (node libraries, shader library code); see cmake/EmbedFiles.cmake.

#include <span>
#include <string_view>

namespace mxc {

/// One embedded file: its path relative to the folder it was embedded from, and its bytes.
struct EmbeddedFile {
  std::string_view path;
  std::string_view contents;
};

}  // namespace mxc
