#pragma once
/// \file
/// A loaded MaterialX document: its elements, by kind, in document order.

#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/common/Diagnostic.h"
#include "compiler/document/Elements.h"
#include "compiler/xml/XmlDocument.h"

namespace mxc::doc {

/// A MaterialX version, "major.minor", as numbers for comparison.
struct Version {
  int major = 0;
  int minor = 0;
  auto operator<=>(const Version&) const = default;
};
/// The version a `version` attribute names; nullopt when it is not "major.minor" (a patch
/// number, "1.38.7", is read and ignored).
std::optional<Version> parseVersion(std::string_view text);

/// One .mtlx file (MaterialX 1.38 or 1.39) as a model. Elements of included files stay in
/// their own Document; `includes` links them.
class Document {
 public:
  explicit Document(xml::Document xml);
  Document(const Document&) = delete;
  Document& operator=(const Document&) = delete;

  const SourceFile& source() const { return xml_.source(); }
  const std::string& path() const { return source().path(); }
  const xml::Document& xml() const { return xml_; }

  std::string_view version;     ///< as written ("1.39"); "" when absent
  /// The version the document is read as: `version`, or 1.39 when absent or malformed.
  Version versionNumber() const;
  std::string_view colorspace;  ///< document colour space
  std::string_view fileprefix;
  SourceLocation location;  ///< the <materialx> element

  std::vector<NodeDef> nodedefs;
  std::vector<NodeGraph> nodegraphs;
  std::vector<Node> nodes;  ///< document-level nodes, materials included
  /// The document is a node graph too (MaterialX 1.39, "Node Graph Elements": elements directly
  /// under <materialx> form its graph): its own interface inputs (for document-level nodes'
  /// `interfacename`), outputs and tokens.
  std::vector<Input> inputs;
  std::vector<Output> outputs;
  std::vector<Token> tokens;
  std::vector<Implementation> implementations;
  std::vector<TypeDef> typedefs;
  std::vector<GeomPropDef> geompropdefs;
  std::vector<UnitDef> unitdefs;
  std::vector<Look> looks;
  std::vector<Include> includes;
  /// MaterialX 1.37-and-older <material> elements, until upgradeTo138 turns them into nodes.
  std::vector<LegacyMaterial> legacyMaterials;
  /// Elements the model keeps but does not act on (geominfo, collection, propertyset, ...).
  std::vector<xml::Element> otherElements;
  /// Upgrades applied to bring an older document to 1.39, for reports.
  std::vector<std::string> upgradeNotes;

  const Node* findNode(std::string_view name) const;
  const NodeGraph* findNodeGraph(std::string_view name) const;
  const NodeDef* findNodeDef(std::string_view name) const;

  /// Keeps a string for the document's lifetime (names synthesised by upgrades).
  std::string_view own(std::string text);
  /// Sets the back-pointers (node -> graph, element -> document) after the element vectors
  /// have stopped changing; the builder and the upgrade call it.
  void link();

 private:
  xml::Document xml_;
  std::deque<std::string> owned_;
};

}  // namespace mxc::doc
