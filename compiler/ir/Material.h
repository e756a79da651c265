#pragma once
/// \file
/// One material in the IR: its expressions, its scattering tree, and what the passes found.

#include <string>
#include <vector>

#include "compiler/ir/Expr.h"
#include "compiler/ir/Features.h"
#include "compiler/ir/Scatter.h"

namespace mxc::ir {

/// A remark about the lowering a user should know: a structure that is not energy-bounded,
/// an approximation, an input that has no effect.
struct Note {
  std::string message;
  Origin origin;
};

/// A shader input the user keeps variable (`--param`): a uniform of the generated shader, read
/// by Op::Parameter expressions of the same name, with the input's value as its default.
struct Parameter {
  std::string name;          ///< the Op::Parameter payload (a GLSL identifier)
  Type type = Type::Float;
  std::vector<float> value;  ///< default, componentCount(type) floats (1 for Bool and Int)
  Origin origin;
  std::string graph;  ///< the document-level graph whose interface input it is; empty for the shading node's
};

/// An image file a material reads, with the input that names it (for errors about the file).
struct ImageFile {
  std::string path;  ///< as the document resolves it (fileprefix applied), as in Op::Texture
  Origin origin;     ///< the first `file` input that names it
};

/// An input of the shading node as the compilation sees it, for reports that say why an effect
/// is compiled in or left out (`inspect --effects`): its value and where it is set.
struct ShaderInput {
  enum class Source : uint8_t {
    Document,   ///< set in the document
    Default,    ///< the nodedef's default
    Override,   ///< `--set`
    Parameter,  ///< kept variable (`--param`, `--no-specialize`): any value in its UI range
    Connected,  ///< connected to a node graph, a node or a geometric property
  };
  std::string_view name;
  std::string_view type;    ///< its MaterialX type (color3, float, ...)
  Source source = Source::Default;
  std::string value;        ///< as written ("0.8, 0.8, 0.8"); empty when connected
  std::string range;        ///< the nodedef's UI range ("0 to 1"), empty when it declares none
  SourceLocation location;  ///< where it is set: the document's element, else the nodedef's input
};

/// An interface input of a document-level node graph that a material reads: `--set` and
/// `--param` reach it as GRAPH.INPUT, or as INPUT when the shading node has no input of that name.
struct GraphInput {
  std::string qualified;  ///< "NG_BrickPattern.brick_color"
  std::string name;       ///< "brick_color"
  std::string type;       ///< its MaterialX type
};

struct Material {
  std::string name;          ///< the material node's name (or a graph output's, for pbrlib graphs)
  std::string shader;        ///< the shading node's category (open_pbr_surface, standard_surface, surface)
  Origin origin;             ///< the shading node
  ExprGraph exprs;
  std::vector<Interface> interfaces;
  std::vector<Medium> media;
  std::vector<Emission> emissions;
  std::vector<ScatterNode> nodes;
  Index root = kNone;
  Param opacity;     ///< kept for transparent shadows; already part of the tree as Mix(Ambient, surface)
  Param thinWalled;  ///< bool: the surface is a two-sided sheet (OpenPBR "Thin-walled mode")
  Features features;  ///< computeFeatures after the passes (the compiler driver sets it)
  std::vector<Note> notes;
  std::vector<Parameter> parameters;
  std::vector<ImageFile> images;
  std::vector<ShaderInput> shaderInputs;  ///< every input of the shading node, in nodedef order
  std::vector<GraphInput> graphInputs;    ///< the document-level graphs' interface inputs it reads

  /// The shading node's input of this name, or null.
  const ShaderInput* shaderInput(std::string_view input) const {
    for (const ShaderInput& i : shaderInputs) {
      if (i.name == input) return &i;
    }
    return nullptr;
  }

  /// Records that an image node reads `path` (once per path).
  void addImage(const std::string& path, Origin from) {
    for (const ImageFile& i : images) {
      if (i.path == path) return;
    }
    images.push_back({path, from});
  }
  Index addNode(ScatterNode node) {
    nodes.push_back(std::move(node));
    return static_cast<Index>(nodes.size() - 1);
  }
  Index addInterface(Interface i) {
    interfaces.push_back(std::move(i));
    return static_cast<Index>(interfaces.size() - 1);
  }
  Index addMedium(Medium m) {
    media.push_back(std::move(m));
    return static_cast<Index>(media.size() - 1);
  }
  Index addEmission(Emission e) {
    emissions.push_back(std::move(e));
    return static_cast<Index>(emissions.size() - 1);
  }
  /// Convenience constructors of scattering nodes.
  Index slab(Index top, Index medium, Index base, Param coverage, Origin from);
  Index mix(Index a, Index b, Param weight, Origin from);
  Index leaf(ScatterKind kind, Origin from);
};

}  // namespace mxc::ir
