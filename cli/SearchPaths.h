#pragma once
/// \file
/// MaterialX's search path: the folders where a document's resources (image files, meshes named
/// by `--mesh`) are looked for when they are not beside the document.

#include <filesystem>
#include <string>
#include <vector>

namespace mxc::cli {

/// The folders searched for resources: `--search-path` folders in order, then those of the
/// MATERIALX_SEARCH_PATH environment variable (separated by ':' or ';').
std::vector<std::filesystem::path> searchPaths(const std::vector<std::string>& fromOptions);

}  // namespace mxc::cli
