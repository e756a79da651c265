#include "compiler/ir/Print.h"

#include <fmt/format.h>

#include "compiler/ir/Walk.h"

namespace mxc::ir {

namespace {

std::string componentsText(const std::vector<float>& c) {
  std::string out;
  for (size_t i = 0; i < c.size(); ++i) out += (i ? ", " : "") + doc::formatFloat(c[i]);
  return c.size() == 1 ? out : "(" + out + ")";
}

class TextPrinter {
 public:
  TextPrinter(const Material& m, const SourceFile* document) : m_(m), document_(document) {}

  std::string run();

 private:
  void line(int indent, const std::string& text) { out_ += std::string(static_cast<size_t>(indent), ' ') + text + "\n"; }
  std::string where(const Origin& o) const {
    if (!o.location.valid()) return o.input.empty() ? "" : std::string(o.input);
    std::string at = o.location.file == document_ ? fmt::format("line {}", o.location.line())
                                                  : fmt::format("{}:{}", o.location.file->path(), o.location.line());
    return o.input.empty() ? at : fmt::format("{} {}", o.input, at);
  }
  std::string param(const Param& p) const { return p.present() ? exprText(m_.exprs, p.value) : "-"; }
  std::string slots(const Slots& s) const {
    std::string out;
    for (const auto& [slot, p] : s.all()) out += fmt::format(" {}={}", slotName(slot), param(p));
    return out;
  }
  void node(Index i, int indent, const std::string& label);
  void interface(Index i, int indent);

