#pragma once
/// \file
/// The state of lowering one material: environments for graph scopes, memoised node results,
/// and the functions rules use to read a node's inputs as IR values or closures.

#include <deque>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/common/Diagnostic.h"
#include "compiler/ir/ExprBuilder.h"
#include "compiler/ir/Material.h"
#include "compiler/library/NodeLibrary.h"
#include "compiler/lower/Lowering.h"
#include "compiler/resolve/ResolvedGraph.h"

namespace mxc::lower {

/// A scope in which nodes are lowered: the document level, a document-level node graph, or
/// an inlined implementation graph bound to the node instance it implements.
struct Env {
  const resolve::ResolvedGraph* graph = nullptr;
  const resolve::ResolvedNode* caller = nullptr;  ///< the instance an implementation graph implements
  Env* callerEnv = nullptr;
  int depth = 0;  ///< inlining depth, bounded so a self-implementing graph cannot recurse forever
  std::map<std::pair<const resolve::ResolvedNode*, std::string>, ir::ExprId> values;
};

/// What a closure-typed output lowers to.
struct Closure {
  enum class Kind : uint8_t { None, Scatter, Medium, Emission };
  Kind kind = Kind::None;
  ir::Index index = ir::kNone;              ///< scatter node (Scatter) or medium (Medium)
  std::vector<ir::Index> emissions;         ///< Emission: the emitters whose sum it is
};

/// A node in the environment it is lowered in.
struct NodeRef {
  const resolve::ResolvedNode* node;
  Env* env;
};

class Context {
 public:
  Context(ir::Material& material, const resolve::ResolvedDocument& document, const LoweringOptions& options,
          Diagnostics& diagnostics);

  ir::Material& material;
  ir::ExprBuilder b;
  const resolve::ResolvedDocument& document;
  const lib::NodeLibrary& library;
  const LoweringOptions& options;
  Diagnostics& diagnostics;
  /// The material's shading node: the node `--set` and `--param` apply to (null for none).
  const resolve::ResolvedNode* shaderNode = nullptr;

  /// The environment of the document level and of each document-level node graph.
  Env& topEnv() { return top_; }
  Env& graphEnv(const resolve::ResolvedGraph& graph);

  // --- Values ---
  /// A node input as an IR value, lowering what it is connected to. kNoExpr when unset.
  ir::ExprId input(const NodeRef& n, std::string_view name);
  /// As input(), with the origin of the input for the IR's Param.
  ir::Param param(const NodeRef& n, std::string_view name);
  /// A uniform string or filename input's value ("" when unset or connected).
  std::string stringInput(const NodeRef& n, std::string_view name);
  /// The file an image node reads: its `file` input, found relative to the document's folder,
  /// else in the first of LoweringOptions::imageSearchPaths that has it (then that path); a
  /// file found nowhere keeps its value, and the renderer reports it missing.
  std::string imageFile(const NodeRef& n);
  /// A tile of a UDIM image set: its number (1001 + u + 10 v, for the tile [u, u+1] x [v, v+1])
  /// and its file.
  struct UdimTile {
    int number;
    std::string file;
  };
  /// The tiles of an image node whose `file` names a tile set with `<UDIM>` (1001, 1002, ...)
  /// or `<UVTILE>` (u1_v1, u2_v1, ...; MaterialX 1.39 "Filename Substitutions"): the files of
  /// the first folder that has any (the document's, then LoweringOptions::imageSearchPaths),
  /// by tile number. Empty when `file` names no tile set, or none of its tiles exists.
  std::vector<UdimTile> udimTiles(const NodeRef& n);
  /// The colour space of a filename input, following interface connections to where it is set
  /// ("" when none is given).
  std::string colorspace(const NodeRef& n, std::string_view name);
  /// `color` (a color3 or color4 in colour space `space`) in the working space
  /// (LoweringOptions::workingSpace): decoded, unless the device decodes it already (an
  /// sRGB-encoded texture read through an sRGB format), then taken to the working primaries;
  /// alpha is kept. A data space ("", none, raw) is left alone; an unknown one is reported once
  /// at `where` and used as it is. Constants fold, so a value costs nothing at run time.
  ir::ExprId toWorkingSpace(ir::ExprId color, std::string_view space, SourceLocation where,
                            bool decodedByDevice = false);
  /// The value feeding a resolved input (of a node, a graph interface, or a graph output).
  /// `interfaceOf`: the document-level graph whose interface input `input` is (--set and
  /// --param reach those as GRAPH.INPUT, or as INPUT when the shading node has no such input).
  ir::ExprId value(const resolve::ResolvedInput& input, Env& env, const resolve::ResolvedGraph* interfaceOf = nullptr);
  /// The output of a value-typed node.
  ir::ExprId nodeValue(const NodeRef& n, std::string_view output);
  /// The leaves (lib::StructType) of a struct-typed input: its literal, the struct a node graph
  /// passes along, else the typedef's member defaults (zero for a member without one).
  std::vector<ir::ExprId> structValue(const resolve::ResolvedInput& input, Env& env);
  /// Where an input of a node is set (its element, else the nodedef's), for Params and messages.
  ir::Origin origin(const NodeRef& n, std::string_view name) const;
  ir::Origin nodeOrigin(const NodeRef& n) const;
  /// The IR type of a node input or output (Float when it has none).
  ir::Type inputType(const NodeRef& n, std::string_view name) const;
  ir::Type outputType(const NodeRef& n, std::string_view output) const;

