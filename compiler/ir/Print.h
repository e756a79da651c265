#pragma once
/// \file
/// Reading the IR: a text tree for people and goldens, and JSON in the schema documented in
/// docs/ir-json.md.

#include <string>

#include <nlohmann/json.hpp>

#include "compiler/ir/Material.h"

namespace mxc::ir {

/// The material as an indented tree: effects, notes, the scattering tree with each interface,
/// medium and emission, then the non-constant expressions it uses. Source positions are
/// written as "line N" in `document` and "path:N" elsewhere (pass null for full paths).
std::string printMaterial(const Material& m, const SourceFile* document);

/// The material as JSON (schema "mxc-ir-1"): every scattering node has a "kind" (slab, mix,
/// bsdf, medium, emission, add, tint, ambient, absorber); slabs have top, medium, base and
/// coverage; the material has an "effects" list.
nlohmann::json materialJson(const Material& m);

/// The structure of the scattering tree as one line, for comparing two lowerings of a material:
/// node kinds, interface kinds with scatter modes, thin films, bulk and thin-wall media,
/// emission, and whether coverages are present; not parameter values, origins, or finite
/// absorbing media (a coat's tint is a value: MaterialX's graph also folds its coat darkening
/// heuristic into it).
std::string structureSignature(const Material& m);

/// An expression as text: a constant's value, else "%id".
std::string exprText(const ExprGraph& g, ExprId id);

}  // namespace mxc::ir
