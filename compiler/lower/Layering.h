#pragma once
/// \file
/// Building slab stacks: what MaterialX's <layer> means in the IR.

#include "compiler/lower/Context.h"

namespace mxc::lower {

/// layer(top, base) for a BSDF base: `base` goes under the bottom of every stack of `top`
/// (through mixes: layer(mix(A, B, w), C) = mix(layer(A, C), layer(B, C), w), OpenPBR
/// "Layering" and "Mixing"). Nodes are copied, never changed in place, since a closure may be
/// used in several places. Returns the new root.
ir::Index attachBase(Context& c, ir::Index top, ir::Index base, const ir::Origin& origin);

/// layer(top, vdf): the medium goes under the interface of every bottom slab of `top`.
ir::Index attachMedium(Context& c, ir::Index top, ir::Index medium, const ir::Origin& origin);

/// A slab whose only content is an interface: Slab{top, no medium, no base, coverage}.
/// An absent or constant-1 coverage is left out.
ir::Index interfaceSlab(Context& c, ir::Interface interface, const ir::Param& coverage);

}  // namespace mxc::lower
