#pragma once
/// \file
/// Loading node libraries: mxc's own (built in) and users' folders, as layers.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "compiler/common/Diagnostic.h"
#include "compiler/document/DocumentLoader.h"
#include "compiler/library/NodeLibrary.h"

namespace mxc::lib {

/// A node library in use, for reports: "builtin" or the folder given with --library, and how
/// many nodedefs the stack had once it was added.
struct LibraryInfo {
  std::string name;
  size_t nodedefs = 0;
};

/// The libraries a compilation resolves against. Each call adds a layer over the previous
/// ones, so later libraries shadow earlier definitions of the same name.
class LibraryStack {
 public:
  LibraryStack(SourceManager& sources, Diagnostics& diagnostics);

  /// mxc's own node library (the nodedefs/ folder of the source tree, compiled in).
  void addBuiltin();
  /// A library folder: every .mtlx file under it, recursively, in path order. A single
  /// .mtlx file is accepted too. Returns false (after reporting) when it cannot be read.
  bool addFolder(const std::filesystem::path& folder);

  /// The top layer, through which every layer is visible. Valid once a layer was added.
  const NodeLibrary& top() const;
  bool empty() const { return layers_.empty(); }

 private:
  NodeLibrary& newLayer();

  Diagnostics& diagnostics_;
  doc::DocumentLoader loader_;
  std::vector<std::unique_ptr<NodeLibrary>> layers_;
};

}  // namespace mxc::lib
