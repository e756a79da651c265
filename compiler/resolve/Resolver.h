#pragma once
/// \file
/// Graph resolution: binding a document's nodes to nodedefs and its inputs to their sources.

#include <memory>

#include "compiler/common/Diagnostic.h"
#include "compiler/document/Document.h"
#include "compiler/library/NodeLibrary.h"
#include "compiler/resolve/ResolvedGraph.h"

namespace mxc::resolve {

/// Resolves a document (with what it includes) against a library. The document's own
/// definitions become a layer over the library. Every node gets its nodedef (NodeDefMatcher);
/// every input a source: `nodename`, `nodegraph` + `output`, `interfacename`, a value, or the
/// nodedef's default value or `defaultgeomprop`. Reported as errors at the offending element:
/// unknown categories, unknown inputs, type mismatches, dangling references, cycles.
ResolvedDocument resolveDocument(const doc::Document& document, const lib::NodeLibrary& library,
                                 Diagnostics& diagnostics);

/// Resolves one node graph of a library on its own, for example the graph that implements a
/// nodedef. Returns null when the graph has no name.
std::unique_ptr<ResolvedGraph> resolveImplementation(const doc::NodeGraph& graph, const lib::NodeLibrary& library,
                                                     Diagnostics& diagnostics);

}  // namespace mxc::resolve
