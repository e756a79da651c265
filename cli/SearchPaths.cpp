#include "cli/SearchPaths.h"

#include <cstdlib>

namespace mxc::cli {

std::vector<std::filesystem::path> searchPaths(const std::vector<std::string>& fromOptions) {
  std::vector<std::filesystem::path> paths(fromOptions.begin(), fromOptions.end());
  if (const char* variable = std::getenv("MATERIALX_SEARCH_PATH")) {
    std::string part;
    for (const char* c = variable;; ++c) {
      if (*c == ':' || *c == ';' || *c == '\0') {
        if (!part.empty()) paths.emplace_back(part);
        part.clear();
        if (*c == '\0') break;
      } else {
        part += *c;
      }
    }
  }
  return paths;
}

}  // namespace mxc::cli
