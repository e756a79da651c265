#include "compiler/lower/Context.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compiler/common/ColorSpace.h"
#include "compiler/common/LargeStack.h"
#include "compiler/common/Quote.h"
#include "compiler/lower/InlineSource.h"
#include "compiler/resolve/Resolver.h"

namespace mxc::lower {

using resolve::InputSource;
using resolve::ResolvedInput;

namespace {

bool isClosureType(std::string_view type) {
  return type == "BSDF" || type == "EDF" || type == "VDF" || type == "surfaceshader" || type == "volumeshader" ||
         type == "displacementshader" || type == "lightshader" || type == "material";
}

/// The zero of a type: what an unresolved or unsupported node contributes, so lowering can
/// go on and report every problem of the document.
ir::ExprId zero(ir::ExprBuilder& b, ir::Type type) {
  if (type == ir::Type::String) return b.graph().constant(doc::Value(doc::ValueType::String, std::string()));
  return b.vec(type, 0.0f);
}

}  // namespace

Context::Context(ir::Material& m, const resolve::ResolvedDocument& doc, const LoweringOptions& o, Diagnostics& d)
    : material(m), b(m.exprs), document(doc), library(*doc.definitions), options(o), diagnostics(d) {
  top_.graph = &doc.top;
}

Env& Context::graphEnv(const resolve::ResolvedGraph& graph) {
  if (auto it = graphEnvs_.find(&graph); it != graphEnvs_.end()) return *it->second;
  Env& env = envs_.emplace_back();
  env.graph = &graph;
  graphEnvs_.emplace(&graph, &env);
  return env;
}

void Context::error(SourceLocation where, std::string message) { diagnostics.error(where, std::move(message)); }

void Context::note(ir::Origin where, std::string message) {
  material.notes.push_back({std::move(message), where});
}

ir::Origin Context::origin(const NodeRef& n, std::string_view name) const {
  if (const ResolvedInput* in = n.node->findInput(name)) return {in->location, in->name};
  return nodeOrigin(n);
}

ir::Origin Context::nodeOrigin(const NodeRef& n) const { return {n.node->node->location, n.node->name()}; }

ir::Type Context::inputType(const NodeRef& n, std::string_view name) const {
  ir::Type type = ir::Type::Float;
  if (const ResolvedInput* in = n.node->findInput(name)) ir::irTypeOf(in->type, type);
  return type;
}

ir::Type Context::outputType(const NodeRef& n, std::string_view output) const {
  ir::Type type = ir::Type::Float;
  if (n.node->signature) {
    const doc::Output* out = output.empty() ? nullptr : n.node->signature->findOutput(output);
    if (!out && !n.node->signature->outputs.empty()) out = n.node->signature->outputs[0];
    if (out) ir::irTypeOf(out->type, type);
  }
  return type;
}

const ResolvedInput* Context::interfaceInput(Env& env, std::string_view name, Env*& where) {
  if (env.caller) {
    where = env.callerEnv;
    return env.caller->findInput(name);
  }
  if (env.graph && env.graph->graph) {
    // A document-level graph: its interface inputs are set at document level.
    where = &top_;
    return env.graph->findInterface(name);
  }
  return nullptr;
}

ir::ExprId Context::applyChannels(ir::ExprId value, std::string_view channels, ir::Type to) {
  // MaterialX 1.38 swizzle: each channel selects a component (r/x=0, g/y=1, b/z=2, a/w=3) or
  // is the constant 0 or 1. The resolver checked the channels against both types.
  std::vector<ir::ExprId> parts;
  const bool scalar = ir::componentCount(b.type(value)) <= 1;
  for (char c : channels) {
    if (c == '0' || c == '1') {
      parts.push_back(b.f(c == '1' ? 1.0f : 0.0f));
      continue;
    }
    const std::string_view names = "rgbaxyzw";
    const int index = static_cast<int>(names.find(c)) % 4;
    parts.push_back(scalar ? value : b.extract(value, index));
  }
  if (parts.size() == 1) return parts[0];
  return b.construct(to, parts);
}

ir::ExprId Context::value(const ResolvedInput& in, Env& env, const resolve::ResolvedGraph* interfaceOf) {
  ir::Type type = ir::Type::Float;
  const bool typed = ir::irTypeOf(in.type, type);
  if (!typed) return ir::kNoExpr;
  ir::ExprId v = ir::kNoExpr;
  switch (in.source) {
    case InputSource::Value:
    case InputSource::Default:
      if (in.value) v = material.exprs.constant(*in.value);
      break;
    case InputSource::GeomProp:
      v = material.exprs.named(ir::Op::GeomProp, type, in.geomprop);
      break;
    case InputSource::Connection:
      if (in.upstream.node) {
        v = nodeValue({in.upstream.node, &env}, in.upstream.output);
      } else if (in.upstream.graph) {
        Env& genv = graphEnv(*in.upstream.graph);
        if (const ResolvedInput* out = in.upstream.graph->findOutput(in.upstream.output)) v = value(*out, genv);
      }
      if (v != ir::kNoExpr && !in.channels.empty()) v = applyChannels(v, in.channels, type);
      break;
    case InputSource::Interface: {
      Env* where = nullptr;
      if (const ResolvedInput* iface = interfaceInput(env, in.interfaceName, where)) {
        // A document-level graph's interface input is one a user may --set or --param.
        const bool published = !env.caller && env.graph && env.graph->graph;
        v = value(*iface, *where, published ? env.graph : nullptr);
      }
      break;
    }
    case InputSource::Unset:
      break;
  }
  if (v == ir::kNoExpr && (in.source == InputSource::Connection || in.source == InputSource::Interface)) {
    // Connected to nothing that has a value (an unconnected graph output, reported by the
    // resolver): the input's default, else zero, so that every consumer gets a value.
    if (in.declaration && in.declaration->value) {
      v = material.exprs.constant(*in.declaration->value);
    } else {
      v = zero(b, type);
    }
  }
  if (shaderNode && &in >= shaderNode->inputs.data() && &in < shaderNode->inputs.data() + shaderNode->inputs.size()) {
    v = userInput(in, v);
  } else if (interfaceOf) {
    v = graphInput(*interfaceOf, in, v);
  }
  // A colour written as a value is in its element's colour space (MaterialX 1.39, "Color
  // Spaces": inherited from the enclosing elements); a --set or --param value stands in for it,
  // in the same space. Connected colours are converted where they were made.
  if (v != ir::kNoExpr && (in.source == InputSource::Value || in.source == InputSource::Default)) {
    const doc::Port* port = in.source == InputSource::Value ? in.instance : in.declaration;
    if (port && !port->colorspace.empty()) v = toWorkingSpace(v, port->colorspace, in.location);
  }
  return v;
}

ir::ExprId Context::userInput(const ResolvedInput& in, ir::ExprId v) {
  return applyUserInput(in, v,
                        {{}, true, "p_" + std::string(in.name), {}, shaderNode->node->location,
                         "the input is connected to a node graph"});
}

ir::ExprId Context::graphInput(const resolve::ResolvedGraph& graph, const ResolvedInput& in, ir::ExprId v) {
  const std::string qualified = fmt::format("{}.{}", graph.name(), in.name);
  bool recorded = false;
  for (const ir::GraphInput& g : material.graphInputs) recorded = recorded || g.qualified == qualified;
  if (!recorded) material.graphInputs.push_back({qualified, std::string(in.name), std::string(in.type)});
  // Unqualified, the name is the shading node's when it has an input of that name. The uniform's
  // name, p_GRAPH_INPUT, is a GLSL identifier (MaterialX names are letters, digits and '_').
  const bool shaderHasIt = shaderNode && shaderNode->findInput(in.name);
  return applyUserInput(in, v,
                        {qualified, !shaderHasIt, fmt::format("p_{}_{}", graph.name(), in.name), graph.name(),
                         in.location, "the graph's input is connected"});
}

ir::ExprId Context::applyUserInput(const ResolvedInput& in, ir::ExprId v, const UserInput& u) {
  auto names = [&](const std::string& name) {
    return (!u.qualified.empty() && name == u.qualified) || (u.plainName && name == in.name);
  };
  for (const auto& [name, text] : options.overrides) {
    if (!names(name)) continue;
    // A value that does not parse as the input's type is reported once for the whole run, at
    // the argument (lower::checkUserInputs); the document's value stays.
    if (std::optional<doc::Value> parsed = doc::tryParseValue(doc::valueTypeOf(in.type), text)) {
      v = material.exprs.constant(*parsed);
    }
  }
  bool variable = false;
  for (const std::string& name : options.parameters) variable = variable || names(name);
  if (variable && v != ir::kNoExpr && !material.exprs.isConstant(v)) {
    // Reported once per input, however often the lowering reads it.
    const std::string reported = u.qualified.empty() ? std::string(in.name) : u.qualified;
    if (reportedParameters_.insert(reported).second) {
      error(u.errorAt,
            fmt::format("--param {}: {}; only an input with a value can be a parameter", reported, u.connected));
    }
    variable = false;
  }
  // --param-all and --no-specialize: every input with a value, not a string (names,
  // enumerations, file names).
  if (options.everyInputVariable && v != ir::kNoExpr && material.exprs.isConstant(v) && b.type(v) != ir::Type::String) {
    variable = true;
  }
  if (!variable || v == ir::kNoExpr) return v;
  const ir::Type type = b.type(v);
  bool known = false;
  for (const ir::Parameter& p : material.parameters) known = known || p.name == u.id;
  if (!known) {
    material.parameters.push_back(
        {u.id, type, material.exprs.constantComponents(v), {in.location, in.name}, std::string(u.graph)});
  }
  return material.exprs.named(ir::Op::Parameter, type, u.id);
}

std::string Context::colorspace(const NodeRef& n, std::string_view name) {
  const ResolvedInput* in = n.node->findInput(name);
  Env* env = n.env;
  for (int depth = 0; in && depth < 64; ++depth) {  // interface chains are short; the bound stops a cycle
    if (in->instance && !in->instance->colorspace.empty()) return std::string(in->instance->colorspace);
    if (in->source != InputSource::Interface) break;
    Env* where = nullptr;
    in = interfaceInput(*env, in->interfaceName, where);
    env = where;
  }
  return {};
}

ir::ExprId Context::toWorkingSpace(ir::ExprId color, std::string_view space, SourceLocation where, bool decodedByDevice) {
  const ir::Type type = b.type(color);
  if (isDataSpace(space) || (type != ir::Type::Vec3 && type != ir::Type::Vec4)) return color;
  const ColorSpace* from = findColorSpace(space);
  if (!from) {
    if (reportedSpaces_.insert(std::string(space)).second) {
      diagnostics.warning(where, fmt::format("colorspace {} is not one mxc knows ({}); its colours are used as they are",
                                             quotedValue(space), fmt::join(colorSpaceNames(), ", ")));
    }
    return color;
  }
  // The options were checked by the driver; a library caller's unknown name falls back to the default.
  const ColorSpace* to = findColorSpace(options.workingSpace);
  if (!to || to->encoding != Encoding::Linear) to = findColorSpace("lin_rec709");
  ir::ExprId rgb = type == ir::Type::Vec4 ? b.construct(ir::Type::Vec3, {b.extract(color, 0), b.extract(color, 1), b.extract(color, 2)})
                                          : color;
  if (!decodedByDevice) {
    switch (from->encoding) {
      case Encoding::Linear:
        break;
      case Encoding::Srgb: {
        // IEC 61966-2-1 (MaterialX cmlib srgb_texture_to_lin_rec709): v / 12.92 up to 0.04045,
        // ((v + 0.055) / 1.055)^2.4 above; max(., 0) keeps the power's base non-negative on the
        // branch not taken (both are computed).
        ir::ExprId linear = b.div(rgb, b.f(12.92f));
        ir::ExprId curved = b.pow(b.max(b.div(b.add(rgb, b.f(0.055f)), b.f(1.055f)), b.f(0.0f)), b.f(2.4f));
        ir::ExprId above = b.binary(ir::Op::Step, b.vec(ir::Type::Vec3, 0.04045f), rgb);
        rgb = b.lerp(linear, curved, above);
        break;
      }
      case Encoding::Gamma:
        // max(v, 0)^gamma: a negative base has no real power (MaterialX's cmlib clamps so too).
        rgb = b.pow(b.max(rgb, b.f(0.0f)), b.f(from->gamma));
        break;
    }
  }
  if (from->primaries != to->primaries) {
    const glm::mat3 m = primariesConversion(from->primaries, to->primaries);
    std::vector<ir::ExprId> rows;
    for (int r = 0; r < 3; ++r) {
      rows.push_back(b.dot(material.exprs.constantVector(ir::Type::Vec3, {m[0][r], m[1][r], m[2][r]}), rgb));
    }
    rgb = b.construct(ir::Type::Vec3, rows);
  }
  if (type == ir::Type::Vec4) return b.construct(ir::Type::Vec4, {rgb, b.extract(color, 3)});
  return rgb;
}

ir::ExprId Context::input(const NodeRef& n, std::string_view name) {
  const ResolvedInput* in = n.node->findInput(name);
  return in ? value(*in, *n.env) : ir::kNoExpr;
}

ir::Param Context::param(const NodeRef& n, std::string_view name) { return {input(n, name), origin(n, name)}; }

std::string Context::stringInput(const NodeRef& n, std::string_view name) {
  const ResolvedInput* in = n.node->findInput(name);
  if (!in) return {};
  ir::ExprId v = value(*in, *n.env);
  if (v != ir::kNoExpr && material.exprs.isConstant(v) && material.exprs[v].type == ir::Type::String) {
    return material.exprs.constantValue(v).str();
  }
  return {};
}

std::string Context::imageFile(const NodeRef& n) {
  const std::string file = stringInput(n, "file");
  const std::filesystem::path path(file);
  if (file.empty() || path.is_absolute() || options.imageSearchPaths.empty()) return file;
  std::error_code ec;  // an unreadable folder is a folder without the file
  if (std::filesystem::exists(std::filesystem::path(document.document->path()).parent_path() / path, ec)) return file;
  for (const std::filesystem::path& folder : options.imageSearchPaths) {
    if (!std::filesystem::exists(folder / path, ec)) continue;
    // Absolute: later stages take a relative path as relative to the document's folder.
    const std::filesystem::path found = std::filesystem::absolute(folder / path, ec);
    return ec ? (folder / path).string() : found.string();
  }
  return file;
}

std::vector<Context::UdimTile> Context::udimTiles(const NodeRef& n) {
  namespace fs = std::filesystem;
  const std::string file = stringInput(n, "file");
  const bool udim = file.find("<UDIM>") != std::string::npos;
  const std::string token = udim ? "<UDIM>" : "<UVTILE>";
  const size_t at = file.find(token);
  if (at == std::string::npos) return {};
  const fs::path pattern(file);
  const std::string name = pattern.filename().string();
  const size_t nameAt = name.find(token);
  if (nameAt == std::string::npos) return {};  // a token in a folder name is not a tile set
  const std::string prefix = name.substr(0, nameAt);
  const std::string suffix = name.substr(nameAt + token.size());
  // The tile number a file name gives, or 0: <UDIM> is four digits 1001-9999; <UVTILE> is
  // u<U>_v<V>, both from 1 (MaterialX: the u index 1-10 and v index from 1).
  auto tileOf = [&](const std::string& entry) -> int {
    if (entry.size() <= prefix.size() + suffix.size() || entry.compare(0, prefix.size(), prefix) != 0 ||
        entry.compare(entry.size() - suffix.size(), suffix.size(), suffix) != 0) {
      return 0;
    }
    const std::string middle = entry.substr(prefix.size(), entry.size() - prefix.size() - suffix.size());
    if (udim) {
      if (middle.size() != 4 || middle.find_first_not_of("0123456789") != std::string::npos) return 0;
      const int number = std::stoi(middle);
      return number >= 1001 ? number : 0;
    }
    int u = 0, v = 0;
    char tail = 0;
    if (std::sscanf(middle.c_str(), "u%d_v%d%c", &u, &v, &tail) != 2 || u < 1 || u > 10 || v < 1 || v > 899) return 0;
    return 1000 + u + 10 * (v - 1);
  };
  std::vector<fs::path> folders;
  const fs::path relativeFolder = pattern.parent_path();
  if (pattern.is_absolute()) {
    folders.push_back(relativeFolder);
  } else {
    folders.push_back(fs::path(document.document->path()).parent_path() / relativeFolder);
    for (const fs::path& folder : options.imageSearchPaths) folders.push_back(folder / relativeFolder);
  }
  for (const fs::path& folder : folders) {
    std::error_code ec;  // an unreadable folder is a folder without tiles
    std::vector<UdimTile> tiles;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string entry = it->path().filename().string();
      if (int number = tileOf(entry)) {
        const fs::path found = fs::absolute(it->path(), ec);
        tiles.push_back({number, (ec ? it->path() : found).string()});
      }
    }
    if (!tiles.empty()) {
      std::sort(tiles.begin(), tiles.end(), [](const UdimTile& x, const UdimTile& y) { return x.number < y.number; });
      return tiles;
    }
  }
  return {};
}

