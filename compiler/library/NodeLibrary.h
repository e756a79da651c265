#pragma once
/// \file
/// The definitions a document resolves against: nodedefs, node-graph implementations,
/// typedefs, geometric-property and unit definitions.

#include <memory>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "compiler/common/Diagnostic.h"
#include "compiler/document/Document.h"
#include "compiler/library/StructType.h"

namespace mxc::lib {

/// A nodedef's inputs and outputs after `inherit` is applied: the inherited ports in the
/// ancestor's order, each replaced by the descendant's redeclaration, then the new ports.
struct Signature {
  std::vector<const doc::Input*> inputs;
  std::vector<const doc::Output*> outputs;

  const doc::Input* findInput(std::string_view name) const;
  const doc::Output* findOutput(std::string_view name) const;
  /// The output type of a single-output nodedef, or "multioutput".
  std::string_view outputType() const;
};

/// Definitions in layers. Each NodeLibrary is one layer over an optional parent: lookups try
/// this layer first, so a user's library shadows the built-in one by name and a document's
/// own definitions shadow both. A name defined twice within one layer is an error.
class NodeLibrary {
 public:
  explicit NodeLibrary(const NodeLibrary* parent = nullptr) : parent_(parent) {}
  NodeLibrary(const NodeLibrary&) = delete;
  NodeLibrary& operator=(const NodeLibrary&) = delete;

  /// Registers the definitions of a document (its nodes are not definitions and are ignored).
  void addDocument(const doc::Document& document, Diagnostics& diagnostics);
  /// Applies inheritance and binds implementations; reports what does not hold together.
  /// Call once after the last addDocument.
  void finalize(Diagnostics& diagnostics);

  const doc::NodeDef* findNodeDef(std::string_view name) const;
  /// Every visible nodedef of a category (a shadowed definition is not listed).
  std::vector<const doc::NodeDef*> nodeDefsFor(std::string_view category) const;
  /// True when some layer defines the category.
  bool hasCategory(std::string_view category) const;
  /// Every visible category, sorted (for suggestions in messages).
  std::vector<std::string_view> categories() const;
  /// The nodedefs without a `node` attribute (no category; found by name only), every layer's.
  std::vector<const doc::NodeDef*> nodeDefsWithoutCategory() const;
  const Signature& signature(const doc::NodeDef& nodedef) const;
  /// The node graph implementing a nodedef, or null (implemented in code, or not at all).
  const doc::NodeGraph* implementationGraph(const doc::NodeDef& nodedef) const;
  /// The nodedef a graph implements, through its `nodedef` attribute or an <implementation>.
  const doc::NodeDef* implementedNodeDef(const doc::NodeGraph& graph) const;
  /// The inline source code implementing a nodedef for `target` (an <implementation> with
  /// `sourcecode`), or null.
  const doc::Implementation* inlineImplementation(const doc::NodeDef& nodedef, std::string_view target) const;
  const doc::TypeDef* findTypeDef(std::string_view name) const;
  /// The struct type of a typedef with members, or null (a standard type, a typedef without
  /// members, or one whose members did not hold together: reported by finalize).
  const StructType* structType(std::string_view name) const;
  /// True for the specification's own types and for typedefs of any layer.
  bool isKnownType(std::string_view name) const;
  const doc::GeomPropDef* findGeomPropDef(std::string_view name) const;

  /// Number of nodedefs in this layer alone.
  size_t nodeDefCount() const { return nodedefs_.size(); }
  const std::vector<const doc::Document*>& documents() const { return documents_; }

 private:
  template <typename T>
  void define(std::unordered_map<std::string_view, const T*>& table, const T& item, std::string_view kind,
              Diagnostics& diagnostics);
  const Signature* findSignature(const doc::NodeDef& nodedef) const;
  /// Builds this layer's struct type `t` (and the struct types its members use); `building`
  /// holds the chain being built, to report a struct that contains itself.
  const StructType* buildStructType(const doc::TypeDef& t, std::vector<std::string_view>& building,
                                    Diagnostics& diagnostics);

  const NodeLibrary* parent_;
  std::vector<const doc::Document*> documents_;
  std::unordered_map<std::string_view, const doc::NodeDef*> nodedefs_;
  std::unordered_map<std::string_view, std::vector<const doc::NodeDef*>> byCategory_;
  std::vector<const doc::NodeDef*> withoutCategory_;
  std::unordered_map<std::string_view, const doc::NodeGraph*> graphs_;  // graphs with a name, for implementations
  std::unordered_map<std::string_view, const doc::NodeGraph*> implementations_;  // by nodedef name
  std::unordered_map<const doc::NodeGraph*, std::string_view> implemented_;       // graph -> nodedef name
  std::unordered_map<std::string_view, const doc::TypeDef*> typedefs_;
  std::unordered_map<std::string_view, const doc::GeomPropDef*> geomprops_;
  std::unordered_map<std::string_view, std::unique_ptr<StructType>> structs_;  // null: tried and failed
  std::unordered_map<std::string, const doc::Implementation*> inlineSources_;  // "nodedef|target"
  mutable std::unordered_map<const doc::NodeDef*, Signature> signatures_;
};

}  // namespace mxc::lib
