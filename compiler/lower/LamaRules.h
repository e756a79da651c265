#pragma once
/// \file
/// Pixar's Lama BSDF nodes (MaterialX 1.39 `libraries/bxdf/lama`, RenderMan's MaterialX Lama),
/// lowered to the slab IR directly: the closure rules of PbrlibRules.cpp's table for the Lama
/// categories (LamaRules.cpp states each mapping).

#include <string_view>

#include "compiler/lower/Context.h"

namespace mxc::lower {

Closure lamaConductor(Context& c, const NodeRef& n, std::string_view output);
Closure lamaDielectric(Context& c, const NodeRef& n, std::string_view output);
Closure lamaGeneralizedSchlick(Context& c, const NodeRef& n, std::string_view output);
Closure lamaIridescence(Context& c, const NodeRef& n, std::string_view output);
Closure lamaDiffuse(Context& c, const NodeRef& n, std::string_view output);
Closure lamaTranslucent(Context& c, const NodeRef& n, std::string_view output);
Closure lamaSheen(Context& c, const NodeRef& n, std::string_view output);
Closure lamaSss(Context& c, const NodeRef& n, std::string_view output);
Closure lamaEmission(Context& c, const NodeRef& n, std::string_view output);
Closure lamaAdd(Context& c, const NodeRef& n, std::string_view output);
Closure lamaMix(Context& c, const NodeRef& n, std::string_view output);
Closure lamaLayer(Context& c, const NodeRef& n, std::string_view output);
/// LamaSurface is a material node: its front BSDF is the material's surface, `presence` its
/// opacity. Lowering finds it as a material's shader (Lowering.cpp).
Closure lamaSurface(Context& c, const NodeRef& n, std::string_view output);

}  // namespace mxc::lower
