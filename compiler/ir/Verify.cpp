#include "compiler/ir/Verify.h"

#include <fmt/format.h>

namespace mxc::ir {

namespace {

constexpr Type kFloat[] = {Type::Float};
constexpr Type kVec2[] = {Type::Vec2};
constexpr Type kVec3[] = {Type::Vec3};
constexpr Type kBool[] = {Type::Bool};
/// A colour, or a grey level that scales one.
constexpr Type kColor[] = {Type::Vec3, Type::Float};

// The schemas: Scatter.h documents each slot's meaning; a kind holds only these.
constexpr SlotSpec kDielectric[] = {
    {Slot::Ior, kFloat},         {Slot::FresnelScale, kFloat},  {Slot::ReflectionTint, kVec3},
    {Slot::TransmissionTint, kVec3}, {Slot::Alpha, kVec2},      {Slot::Normal, kVec3},
    {Slot::Tangent, kVec3},      {Slot::AbbeNumber, kFloat},    {Slot::Darkening, kFloat},
    {Slot::BaseAlbedo, kVec3},   {Slot::BaseRoughness, kFloat}, {Slot::BaseIor, kFloat},
    {Slot::Weight, kColor},
};
constexpr SlotSpec kConductor[] = {
    {Slot::ComplexIor, kVec3}, {Slot::Extinction, kVec3}, {Slot::Alpha, kVec2},
    {Slot::Normal, kVec3},     {Slot::Tangent, kVec3},    {Slot::Weight, kColor},
};
constexpr SlotSpec kSchlick[] = {
    {Slot::F0, kVec3},     {Slot::F82, kVec3},          {Slot::F90, kVec3},   {Slot::Exponent, kFloat},
    {Slot::FresnelScale, kFloat}, {Slot::Alpha, kVec2}, {Slot::Normal, kVec3}, {Slot::Tangent, kVec3},
    {Slot::Weight, kColor},
};
constexpr SlotSpec kDiffuse[] = {
    {Slot::Color, kVec3}, {Slot::Roughness, kFloat}, {Slot::Normal, kVec3}, {Slot::Weight, kColor},
};
constexpr SlotSpec kSheen[] = {
    {Slot::Color, kVec3}, {Slot::Roughness, kFloat}, {Slot::Normal, kVec3}, {Slot::Weight, kColor}, {Slot::BaseAlbedo, kVec3},
};
constexpr SlotSpec kDiffuseTransmission[] = {
    {Slot::Color, kVec3}, {Slot::Normal, kVec3}, {Slot::Weight, kColor},
};
constexpr SlotSpec kDiffuseSheet[] = {
    {Slot::Color, kVec3},  {Slot::Anisotropy, kFloat}, {Slot::Roughness, kFloat},
    {Slot::Normal, kVec3}, {Slot::Weight, kColor},
};
constexpr SlotSpec kHair[] = {
    {Slot::Ior, kFloat},           {Slot::ReflectionTint, kVec3},    {Slot::TransmissionTint, kVec3},
    {Slot::InternalReflectionTint, kVec3}, {Slot::FibreRoughnessR, kVec2}, {Slot::FibreRoughnessTT, kVec2},
    {Slot::FibreRoughnessTRT, kVec2}, {Slot::CuticleTilt, kFloat},  {Slot::Absorption, kVec3},
    {Slot::Normal, kVec3},         {Slot::Tangent, kVec3},           {Slot::Weight, kColor},
};
constexpr SlotSpec kMedium[] = {
    {Slot::Absorption, kVec3},     {Slot::Scattering, kVec3}, {Slot::Anisotropy, kFloat}, {Slot::Thickness, kFloat},
    {Slot::ObservedAlbedo, kVec3}, {Slot::AbbeNumber, kFloat}, {Slot::Ior, kFloat},
};
constexpr SlotSpec kUniformEmission[] = {
    {Slot::Color, kVec3}, {Slot::Luminance, kFloat}, {Slot::F0, kVec3}, {Slot::F90, kVec3}, {Slot::Exponent, kFloat},
};
constexpr SlotSpec kConicalEmission[] = {
    {Slot::Color, kVec3},      {Slot::Luminance, kFloat},  {Slot::F0, kVec3},          {Slot::F90, kVec3},
    {Slot::Exponent, kFloat},  {Slot::Normal, kVec3},      {Slot::InnerAngle, kFloat}, {Slot::OuterAngle, kFloat},
};

class Verifier {
 public:
  explicit Verifier(const Material& m) : m_(m) {}

