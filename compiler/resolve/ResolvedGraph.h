#pragma once
/// \file
/// The resolved graph: every node bound to its nodedef, every input to where its value comes
/// from (a written value, a default, a connection, the graph interface or a geometric
/// property), in dependency order. Later stages (lowering to the IR) read only this.

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "compiler/document/Document.h"
#include "compiler/library/NodeLibrary.h"

namespace mxc::resolve {

struct ResolvedGraph;
struct ResolvedNode;

/// Where an input's value comes from.
enum class InputSource : uint8_t {
  Value,       ///< a value written on the node (or on a graph's interface input)
  Default,     ///< the nodedef's default value
  Connection,  ///< an output of a node, or of a document-level node graph
  Interface,   ///< an input of the enclosing graph's interface
  GeomProp,    ///< a geometric property (the nodedef's defaultgeomprop)
  Unset,       ///< nothing: no value and no default (for example an empty BSDF input)
};

std::string_view inputSourceName(InputSource source);

/// The producing end of a connection: an output of a node, or of a document-level graph.
struct Upstream {
  const ResolvedNode* node = nullptr;
  const ResolvedGraph* graph = nullptr;
  std::string_view output;  ///< output name ("out" for single-output nodes)
  std::string_view type;    ///< type of that output
};

/// One input of a node (or of a graph interface, or a graph output's source), resolved.
struct ResolvedInput {
  std::string_view name;
  std::string_view type;
  InputSource source = InputSource::Unset;
  const doc::Input* declaration = nullptr;  ///< the nodedef's input (after inheritance); null for graph outputs
  const doc::Port* instance = nullptr;      ///< the element that set it, when one did
  std::optional<doc::Value> value;          ///< for Value and Default
  /// For Value and Default of a struct type: the literal's leaves (lib::StructType), and
  /// `value` is empty.
  std::vector<doc::Value> structValue;
  std::string_view geomprop;                ///< for GeomProp: a geompropdef name such as "Nworld"
  Upstream upstream;                        ///< for Connection
  std::string_view interfaceName;           ///< for Interface
  std::string_view channels;                ///< MaterialX 1.38 swizzle applied to the connection
  SourceLocation location;                  ///< where it is set: the instance, else the nodedef input

  /// The struct literal as written ("{0.1;0.5}"), for a struct value; "" otherwise.
  std::string_view structLiteral() const;
};

/// A node bound to its nodedef.
struct ResolvedNode {
  const doc::Node* node = nullptr;
  const doc::NodeDef* nodedef = nullptr;
  const lib::Signature* signature = nullptr;
  const ResolvedGraph* scope = nullptr;
  std::vector<ResolvedInput> inputs;  ///< every nodedef input, in nodedef order

  std::string_view name() const { return node->name; }
  std::string_view category() const { return node->category; }
  const ResolvedInput* findInput(std::string_view name) const;
};

/// A scope: a node graph, or the document level (graph == nullptr).
struct ResolvedGraph {
  const doc::NodeGraph* graph = nullptr;
  const doc::NodeDef* implements = nullptr;  ///< the nodedef this graph implements, if any
  std::vector<ResolvedInput> interface;      ///< interface inputs with their values
  std::vector<std::unique_ptr<ResolvedNode>> nodes;  ///< dependency order: producers first
  std::vector<ResolvedInput> outputs;                ///< graph outputs and what feeds them

  std::string_view name() const { return graph ? graph->name : std::string_view("(document)"); }
  const ResolvedNode* findNode(std::string_view name) const;
  const ResolvedInput* findInterface(std::string_view name) const;
  const ResolvedInput* findOutput(std::string_view name) const;
};

/// A material node and the shaders it binds.
struct ResolvedMaterial {
  struct Shader {
    std::string_view input;  ///< surfaceshader, displacementshader, ...
    const ResolvedNode* node = nullptr;
  };
  const ResolvedNode* node = nullptr;
  std::vector<Shader> shaders;
};

/// A whole document resolved against a library: its own definitions form a layer over the
/// library, and its nodes and graphs (those of included documents too) are bound.
/// Resolved nodes point at the graph that scopes them (`top` for document-level nodes), so a
/// ResolvedDocument must stay where it was built: initialise it from resolveDocument()'s result
/// (guaranteed copy elision), never move or copy it afterwards.
struct ResolvedDocument {
  const doc::Document* document = nullptr;
  std::vector<const doc::Document*> documents;  ///< the document and everything it includes
  std::unique_ptr<lib::NodeLibrary> definitions;
  ResolvedGraph top;  ///< document-level nodes
  std::vector<std::unique_ptr<ResolvedGraph>> graphs;
  std::vector<ResolvedMaterial> materials;

  const ResolvedGraph* findGraph(std::string_view name) const;
};

}  // namespace mxc::resolve