ir::ExprId Context::nodeValue(const NodeRef& n, std::string_view output) {
  const auto key = std::make_pair(n.node, std::string(output));
  if (auto it = n.env->values.find(key); it != n.env->values.end()) return it->second;
  const ir::Type type = outputType(n, output);
  ir::ExprId v = ir::kNoExpr;
  // Lowering recurses along connections, about 600 bytes of frames per node on the path.
  // Keep a reserve for the rule that runs at the deepest point (a few frames); a graph deeper
  // than the stack (millions of nodes on one path on the CLI's 1 GiB stack, about ten
  // thousand on an 8 MiB main thread) stops here with an error.
  constexpr size_t kStackReserve = size_t{1} << 20;
  if (stackRemaining() < kStackReserve) {
    if (!tooDeepReported_) {
      error(n.node->node->location,
            fmt::format("node '{}' is {} connections away from the shading node: the graph is too deep to lower "
                        "(the compiler's stack is exhausted)",
                        n.node->name(), depth_));
      tooDeepReported_ = true;
    }
    return zero(b, type);
  }
  struct Depth {
    int& depth;
    explicit Depth(int& d) : depth(d) { ++depth; }
    ~Depth() { --depth; }
  } onPath(depth_);
  if (!n.node->nodedef) {
    reportUnknownCategory(*n.node);  // otherwise the resolver reported why
    v = zero(b, type);
  } else if (n.node->signature && isClosureType(n.node->signature->outputType())) {
    error(n.node->node->location, fmt::format("node '{}' outputs a {}, which cannot be used as a value",
                                              n.node->name(), n.node->signature->outputType()));
    v = zero(b, type);
  } else if (ValueRule rule = findValueRule(n.node->category())) {
    v = rule(*this, n, output, type);
  } else if (Env* inner = inlineImplementation(n)) {
    if (const ResolvedInput* out = implementationOutput(*inner, output)) v = value(*out, *inner);
  } else if (const doc::Implementation* source = library.inlineImplementation(*n.node->nodedef, "genglsl")) {
    v = lowerInlineSource(*this, n, *source, output, type);
  } else {
    error(n.node->node->location,
          fmt::format("<{}> (nodedef {}) is not supported by mxc's lowering yet, and no node graph or inline "
                      "source code in the libraries implements it",
                      n.node->category(), n.node->nodedef->name));
  }
  if (v == ir::kNoExpr) v = zero(b, type);
  n.env->values.emplace(key, v);
  return v;
}