  const Material& m_;
  const SourceFile* document_;
  std::string out_;
  std::vector<bool> shownInterfaces_;
};

void TextPrinter::interface(Index i, int indent) {
  const Interface& f = m_.interfaces[i];
  if (shownInterfaces_[i]) {
    line(indent, fmt::format("top: #{} (above)", i));
    return;
  }
  shownInterfaces_[i] = true;
  std::string kind(interfaceKindName(f.kind));
  if (f.kind == InterfaceKind::Dielectric || f.kind == InterfaceKind::Schlick) {
    kind += f.scatter == ScatterMode::R ? " R" : f.scatter == ScatterMode::T ? " T" : " RT";
  }
  if (f.kind == InterfaceKind::Diffuse) kind += f.diffuseModel == DiffuseModel::EON ? " eon" : " oren_nayar";
  if (f.kind == InterfaceKind::Sheen) kind += f.sheenModel == SheenModel::Zeltner ? " zeltner" : " conty_kulla";
  if ((f.kind == InterfaceKind::Dielectric || f.kind == InterfaceKind::Schlick) && f.iorReference == IorReference::Ambient) {
    kind += " ior:ambient";
  }
  line(indent, fmt::format("top: #{} {}{}  [{}]", i, kind, slots(f.slots), where(f.origin)));
  if (f.thinFilm.present()) {
    line(indent + 2, fmt::format("thin_film thickness={} ior={} coverage={}  [{}]", param(f.thinFilm.thickness),
                                 param(f.thinFilm.ior), f.thinFilm.coverage.present() ? param(f.thinFilm.coverage) : "1",
                                 where(f.thinFilm.thickness.origin)));
  }
}

void TextPrinter::node(Index i, int indent, const std::string& label) {
  const ScatterNode& n = m_.nodes[i];
  const std::string prefix = label.empty() ? "" : label + ": ";
  switch (n.kind) {
    case ScatterKind::Slab: {
      std::string coverage = n.coverage.present() ? fmt::format(" coverage={} [{}]", param(n.coverage), where(n.coverage.origin)) : "";
      line(indent, fmt::format("{}slab{}", prefix, coverage));
      if (n.top != kNone) interface(n.top, indent + 2);
      else line(indent + 2, "top: (index-matched)");
      if (n.medium != kNone) {
        const Medium& md = m_.media[n.medium];
        line(indent + 2, fmt::format("medium: {}{}  [{}]", extentName(md.extent), slots(md.slots), where(md.origin)));
      }
      if (n.base != kNone) node(n.base, indent + 2, "base");
      break;
    }
    case ScatterKind::Mix:
      line(indent, fmt::format("{}mix weight={} [{}]", prefix, param(n.weight), where(n.weight.origin)));
      node(n.a, indent + 2, "a");
      node(n.b, indent + 2, "b");
      break;
    case ScatterKind::Add:
      line(indent, fmt::format("{}add (not energy-bounded) [{}]", prefix, where(n.origin)));
      node(n.a, indent + 2, "a");
      node(n.b, indent + 2, "b");
      break;
    case ScatterKind::Tint:
      line(indent, fmt::format("{}tint color={} [{}]", prefix, param(n.weight), where(n.origin)));
      node(n.a, indent + 2, "a");
      break;
    case ScatterKind::Emissive: {
      const Emission& e = m_.emissions[n.emission];
      line(indent, fmt::format("{}emissive: {}{}  [{}]", prefix, e.kind == Emission::Kind::Uniform ? "uniform" : "conical",
                               slots(e.slots), where(e.origin)));
      node(n.a, indent + 2, "under");
      break;
    }
    case ScatterKind::Ambient: line(indent, prefix + "ambient"); break;
    case ScatterKind::Absorber: line(indent, prefix + "absorber"); break;
  }
}

std::string TextPrinter::run() {
  shownInterfaces_.assign(m_.interfaces.size(), false);
  line(0, fmt::format("material {} ({}{})", m_.name, m_.shader,
                      m_.origin.location.valid() ? ", " + where({m_.origin.location, {}}) : ""));
  std::vector<std::string> effects;
  m_.features.effects.forEach(
      [&](Effect e) { effects.push_back(fmt::format("{} ({})", effectName(e), where(m_.features.origin(e)))); });
  line(2, fmt::format("effects: {}", effects.empty() ? "(none)" : fmt::format("{}", fmt::join(effects, ", "))));
  for (const Note& n : m_.notes) line(2, fmt::format("note: {} [{}]", n.message, where(n.origin)));
  if (m_.root != kNone) node(m_.root, 2, "root");
  std::vector<bool> used(m_.exprs.size());
  Material& mutableM = const_cast<Material&>(m_);  // the walk takes a mutable material; nothing is written
  std::vector<ExprId> stack;
  forEachReachableParam(mutableM, [&](Param& p) {
    if (p.present()) stack.push_back(p.value);
  });
  while (!stack.empty()) {
    ExprId id = stack.back();
    stack.pop_back();
    if (used[id]) continue;
    used[id] = true;
    for (ExprId a : m_.exprs.argsOf(id)) stack.push_back(a);
  }
  bool header = false;
  for (ExprId id = 0; id < m_.exprs.size(); ++id) {
    const Expr& e = m_.exprs[id];
    if (!used[id] || e.op == Op::Constant) continue;
    if (!header) line(2, "expressions:"), header = true;
    std::vector<std::string> args;
    for (ExprId a : m_.exprs.argsOf(id)) args.push_back(exprText(m_.exprs, a));
    std::string payload;
    if (hasTextPayload(e.op)) payload = fmt::format(" \"{}\"", m_.exprs.text(id));
    else if (e.op == Op::Extract) payload = fmt::format(" [{}]", e.payload);
    line(4, fmt::format("%{} = {}{}{}{} : {}", id, opName(e.op), payload, args.empty() ? "" : " ",
                        fmt::join(args, ", "), typeName(e.type)));
  }
  return out_;
}

nlohmann::json locationJson(const SourceLocation& l) {
  if (!l.valid()) return nullptr;
  LineColumn lc = l.lineColumn();
  return {{"file", l.file->path()}, {"line", lc.line}, {"column", lc.column}};
}

nlohmann::json exprJsonValue(const ExprGraph& g, ExprId id) {
  if (g.isConstant(id)) {
    if (g[id].type == Type::String) return g.constantValue(id).str();
    std::vector<float> c = g.constantComponents(id);
    if (c.size() == 1) return c[0];
    return c;
  }
  return fmt::format("%{}", id);
}

nlohmann::json paramJson(const ExprGraph& g, const Param& p) {
  if (!p.present()) return nullptr;
  return {{"value", exprJsonValue(g, p.value)}, {"input", p.origin.input}, {"location", locationJson(p.origin.location)}};
}

nlohmann::json slotsJson(const ExprGraph& g, const Slots& s) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [slot, p] : s.all()) out[std::string(slotName(slot))] = paramJson(g, p);
  return out;
}

