#include "compiler/lower/Layering.h"

#include "compiler/lower/Media.h"

namespace mxc::lower {

using ir::Index;
using ir::ScatterKind;

namespace {

/// MaterialX writes the absorption between a layer's top and its base as a colour multiplying
/// the base (`layer(coat, base * lerp(1, coat_color, coat))`, the seed commentary 4.1): in the
/// IR that colour is the medium of the slab, an absorber of unit thickness whose normal-
/// incidence transmittance is the colour (as OpenPBR defines coat_color). Nested tints
/// multiply. Returns the base under the tints, and sets `medium` (kNone when no tint).
Index absorbTints(Context& c, Index base, Index& medium, const ir::Origin& origin) {
  ir::ExprId color = ir::kNoExpr;
  ir::Origin colorOrigin = origin;
  while (base != ir::kNone && c.material.nodes[base].kind == ScatterKind::Tint) {
    const ir::ScatterNode& tint = c.material.nodes[base];
    ir::ExprId w = tint.weight.value;
    if (c.b.type(w) == ir::Type::Float) w = c.b.splat(w, ir::Type::Vec3);
    color = color == ir::kNoExpr ? w : c.b.mul(color, w);
    colorOrigin = tint.weight.origin;
    base = tint.a;
  }
  medium = color == ir::kNoExpr ? ir::kNone : coatMedium(c, {color, colorOrigin}, colorOrigin);
  return base;
}

}  // namespace

Index attachBase(Context& c, Index top, Index base, const ir::Origin& origin) {
  ir::ScatterNode node = c.material.nodes[top];  // a copy: `top` may be shared
  switch (node.kind) {
    case ScatterKind::Slab:
      if (node.medium != ir::kNone && c.material.media[node.medium].extent == ir::Medium::Extent::Bulk) {
        c.note(origin, "a layer base under a semi-infinite medium is never reached by light; it is dropped");
        return top;
      }
      if (node.base == ir::kNone) {
        Index medium = ir::kNone;
        Index under = node.medium == ir::kNone ? absorbTints(c, base, medium, origin) : base;
        node.medium = medium != ir::kNone ? medium : node.medium;
        node.base = under;
      } else {
        node.base = attachBase(c, node.base, base, origin);
      }
      return c.material.addNode(std::move(node));
    case ScatterKind::Mix:
      node.a = attachBase(c, node.a, base, origin);
      node.b = attachBase(c, node.b, base, origin);
      return c.material.addNode(std::move(node));
    case ScatterKind::Add:
      c.note(origin, "layering over an <add> of BSDFs puts the base under each term: the sum of their "
                     "albedo-scaled bases can exceed 1 (not energy-bounded)");
      node.a = attachBase(c, node.a, base, origin);
      node.b = attachBase(c, node.b, base, origin);
      return c.material.addNode(std::move(node));
    case ScatterKind::Tint:
      // MaterialX scales the top only (tint * top + (1 - tint * E_top) base); the IR tints the
      // stack. The difference is the tint's effect on the base, noted for the user.
      c.note(origin, "a layer whose top is tinted by a colour: the tint also applies to the base in the IR");
      node.a = attachBase(c, node.a, base, origin);
      return c.material.addNode(std::move(node));
    case ScatterKind::Emissive:
      node.a = attachBase(c, node.a, base, origin);
      return c.material.addNode(std::move(node));
    case ScatterKind::Ambient:
      return base;  // nothing on top: the base shows through
    case ScatterKind::Absorber:
      // A top with no BSDF (an unconnected side of a mix, the unweighted part of a scaled
      // BSDF) reflects nothing, so all of the base shows: layer(0, base) = 0 + (1 - 0) base
      // (MaterialX "layer": top + (1 - albedo(top)) base).
      return base;
  }
  return top;
}

Index attachMedium(Context& c, Index top, Index medium, const ir::Origin& origin) {
  ir::ScatterNode node = c.material.nodes[top];
  switch (node.kind) {
    case ScatterKind::Slab:
      if (node.base != ir::kNone) {
        node.base = attachMedium(c, node.base, medium, origin);
      } else if (node.medium == ir::kNone) {
        node.medium = medium;
      } else {
        c.note(origin, "a volume layered under a slab that already has a medium is ignored");
        return top;
      }
      return c.material.addNode(std::move(node));
    case ScatterKind::Mix:
    case ScatterKind::Add:
      node.a = attachMedium(c, node.a, medium, origin);
      node.b = attachMedium(c, node.b, medium, origin);
      return c.material.addNode(std::move(node));
    case ScatterKind::Tint:
    case ScatterKind::Emissive:
      node.a = attachMedium(c, node.a, medium, origin);
      return c.material.addNode(std::move(node));
    case ScatterKind::Ambient:
    case ScatterKind::Absorber:
      c.note(origin, "a volume layered under nothing (or under a black surface) has no effect");
      return top;
  }
  return top;
}

Index interfaceSlab(Context& c, ir::Interface interface, const ir::Param& coverage) {
  ir::Origin origin = interface.origin;
  Index top = c.material.addInterface(std::move(interface));
  ir::Param cov = coverage;
  if (cov.present() && c.material.exprs.isConstantEqual(cov.value, 1.0f)) cov = {};
  return c.material.slab(top, ir::kNone, ir::kNone, cov, origin);
}

}  // namespace mxc::lower