std::vector<ir::ExprId> Context::structValue(const ResolvedInput& in, Env& env) {
  const lib::StructType* type = library.structType(in.type);
  if (!type) return {};
  std::vector<ir::ExprId> leaves;
  switch (in.source) {
    case InputSource::Value:
    case InputSource::Default:
      for (const doc::Value& leaf : in.structValue) leaves.push_back(material.exprs.constant(leaf));
      break;
    case InputSource::Connection:
      if (in.upstream.graph) {
        Env& genv = graphEnv(*in.upstream.graph);
        if (const ResolvedInput* out = in.upstream.graph->findOutput(in.upstream.output)) leaves = structValue(*out, genv);
      } else if (const resolve::ResolvedNode* node = in.upstream.node) {
        if (Env* inner = node->nodedef ? inlineImplementation({node, &env}) : nullptr) {
          if (const ResolvedInput* out = implementationOutput(*inner, in.upstream.output)) leaves = structValue(*out, *inner);
        } else if (node->nodedef) {
          error(node->node->location, fmt::format("<{}> '{}' outputs a {} struct, which mxc computes only through "
                                                  "node graphs (and reads as literals)",
                                                  node->category(), node->name(), in.type));
        }
      }
      break;
    case InputSource::Interface: {
      Env* where = nullptr;
      if (const ResolvedInput* iface = interfaceInput(env, in.interfaceName, where)) leaves = structValue(*iface, *where);
      break;
    }
    default:
      break;
  }
  if (leaves.size() == type->leaves.size()) return leaves;
  leaves.clear();
  for (const lib::StructType::Leaf& leaf : type->leaves) {
    ir::Type t = ir::Type::Float;
    if (leaf.defaultValue) {
      leaves.push_back(material.exprs.constant(*leaf.defaultValue));
    } else {
      ir::irTypeOf(doc::typeName(leaf.type), t);
      leaves.push_back(zero(b, t));
    }
  }
  return leaves;
}

