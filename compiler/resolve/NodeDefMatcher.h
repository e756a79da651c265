#pragma once
/// \file
/// Choosing the nodedef of a node instance.

#include "compiler/common/Diagnostic.h"
#include "compiler/document/Elements.h"
#include "compiler/library/NodeLibrary.h"

namespace mxc::resolve {

/// The nodedef of a node (MaterialX 1.39 "Node Definitions"): the one its `nodedef` attribute
/// names, else the single definition of its category whose output type equals the node's type
/// and which declares every input the node sets, with the same type; a `version` attribute
/// selects among versions, and otherwise the default version wins; among definitions that still
/// fit equally, the first declared wins (as in MaterialX). When none fits, the error says why,
/// naming the closest definition. Returns null after reporting an error.
const doc::NodeDef* matchNodeDef(const doc::Node& node, const lib::NodeLibrary& library, Diagnostics& diagnostics);

}  // namespace mxc::resolve