  // --- Closures ---
  Closure closureInput(const NodeRef& n, std::string_view name);
  Closure closure(const resolve::ResolvedInput& input, Env& env);
  Closure nodeClosure(const NodeRef& n, std::string_view output);

  // --- Messages ---
  void error(SourceLocation where, std::string message);
  /// An error at a node of a category no nodedef defines, once per node, when a material needs it.
  void reportUnknownCategory(const resolve::ResolvedNode& node);
  void note(ir::Origin where, std::string message);

  /// Runs the node graph implementing `n`'s nodedef, binding its interface to `n`'s inputs.
  /// Returns the environment of the inlined graph, or null when there is none.
  Env* inlineImplementation(const NodeRef& n);
  /// The output of an implementation graph, as a value or a closure.
  const resolve::ResolvedInput* implementationOutput(Env& env, std::string_view output);

 private:
  int depth_ = 0;                 ///< nodeValue calls on the stack: the path length from the shading node
  bool tooDeepReported_ = false;  ///< the stack limit is reported once per material
  std::set<std::string> reportedParameters_;  ///< --param inputs reported as connected
  std::set<std::string> reportedSpaces_;      ///< unknown colour spaces, reported once each
  std::set<const resolve::ResolvedNode*> reportedUnknown_;  ///< nodes of unknown categories, reported once each
  const resolve::ResolvedInput* interfaceInput(Env& env, std::string_view name, Env*& where);
  /// The value of a shading-node input with `--set` and `--param` applied; kNoExpr when neither
  /// names it.
  ir::ExprId userInput(const resolve::ResolvedInput& input, ir::ExprId documentValue);
  /// --set / --param on an interface input of a document-level graph.
  ir::ExprId graphInput(const resolve::ResolvedGraph& graph, const resolve::ResolvedInput& input, ir::ExprId documentValue);
  /// An input --set and --param may reach: the names they give it, the uniform it becomes when
  /// kept, and where an input that cannot be kept is reported.
  struct UserInput {
    std::string qualified;  ///< "GRAPH.INPUT" for a graph's interface input, else empty
    bool plainName = true;  ///< the input's own name reaches it too
    std::string id;         ///< the uniform ("p_base_color", "p_NG_BrickPattern_brick_color")
    std::string_view graph;  ///< the graph of an interface input, else empty
    SourceLocation errorAt;
    std::string_view connected;  ///< why a connected input cannot be a parameter, for the message
  };
  /// --set, --param, --param-all and --no-specialize on the input `in` whose document value is `v`.
  ir::ExprId applyUserInput(const resolve::ResolvedInput& in, ir::ExprId v, const UserInput& u);
  ir::ExprId applyChannels(ir::ExprId value, std::string_view channels, ir::Type to);

  Env top_;
  std::deque<Env> envs_;
  std::map<const resolve::ResolvedGraph*, Env*> graphEnvs_;
  std::map<std::pair<const resolve::ResolvedNode*, Env*>, Env*> inlined_;
  std::map<std::pair<const resolve::ResolvedNode*, Env*>, std::map<std::string, Closure>> closures_;
  std::map<const doc::NodeGraph*, std::unique_ptr<resolve::ResolvedGraph>> implementations_;
};

/// A value-node rule: lowers output `output` of node `n`, of IR type `type`.
using ValueRule = ir::ExprId (*)(Context& c, const NodeRef& n, std::string_view output, ir::Type type);
/// The rule for a value-node category, or null (stdlib categories: StdlibRules.cpp).
ValueRule findValueRule(std::string_view category);

/// A closure-node rule (pbrlib BSDF, EDF and VDF nodes: PbrlibRules.cpp).
using ClosureRule = Closure (*)(Context& c, const NodeRef& n, std::string_view output);
ClosureRule findClosureRule(std::string_view category);

/// mxc's lowering of the shading models from their specifications (OpenPbrLowering.cpp,
/// StandardSurfaceLowering.cpp); each returns the root of the material's scattering tree.
ir::Index lowerOpenPbrSurface(Context& c, const NodeRef& n);
ir::Index lowerStandardSurface(Context& c, const NodeRef& n);
ir::Index lowerUsdPreviewSurface(Context& c, const NodeRef& n);
ir::Index lowerGltfPbr(Context& c, const NodeRef& n);
ir::Index lowerDisneyPrincipled(Context& c, const NodeRef& n);

}  // namespace mxc::lower