Env* Context::inlineImplementation(const NodeRef& n) {
  if (!n.node->nodedef) return nullptr;
  const doc::NodeGraph* graph = library.implementationGraph(*n.node->nodedef);
  if (!graph) return nullptr;
  const auto key = std::make_pair(n.node, n.env);
  if (auto it = inlined_.find(key); it != inlined_.end()) return it->second;
  if (n.env->depth >= 32) {
    error(n.node->node->location, fmt::format("node graphs implementing <{}> nest more than 32 deep (a graph that "
                                              "uses its own node?)",
                                              n.node->category()));
    return nullptr;
  }
  auto& resolved = implementations_[graph];
  if (!resolved) resolved = resolve::resolveImplementation(*graph, library, diagnostics);
  if (!resolved) return nullptr;
  Env& env = envs_.emplace_back();
  env.graph = resolved.get();
  env.caller = n.node;
  env.callerEnv = n.env;
  env.depth = n.env->depth + 1;
  inlined_.emplace(key, &env);
  return &env;
}

const ResolvedInput* Context::implementationOutput(Env& env, std::string_view output) {
  const ResolvedInput* out = output.empty() ? nullptr : env.graph->findOutput(output);
  if (!out && !env.graph->outputs.empty()) out = &env.graph->outputs.front();
  return out;
}

