#pragma once
/// \file
/// Builds the document model from a parsed XML tree.

#include <memory>

#include "compiler/common/Diagnostic.h"
#include "compiler/document/Document.h"
#include "compiler/xml/XmlDocument.h"

namespace mxc::doc {

/// Reads every element of a <materialx> tree into a Document: required attributes, valid and
/// unique names, typed values (a malformed value is reported at its line and column). Problems
/// go to `diagnostics`; the document is returned with what could be read.
std::unique_ptr<Document> buildDocument(xml::Document xml, Diagnostics& diagnostics);

}  // namespace mxc::doc
