#pragma once
/// \file
/// Upgrading MaterialX 1.38 documents to the 1.39 node set.

#include "compiler/common/Diagnostic.h"
#include "compiler/document/Document.h"

namespace mxc::doc {

/// Rewrites a 1.38 document in place so that it resolves against a 1.39 library:
/// - layer(thin_film_bsdf, B) becomes B with thinfilm_thickness/thinfilm_ior on its BSDFs;
/// - subsurface_bsdf's vector3 radius becomes color3 (through a convert node when connected);
/// - atan2's in1/in2 become iny/inx.
/// The 1.38 `channels` swizzle on inputs needs no rewrite: the resolver applies it.
/// Each change is listed in Document::upgradeNotes. Documents of other versions are untouched.
void upgradeTo139(Document& doc, Diagnostics& diagnostics);

}  // namespace mxc::doc