Closure Context::closure(const ResolvedInput& in, Env& env) {
  switch (in.source) {
    case InputSource::Connection:
      if (in.upstream.node) return nodeClosure({in.upstream.node, &env}, in.upstream.output);
      if (in.upstream.graph) {
        Env& genv = graphEnv(*in.upstream.graph);
        if (const ResolvedInput* out = in.upstream.graph->findOutput(in.upstream.output)) return closure(*out, genv);
      }
      return {};
    case InputSource::Interface: {
      Env* where = nullptr;
      if (const ResolvedInput* iface = interfaceInput(env, in.interfaceName, where)) return closure(*iface, *where);
      return {};
    }
    default:
      return {};
  }
}

Closure Context::closureInput(const NodeRef& n, std::string_view name) {
  const ResolvedInput* in = n.node->findInput(name);
  return in ? closure(*in, *n.env) : Closure{};
}

void Context::reportUnknownCategory(const resolve::ResolvedNode& node) {
  // A node of a category no nodedef defines is read (MaterialX reads and validates it so, and
  // the resolver only warns): it is an error once something to compile depends on it.
  if (!library.nodeDefsFor(node.category()).empty()) return;
  if (!reportedUnknown_.insert(&node).second) return;
  error(node.node->location, fmt::format("node '{}' is a <{}>, which no nodedef defines: the material cannot be compiled "
                                         "without it",
                                         node.name(), node.category()));
}

Closure Context::nodeClosure(const NodeRef& n, std::string_view output) {
  auto& cache = closures_[std::make_pair(n.node, n.env)];
  if (auto it = cache.find(std::string(output)); it != cache.end()) return it->second;
  Closure result;
  if (!n.node->nodedef) {
    reportUnknownCategory(*n.node);  // otherwise the resolver reported why
  } else if (ClosureRule rule = findClosureRule(n.node->category())) {
    result = rule(*this, n, output);
  } else if (Env* inner = inlineImplementation(n)) {
    if (const ResolvedInput* out = implementationOutput(*inner, output)) result = closure(*out, *inner);
  } else {
    error(n.node->node->location,
          fmt::format("<{}> (nodedef {}) is not supported by mxc's lowering yet, and no node graph in the libraries "
                      "implements it",
                      n.node->category(), n.node->nodedef->name));
  }
  cache.emplace(std::string(output), result);
  return result;
}

}  // namespace mxc::lower
