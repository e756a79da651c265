#pragma once
/// \file
/// Upgrading MaterialX 1.38 documents to the 1.39 node set.

#include "compiler/common/Diagnostic.h"
#include "compiler/document/Document.h"

namespace mxc::doc {

/// Rewrites a MaterialX 1.22-1.37 document in place into the 1.38 form, following MaterialX's
/// upgrade rules (its Version.cpp is the description of record):
/// - each <material> becomes a shader node per <shaderref> (inputs from its <bindinput>s and
///   <bindparam>s, or from <override>s through the shader's public names) and a
///   surfacematerial node of the material's name; legacy shader nodedefs are removed;
/// - the 1.37 BSDFs become 1.38 ones: *_brdf/_btdf renamed, a `base` input becomes a layer
///   node, conductor_brdf's artistic inputs go through an artistic_ior node, dielectric_btdf
///   gets scatter_mode T; atan2's in1/in2 are swapped;
/// - the 1.36 node renames: rotate -> rotate2d/3d, combine/separate -> their sized forms,
///   compare -> ifgreatereq, matrix invert -> invertmatrix, transform* without spaces ->
///   transformmatrix, geomattrvalue -> geompropvalue; backdrop nodes are dropped;
/// - %UDIM and %UVTILE in filenames (1.35) become <UDIM> and <UVTILE>.
/// The builder already read <parameter> as <input>, <opgraph> as <nodegraph>, <shader> as a
/// nodedef and the old type names. Each change is listed in Document::upgradeNotes.
void upgradeTo138(Document& doc, Diagnostics& diagnostics);

/// Rewrites a 1.38 document in place so that it resolves against a 1.39 library:
/// - layer(thin_film_bsdf, B) becomes B with thinfilm_thickness/thinfilm_ior on its BSDFs;
/// - subsurface_bsdf's vector3 radius becomes color3 (through a convert node when connected);
/// - atan2's in1/in2 become iny/inx;
/// - a swizzle node becomes a dot whose input takes the swizzle's channels (connected) or a
///   constant of the swizzled components (a value).
/// The 1.38 `channels` swizzle on inputs needs no rewrite: the resolver applies it.
/// Each change is listed in Document::upgradeNotes. 1.39 documents are untouched.
void upgradeTo139(Document& doc, Diagnostics& diagnostics);

}  // namespace mxc::doc
