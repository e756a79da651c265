#pragma once
/// \file
/// The elements of a MaterialX document (MaterialX Specification 1.39, "MaterialX Document
/// Elements"): inputs and outputs, nodes, node definitions, node graphs, implementations,
/// type, geometric-property and unit definitions, and looks.
///
/// Strings are views into the owning Document (its XML text or its own storage). Each element
/// keeps its source position and, when it came from the XML, the raw element for attributes
/// the model does not name (ui*, doc, ...).

#include <optional>
#include <string_view>
#include <vector>

#include "compiler/common/SourceFile.h"
#include "compiler/document/Value.h"
#include "compiler/xml/XmlDocument.h"

namespace mxc::doc {

class Document;
struct NodeGraph;

/// An <input> or <output>: a typed port, with either a value or a connection.
struct Port {
  std::string_view name;
  std::string_view type;
  SourceLocation location;
  xml::Element element;  ///< invalid for elements an upgrade synthesised

  std::optional<std::string_view> valueString;  ///< the `value` attribute as written
  std::optional<Value> value;                   ///< parsed when the type has literal values
  SourceLocation valueLocation;                 ///< where the value text starts

  // Connections (MaterialX 1.39 "Inputs" / "Outputs").
  std::string_view nodename;       ///< a node in the same scope
  std::string_view nodegraph;      ///< a node graph at document level
  std::string_view output;         ///< which output of that node or graph
  std::string_view interfacename;  ///< an input of the enclosing graph's interface
  std::string_view channels;       ///< MaterialX 1.38 swizzle of the connected value ("r", "xxx", ...)

  std::string_view defaultgeomprop;  ///< nodedef inputs: geometric property used when unconnected
  std::string_view defaultinput;     ///< nodedef outputs: input passed through when the node is disabled
  std::string_view colorspace;       ///< effective colour space (inherited from enclosing elements)
  std::string_view fileprefix;       ///< effective file prefix for filename values
  std::string_view unit;
  std::string_view unittype;
  std::string_view enumNames;   ///< `enum`: the allowed values (or labels of `enumvalues`)
  std::string_view enumValues;  ///< `enumvalues`: values matching the labels of `enum`
  bool uniform = false;

  bool isConnected() const { return !nodename.empty() || !nodegraph.empty() || !interfacename.empty(); }
  /// Location of an attribute's value (falls back to the element's location).
  SourceLocation attributeLocation(std::string_view attribute) const;
};

struct Input : Port {};
struct Output : Port {};

/// A <token>: a named string substituted into filename values as [name].
struct Token {
  std::string_view name;
  std::string_view type;
  std::string_view value;
  SourceLocation location;
};

/// A node instance: an element whose name is a node category (<multiply>, <standard_surface>, ...).
struct Node {
  std::string_view category;
  std::string_view name;
  std::string_view type;     ///< output type, or "multioutput"
  std::string_view nodedef;  ///< explicit `nodedef` attribute
  std::string_view version;  ///< requested nodedef version
  SourceLocation location;
  xml::Element element;
  std::vector<Input> inputs;
  std::vector<Output> outputs;  ///< declared outputs of a multi-output node
  std::vector<Token> tokens;
  const NodeGraph* graph = nullptr;  ///< enclosing graph; null at document level
  const Document* document = nullptr;

  const Input* findInput(std::string_view name) const;
  Input* findInput(std::string_view name);
  SourceLocation attributeLocation(std::string_view attribute) const;
};

/// A <nodedef>: the interface of a node category for one signature.
struct NodeDef {
  std::string_view name;
  std::string_view node;  ///< the category it defines
  std::string_view nodegroup;
  std::string_view version;
  bool isDefaultVersion = false;
  std::string_view inherit;  ///< nodedef whose inputs this one extends
  std::string_view target;
  SourceLocation location;
  xml::Element element;
  std::vector<Input> inputs;
  std::vector<Output> outputs;
  std::vector<Token> tokens;
  const Document* document = nullptr;
  /// A MaterialX 1.36-and-older shader definition (`<shader>`, or a nodedef with `shadertype`):
  /// read to upgrade the materials that bind it, then removed, as MaterialX's upgrade does.
  bool legacyShader = false;