nlohmann::json nodeJson(const Material& m, Index i) {
  const ScatterNode& n = m.nodes[i];
  const ExprGraph& g = m.exprs;
  nlohmann::json j;
  switch (n.kind) {
    case ScatterKind::Slab: {
      j["kind"] = "slab";
      if (n.top != kNone) {
        const Interface& f = m.interfaces[n.top];
        nlohmann::json top{{"kind", "bsdf"}, {"id", n.top}, {"bsdf", interfaceKindName(f.kind)},
                           {"params", slotsJson(g, f.slots)}, {"location", locationJson(f.origin.location)}};
        if (f.kind == InterfaceKind::Dielectric || f.kind == InterfaceKind::Schlick) {
          top["scatter"] = f.scatter == ScatterMode::R ? "R" : f.scatter == ScatterMode::T ? "T" : "RT";
          top["ior_reference"] = f.iorReference == IorReference::Ambient ? "ambient" : "medium_above";
        }
        if (f.kind == InterfaceKind::Diffuse) top["model"] = f.diffuseModel == DiffuseModel::EON ? "eon" : "oren_nayar";
        if (f.kind == InterfaceKind::Sheen) top["model"] = f.sheenModel == SheenModel::Zeltner ? "zeltner" : "conty_kulla";
        if (f.thinFilm.present()) {
          top["thin_film"] = {{"thickness", paramJson(g, f.thinFilm.thickness)},
                              {"ior", paramJson(g, f.thinFilm.ior)},
                              {"coverage", paramJson(g, f.thinFilm.coverage)}};
        }
        j["top"] = top;
      } else {
        j["top"] = nullptr;
      }
      if (n.medium != kNone) {
        const Medium& md = m.media[n.medium];
        j["medium"] = {{"kind", "medium"}, {"id", n.medium}, {"extent", extentName(md.extent)},
                       {"params", slotsJson(g, md.slots)}, {"location", locationJson(md.origin.location)}};
      } else {
        j["medium"] = nullptr;
      }
      j["base"] = n.base != kNone ? nodeJson(m, n.base) : nlohmann::json(nullptr);
      j["coverage"] = paramJson(g, n.coverage);
      break;
    }
    case ScatterKind::Mix:
      j = {{"kind", "mix"}, {"a", nodeJson(m, n.a)}, {"b", nodeJson(m, n.b)}, {"weight", paramJson(g, n.weight)}};
      break;
    case ScatterKind::Add: j = {{"kind", "add"}, {"a", nodeJson(m, n.a)}, {"b", nodeJson(m, n.b)}}; break;
    case ScatterKind::Tint: j = {{"kind", "tint"}, {"a", nodeJson(m, n.a)}, {"color", paramJson(g, n.weight)}}; break;
    case ScatterKind::Emissive: {
      const Emission& e = m.emissions[n.emission];
      j = {{"kind", "emission"},
           {"edf", e.kind == Emission::Kind::Uniform ? "uniform" : "conical"},
           {"params", slotsJson(g, e.slots)},
           {"location", locationJson(e.origin.location)},
           {"under", nodeJson(m, n.a)}};
      break;
    }
    case ScatterKind::Ambient: j = {{"kind", "ambient"}}; break;
    case ScatterKind::Absorber: j = {{"kind", "absorber"}}; break;
  }
  return j;
}

}  // namespace

