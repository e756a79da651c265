#pragma once
/// \file
/// Combining closures as MaterialX pbrlib's layer, mix, add and multiply define them (MaterialX
/// 1.39 "PBR Shader Nodes": layer, mix, add, multiply), for every rule that builds a scattering
/// tree from other closures (pbrlib's own nodes, Pixar's Lama nodes).

#include "compiler/lower/Context.h"

namespace mxc::lower {

/// layer(top, base): a BSDF base goes under every bottom slab of `top`, a VDF fills the slab
/// under its interface; an empty top leaves the base.
Closure layerClosures(Context& c, const Closure& top, const Closure& base, const ir::Origin& origin);

/// mix(fg, bg, w) = (1 - w) bg + w fg. Emissions are scaled and summed; mixing media is an
/// error reported at `origin`; an empty side is black.
Closure mixClosures(Context& c, const Closure& fg, const Closure& bg, const ir::Param& w, const ir::Origin& origin);

/// a + b. A sum of BSDFs is noted as not energy-bounded; emissions are concatenated.
Closure addClosures(Context& c, const Closure& a, const Closure& b, const ir::Origin& origin);

/// A surface present over `opacity` of its area, the ambient seen through the rest:
/// Mix(Ambient, root, opacity) (MaterialX surface "opacity"); `root` itself for an absent or
/// constant-1 opacity.
ir::Index withOpacity(Context& c, ir::Index root, const ir::Param& opacity, const ir::Origin& origin);

/// `closure` scaled by `factor` (a float or a colour): a float w on a BSDF is Mix(black, f, w), a
/// colour a Tint; emissions and media are scaled in their coefficients.
Closure scaleClosure(Context& c, const Closure& closure, const ir::Param& factor, const ir::Origin& origin);

}  // namespace mxc::lower
