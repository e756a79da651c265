#include "compiler/lower/ClosureAlgebra.h"

#include <fmt/format.h>

#include "compiler/lower/Layering.h"

namespace mxc::lower {

using ir::ExprId;
using ir::Index;

namespace {

Closure scatter(Index index) { return {Closure::Kind::Scatter, index, {}}; }

/// Scales the colour of every emitter (a copy of each).
Closure scaleEmission(Context& c, const Closure& edf, ExprId factor, const ir::Origin& origin) {
  Closure out{Closure::Kind::Emission, ir::kNone, {}};
  for (Index i : edf.emissions) {
    ir::Emission e = c.material.emissions[i];
    ir::Param* color = e.slots.find(ir::Slot::Color);
    if (color && color->present()) color->value = c.b.mul(color->value, factor);
    else e.slots.set(ir::Slot::Color, {factor, origin});
    out.emissions.push_back(c.material.addEmission(std::move(e)));
  }
  return out;
}

}  // namespace

Closure layerClosures(Context& c, const Closure& top, const Closure& base, const ir::Origin& origin) {
  if (top.kind != Closure::Kind::Scatter) return base;  // an empty top leaves the base
  if (base.kind == Closure::Kind::Medium) return scatter(attachMedium(c, top.index, base.index, origin));
  if (base.kind != Closure::Kind::Scatter) return top;
  return scatter(attachBase(c, top.index, base.index, origin));
}

Closure mixClosures(Context& c, const Closure& fg, const Closure& bg, const ir::Param& w, const ir::Origin& origin) {
  if (fg.kind == Closure::Kind::Emission || bg.kind == Closure::Kind::Emission) {
    Closure a = scaleEmission(c, bg, c.b.oneMinus(w.value), w.origin);
    Closure b = scaleEmission(c, fg, w.value, w.origin);
    a.emissions.insert(a.emissions.end(), b.emissions.begin(), b.emissions.end());
    return a;
  }
  if (fg.kind == Closure::Kind::Medium || bg.kind == Closure::Kind::Medium) {
    c.error(origin.location, "mixing volumes (VDFs) is not supported: mix the BSDFs that contain them");
    return bg;
  }
  // mix(fg, bg, w) = (1 - w) bg + w fg: Mix{a: bg, b: fg, weight: w}; an empty side is black.
  Index a = bg.kind == Closure::Kind::Scatter ? bg.index : c.material.leaf(ir::ScatterKind::Absorber, origin);
  Index b = fg.kind == Closure::Kind::Scatter ? fg.index : c.material.leaf(ir::ScatterKind::Absorber, origin);
  return scatter(c.material.mix(a, b, w, origin));
}

Closure addClosures(Context& c, const Closure& a, const Closure& b, const ir::Origin& origin) {
  if (a.kind == Closure::Kind::Emission || b.kind == Closure::Kind::Emission) {
    Closure sum = a;
    sum.kind = Closure::Kind::Emission;
    sum.emissions.insert(sum.emissions.end(), b.emissions.begin(), b.emissions.end());
    return sum;
  }
  if (a.kind != Closure::Kind::Scatter) return b;
  if (b.kind != Closure::Kind::Scatter) return a;
  c.note(origin, "<add> of BSDFs is not energy-bounded: the sum's albedo can exceed 1");
  ir::ScatterNode node;
  node.kind = ir::ScatterKind::Add;
  node.a = a.index;
  node.b = b.index;
  node.origin = origin;
  return scatter(c.material.addNode(std::move(node)));
}

Index withOpacity(Context& c, Index root, const ir::Param& opacity, const ir::Origin& origin) {
  if (!opacity.present() || c.material.exprs.isConstantEqual(opacity.value, 1.0f)) return root;
  return c.material.mix(c.material.leaf(ir::ScatterKind::Ambient, origin), root, opacity, origin);
}

Closure scaleClosure(Context& c, const Closure& closure, const ir::Param& factor, const ir::Origin& origin) {
  if (closure.kind == Closure::Kind::Emission) return scaleEmission(c, closure, factor.value, factor.origin);
  if (closure.kind == Closure::Kind::Medium) {
    ir::Medium m = c.material.media[closure.index];
    for (auto& [slot, p] : m.slots.all()) {
      if (slot == ir::Slot::Absorption || slot == ir::Slot::Scattering) p.value = c.b.mul(p.value, factor.value);
    }
    return {Closure::Kind::Medium, c.material.addMedium(std::move(m)), {}};
  }
  if (closure.kind != Closure::Kind::Scatter) return closure;
  if (c.b.type(factor.value) == ir::Type::Float) {
    // w f is a surface covered with f over a fraction w, black elsewhere: Mix(Absorber, f, w).
    // Bounded only for w in [0, 1]: a constant outside that range is noted.
    if (c.material.exprs.isConstant(factor.value)) {
      float w = c.material.exprs.constantComponents(factor.value)[0];
      if (w < 0.0f || w > 1.0f) c.note(factor.origin, fmt::format("a BSDF scaled by {} is not energy-bounded", w));
    }
    Index black = c.material.leaf(ir::ScatterKind::Absorber, origin);
    return scatter(c.material.mix(black, closure.index, factor, origin));
  }
  ir::ScatterNode node;
  node.kind = ir::ScatterKind::Tint;
  node.a = closure.index;
  node.weight = factor;
  node.origin = origin;
  return scatter(c.material.addNode(std::move(node)));
}

}  // namespace mxc::lower