std::string exprText(const ExprGraph& g, ExprId id) {
  if (id == kNoExpr) return "-";
  if (g.isConstant(id)) {
    if (g[id].type == Type::String) return fmt::format("\"{}\"", g.constantValue(id).str());
    return componentsText(g.constantComponents(id));
  }
  return fmt::format("%{}", id);
}

namespace {

std::string signatureOf(const Material& m, Index i) {
  if (i == kNone) return "-";
  const ScatterNode& n = m.nodes[i];
  switch (n.kind) {
    case ScatterKind::Slab: {
      std::string top = "-";
      if (n.top != kNone) {
        const Interface& f = m.interfaces[n.top];
        top = std::string(interfaceKindName(f.kind));
        if (f.kind == InterfaceKind::Dielectric || f.kind == InterfaceKind::Schlick) {
          top += f.scatter == ScatterMode::R ? ":R" : f.scatter == ScatterMode::T ? ":T" : ":RT";
        }
        if (f.thinFilm.present()) top += "+film";
      }
      // A finite absorbing medium is a coat's tint: a value (coat_color, or a darkening factor
      // that MaterialX's graph folds into it), not structure; bulk and thin-wall media are.
      std::string medium = n.medium != kNone && m.media[n.medium].extent != Medium::Extent::Finite
                               ? std::string(extentName(m.media[n.medium].extent))
                               : "-";
      return fmt::format("slab({},{},{}{})", top, medium, signatureOf(m, n.base), n.coverage.present() ? ",cov" : "");
    }
    case ScatterKind::Mix: return fmt::format("mix({},{})", signatureOf(m, n.a), signatureOf(m, n.b));
    case ScatterKind::Add: return fmt::format("add({},{})", signatureOf(m, n.a), signatureOf(m, n.b));
    case ScatterKind::Tint: return fmt::format("tint({})", signatureOf(m, n.a));
    case ScatterKind::Emissive: return fmt::format("emissive({})", signatureOf(m, n.a));
    case ScatterKind::Ambient: return "ambient";
    case ScatterKind::Absorber: return "absorber";
  }
  return "?";
}

}  // namespace

std::string structureSignature(const Material& m) { return signatureOf(m, m.root); }

std::string printMaterial(const Material& m, const SourceFile* document) { return TextPrinter(m, document).run(); }

nlohmann::json materialJson(const Material& m) {
  nlohmann::json effects = nlohmann::json::array();
  m.features.effects.forEach([&](Effect e) {
    const Origin& origin = m.features.origin(e);
    effects.push_back({{"name", effectName(e)}, {"input", origin.input}, {"location", locationJson(origin.location)}});
  });
  nlohmann::json notes = nlohmann::json::array();
  for (const Note& n : m.notes) {
    notes.push_back({{"message", n.message}, {"input", n.origin.input}, {"location", locationJson(n.origin.location)}});
  }
  nlohmann::json expressions = nlohmann::json::array();
  for (ExprId id = 0; id < m.exprs.size(); ++id) {
    const Expr& e = m.exprs[id];
    if (e.op == Op::Constant) continue;
    nlohmann::json args = nlohmann::json::array();
    for (ExprId a : m.exprs.argsOf(id)) args.push_back(exprJsonValue(m.exprs, a));
    nlohmann::json x{{"id", fmt::format("%{}", id)}, {"op", opName(e.op)}, {"type", typeName(e.type)}, {"args", args}};
    if (hasTextPayload(e.op)) x["text"] = m.exprs.text(id);
    if (e.op == Op::Extract) x["component"] = e.payload;
    expressions.push_back(x);
  }
  return {{"name", m.name},
          {"shader", m.shader},
          {"location", locationJson(m.origin.location)},
          {"effects", effects},
          {"notes", notes},
          {"root", m.root != kNone ? nodeJson(m, m.root) : nlohmann::json(nullptr)},
          {"thin_walled", paramJson(m.exprs, m.thinWalled)},
          {"expressions", expressions}};
}

}  // namespace mxc::ir
