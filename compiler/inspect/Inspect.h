#pragma once
/// \file
/// Reports of a resolved document for `mxc inspect`: an indented text tree, JSON in the
/// documented schema (docs/inspect-json.md), and Graphviz DOT.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compiler/common/Diagnostic.h"
#include "compiler/library/LibraryStack.h"
#include "compiler/resolve/ResolvedGraph.h"

namespace mxc::inspect {

using LibraryInfo = lib::LibraryInfo;

/// Everything a report shows.
struct InspectInput {
  const resolve::ResolvedDocument& document;
  const Diagnostics& diagnostics;
  std::vector<LibraryInfo> libraries;
};

/// The materials, their shader nodes with every input (set, default, connected; with its
/// source line) as an indented tree, then the graphs and nodes no material reaches.
std::string inspectText(const InspectInput& input);
/// The same content as JSON text (indented by 2, without a final line break); schema
/// "mxc-inspect-1", described in docs/inspect-json.md.
/// `lossy` as jsonText's (compiler/common/JsonText.h).
std::string inspectJson(const InspectInput& input, bool* lossy = nullptr);
/// A Graphviz digraph: nodes, graphs as clusters, connections as edges labelled by input.
std::string inspectDot(const InspectInput& input);

/// A stable identifier of a node in reports: its name, prefixed by its graph ("NG/name").
std::string nodeId(const resolve::ResolvedNode& node);

}  // namespace mxc::inspect