  std::vector<VerifyError> run() {
    expressions();
    // Table references of every node: passes rewrite references across all nodes.
    for (size_t i = 0; i < m_.nodes.size(); ++i) indices(static_cast<Index>(i));
    if (m_.root != kNone && !in(m_.root, m_.nodes.size(), VerifyRule::IndexInRange, "the root")) return errors_;
    // Entries no reachable node refers to are garbage that the dead-code pass sweeps; no pass
    // reads them (every pass walks from the root), so the other rules hold for what is reachable.
    std::vector<bool> interfaceSeen(m_.interfaces.size()), mediumSeen(m_.media.size()), emissionSeen(m_.emissions.size());
    for (Index i : reachable()) {
      const ScatterNode& n = m_.nodes[i];
      node(i);
      if (n.top < m_.interfaces.size() && !interfaceSeen[n.top]) {
        interfaceSeen[n.top] = true;
        interface(n.top);
      }
      if (n.medium < m_.media.size() && !mediumSeen[n.medium]) {
        mediumSeen[n.medium] = true;
        slots(m_.media[n.medium].slots, slotSchema(m_.media[n.medium]),
              fmt::format("medium {} ({})", n.medium, extentName(m_.media[n.medium].extent)));
      }
      if (n.emission < m_.emissions.size() && !emissionSeen[n.emission]) {
        emissionSeen[n.emission] = true;
        const Emission& e = m_.emissions[n.emission];
        slots(e.slots, slotSchema(e.kind),
              fmt::format("emission {} ({})", n.emission, e.kind == Emission::Kind::Conical ? "conical" : "uniform"));
      }
    }
    param(m_.opacity, kColor, "the opacity");
    param(m_.thinWalled, kBool, "thin_walled");
    return errors_;
  }

 private:
  void fail(VerifyRule rule, std::string message) { errors_.push_back({rule, std::move(message)}); }

  bool in(Index index, size_t size, VerifyRule rule, const std::string& what) {
    if (index < size) return true;
    fail(rule, fmt::format("{} refers to entry {} of a table of {}", what, index, size));
    return false;
  }

  void expressions() {
    for (ExprId id = 0; id < m_.exprs.size(); ++id) {
      for (ExprId a : m_.exprs.argsOf(id)) {
        if (a >= id) fail(VerifyRule::ExpressionInRange, fmt::format("expression %{} uses %{}, which does not come before it", id, a));
      }
    }
  }

  /// A present parameter refers to an expression of one of `types`.
  void param(const Param& p, std::span<const Type> types, const std::string& what) {
    if (!p.present()) return;
    if (!in(p.value, m_.exprs.size(), VerifyRule::ExpressionInRange, what)) return;
    const Type t = m_.exprs[p.value].type;
    for (Type allowed : types) {
      if (t == allowed) return;
    }
    fail(VerifyRule::ParamType, fmt::format("{} is a {}", what, typeName(t)));
  }

  void slots(const Slots& s, std::span<const SlotSpec> schema, const std::string& owner) {
    for (const auto& [slot, p] : s.all()) {
      const SlotSpec* spec = nullptr;
      for (const SlotSpec& candidate : schema) {
        if (candidate.slot == slot) spec = &candidate;
      }
      const std::string what = fmt::format("{} slot {}", owner, slotName(slot));
      if (!spec) {
        fail(VerifyRule::SlotAllowed, fmt::format("{} is not in the kind's schema", what));
        continue;
      }
      if (!p.present()) continue;
      if (!in(p.value, m_.exprs.size(), VerifyRule::ExpressionInRange, what)) continue;
      const Type t = m_.exprs[p.value].type;
      bool ok = false;
      for (Type allowed : spec->types) ok = ok || t == allowed;
      if (!ok) fail(VerifyRule::SlotType, fmt::format("{} is a {}", what, typeName(t)));
    }
  }

  void interface(Index i) {
    const Interface& f = m_.interfaces[i];
    slots(f.slots, slotSchema(f.kind), fmt::format("interface {} ({})", i, interfaceKindName(f.kind)));
    if (!f.thinFilm.present()) return;
    const std::string what = fmt::format("interface {}'s thin film", i);
    param(f.thinFilm.thickness, kFloat, what + " thickness");
    param(f.thinFilm.ior, kFloat, what + " ior");
    param(f.thinFilm.coverage, kFloat, what + " coverage");
  }

  /// The node's references point into their tables.
  void indices(Index i) {
    const ScatterNode& n = m_.nodes[i];
    const std::string what = fmt::format("node {} ({})", i, scatterKindName(n.kind));
    auto check = [&](Index ref, size_t size, const char* name) {
      if (ref != kNone) in(ref, size, VerifyRule::IndexInRange, fmt::format("{}'s {}", what, name));
    };
    check(n.top, m_.interfaces.size(), "interface");
    check(n.medium, m_.media.size(), "medium");
    check(n.base, m_.nodes.size(), "base");
    check(n.a, m_.nodes.size(), "a");
    check(n.b, m_.nodes.size(), "b");
    check(n.emission, m_.emissions.size(), "emission");
  }