  const Input* findInput(std::string_view name) const;
  const Output* findOutput(std::string_view name) const;
};

/// A <shaderref> of a MaterialX 1.37-and-older <material>: the shader node the material binds,
/// with its inputs (<bindinput>, <bindparam>) and tokens (<bindtoken>).
struct ShaderRef {
  std::string_view name;
  std::string_view node;     ///< the shader's node category, when given
  std::string_view nodedef;  ///< the shader's nodedef, when given
  std::string_view type;     ///< surfaceshader, displacementshader, ...; empty when not given
  std::string_view version;
  std::string_view target;
  SourceLocation location;
  std::vector<Input> bindings;
  std::vector<Token> tokens;
};

/// A MaterialX 1.37-and-older <material> element. upgradeTo138 turns each into shader nodes and
/// a surfacematerial node, and empties Document::legacyMaterials.
struct LegacyMaterial {
  std::string_view name;
  SourceLocation location;
  std::vector<ShaderRef> shaderrefs;
  std::vector<Input> overrides;  ///< 1.35-and-older <override>s of the shader's public names
};

/// A <nodegraph>: nodes with an interface. With `nodedef` set, it implements that nodedef and
/// its interface is the nodedef's inputs.
struct NodeGraph {
  std::string_view name;
  std::string_view nodedef;
  SourceLocation location;
  xml::Element element;
  std::vector<Input> inputs;  ///< interface inputs declared on the graph itself
  std::vector<Output> outputs;
  std::vector<Node> nodes;
  std::vector<Token> tokens;
  const Document* document = nullptr;

  const Node* findNode(std::string_view name) const;
  Node* findNode(std::string_view name);
  const Input* findInput(std::string_view name) const;
  const Output* findOutput(std::string_view name) const;
};

/// An <implementation>: binds a nodedef to a node graph or to source code for a target.
struct Implementation {
  std::string_view name;
  std::string_view nodedef;
  std::string_view nodegraph;
  std::string_view file;
  std::string_view function;
  std::string_view target;
  /// Inline source code for `target` (MaterialX 1.39 "Implementation Elements"): an expression
  /// in which {{name}} stands for input `name`.
  std::string_view sourcecode;
  SourceLocation location;
};

/// A <typedef>: declares a type name (MaterialX "Custom Data Types"). A typedef with
/// <member>s is a struct; its values are written "{member;member;...}", nested for members
/// that are structs themselves.
struct TypeDef {
  struct Member {
    std::string_view name;
    std::string_view type;
    std::optional<std::string_view> valueString;  ///< the member's default, as written
    SourceLocation location;
  };
  std::string_view name;
  std::string_view semantic;
  std::string_view context;
  SourceLocation location;
  std::vector<Member> members;
};

/// A <geompropdef>: a named geometric property (Nworld, UV0, ...) that inputs can default to.
struct GeomPropDef {
  std::string_view name;
  std::string_view type;
  std::string_view geomprop;  ///< position, normal, tangent, bitangent, texcoord, geomcolor, ...
  std::string_view space;
  std::string_view index;
  SourceLocation location;
};

/// A <unitdef>: units of one unit type with their scales.
struct UnitDef {
  struct Unit {
    std::string_view name;
    float scale = 1.0f;
  };
  std::string_view name;
  std::string_view unittype;
  std::vector<Unit> units;
  SourceLocation location;
};

/// A <materialassign> inside a <look>: kept and reported, not acted on.
struct MaterialAssign {
  std::string_view name;
  std::string_view material;
  std::string_view geom;
  std::string_view collection;
  SourceLocation location;
};

/// A <look>: kept and reported, not acted on.
struct Look {
  std::string_view name;
  std::vector<MaterialAssign> assigns;
  SourceLocation location;
};

/// An <xi:include> of another document.
struct Include {
  std::string_view href;
  SourceLocation location;
  const Document* document = nullptr;  ///< the loaded document (set by the loader)
};

}  // namespace mxc::doc