  /// The node has what its kind uses and nothing else, with parameters of their types.
  void node(Index i) {
    const ScatterNode& n = m_.nodes[i];
    const std::string what = fmt::format("node {} ({})", i, scatterKindName(n.kind));
    auto has = [&](bool present, const char* name) {
      if (!present) fail(VerifyRule::NodeShape, fmt::format("{} has no {}", what, name));
    };
    auto none = [&](bool absent, const char* name) {
      if (!absent) fail(VerifyRule::NodeShape, fmt::format("{} has a {}, which its kind does not use", what, name));
    };
    const bool noSlab = n.top == kNone && n.medium == kNone && n.base == kNone;
    switch (n.kind) {
      case ScatterKind::Slab:
        has(n.top != kNone || n.medium != kNone, "interface or medium");
        param(n.coverage, kFloat, what + "'s coverage");
        none(n.a == kNone && n.b == kNone, "child a or b");
        none(!n.weight.present(), "weight");
        none(n.emission == kNone, "emission");
        break;
      case ScatterKind::Mix:
        has(n.a != kNone, "child a");
        has(n.b != kNone, "child b");
        has(n.weight.present(), "weight");
        param(n.weight, kColor, what + "'s weight");
        none(noSlab && n.emission == kNone, "slab part or emission");
        break;
      case ScatterKind::Add:
        has(n.a != kNone, "child a");
        has(n.b != kNone, "child b");
        none(!n.weight.present(), "weight");
        none(noSlab && n.emission == kNone, "slab part or emission");
        break;
      case ScatterKind::Tint:
        has(n.a != kNone, "child a");
        has(n.weight.present(), "colour");
        param(n.weight, kColor, what + "'s colour");
        none(n.b == kNone && noSlab && n.emission == kNone, "second child, slab part or emission");
        break;
      case ScatterKind::Emissive:
        has(n.a != kNone, "child a");
        has(n.emission != kNone, "emission");
        none(n.b == kNone && noSlab && !n.weight.present(), "second child, slab part or weight");
        break;
      case ScatterKind::Ambient:
      case ScatterKind::Absorber:
        none(n.a == kNone && n.b == kNone && noSlab && n.emission == kNone && !n.weight.present() &&
                 !n.coverage.present(),
             "child, slab part, emission or parameter");
        break;
    }
  }

  /// The nodes reachable from the root, each once; a cycle is reported (and not followed).
  std::vector<Index> reachable() {
    std::vector<Index> order;
    if (m_.root == kNone) return order;
    // Iterative depth-first search: 0 unseen, 1 on the current path, 2 done.
    std::vector<uint8_t> state(m_.nodes.size(), 0);
    std::vector<std::pair<Index, int>> stack{{m_.root, 0}};
    state[m_.root] = 1;
    order.push_back(m_.root);
    bool reported = false;
    while (!stack.empty()) {
      auto& [i, next] = stack.back();
      const ScatterNode& n = m_.nodes[i];
      const Index children[] = {n.base, n.a, n.b};
      if (next == 3) {
        state[i] = 2;
        stack.pop_back();
        continue;
      }
      const Index c = children[next++];
      if (c == kNone || c >= m_.nodes.size()) continue;
      if (state[c] == 1) {
        if (!reported) fail(VerifyRule::Acyclic, fmt::format("node {} is its own descendant", c));
        reported = true;
        continue;
      }
      if (state[c] == 0) {
        state[c] = 1;
        order.push_back(c);
        stack.push_back({c, 0});
      }
    }
    return order;
  }

  const Material& m_;
  std::vector<VerifyError> errors_;
};

}  // namespace

std::string_view verifyRuleName(VerifyRule rule) {
  switch (rule) {
    case VerifyRule::IndexInRange: return "index-in-range";
    case VerifyRule::ExpressionInRange: return "expression-in-range";
    case VerifyRule::NodeShape: return "node-shape";
    case VerifyRule::Acyclic: return "acyclic";
    case VerifyRule::SlotAllowed: return "slot-allowed";
    case VerifyRule::SlotType: return "slot-type";
    case VerifyRule::ParamType: return "param-type";
  }
  return "?";
}

std::span<const SlotSpec> slotSchema(InterfaceKind kind) {
  switch (kind) {
    case InterfaceKind::Dielectric: return kDielectric;
    case InterfaceKind::Conductor: return kConductor;
    case InterfaceKind::Schlick: return kSchlick;
    case InterfaceKind::Diffuse:
    case InterfaceKind::Burley: return kDiffuse;
    case InterfaceKind::Sheen: return kSheen;
    case InterfaceKind::DiffuseTransmission: return kDiffuseTransmission;
    case InterfaceKind::DiffuseSheet: return kDiffuseSheet;
    case InterfaceKind::Hair: return kHair;
  }
  return {};
}

std::span<const SlotSpec> slotSchema(const Medium&) { return kMedium; }

std::span<const SlotSpec> slotSchema(Emission::Kind kind) {
  return kind == Emission::Kind::Conical ? std::span<const SlotSpec>(kConicalEmission)
                                         : std::span<const SlotSpec>(kUniformEmission);
}

std::vector<VerifyError> verify(const Material& m) { return Verifier(m).run(); }

VerifyFailure::VerifyFailure(const std::string& stage, const Material& m, const std::vector<VerifyError>& errors)
    : std::logic_error([&] {
        std::string text = fmt::format("the IR of material '{}' is broken after {}:", m.name, stage);
        for (const VerifyError& e : errors) text += fmt::format("\n  {}: {}", verifyRuleName(e.rule), e.message);
        return text;
      }()) {}

}  // namespace mxc::ir
