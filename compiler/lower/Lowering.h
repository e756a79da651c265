#pragma once
/// \file
/// Lowering: from the resolved graph of a document to IR materials (compiler/ir).

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "compiler/common/Diagnostic.h"
#include "compiler/ir/Material.h"
#include "compiler/resolve/ResolvedGraph.h"

namespace mxc::lower {

struct LoweringOptions {
  /// Lower open_pbr_surface and standard_surface through the node graph that implements them
  /// in the library (for example MaterialX's own graphs, with --library), instead of mxc's
  /// lowering from the specifications. Used to compare the two.
  bool useShadingModelGraphs = false;
  /// `--set INPUT=VALUE`: inputs of each material's shading node replaced by these values
  /// (written as in a document's `value` attribute), so a user can try a value without editing
  /// the document.
  std::vector<std::pair<std::string, std::string>> overrides;
  /// `--param NAME`: inputs of the shading node that stay variable in the shader (a uniform with
  /// the input's value as its default) instead of being folded as constants.
  std::vector<std::string> parameters;
  /// `--no-specialize`: every input of the shading node that has a value (set or default; not a
  /// string) stays variable, as `--param` would keep it, so that no effect of the shading model
  /// is folded away: the general shader a generator that does not specialize makes.
  bool everyInputVariable = false;
  /// Folders an image file is looked for in when it is not found relative to the document's
  /// folder (`--search-path`, MATERIALX_SEARCH_PATH): MaterialX's resolution order, the
  /// document's folder first (its `fileprefix` is part of the file's value already).
  std::vector<std::filesystem::path> imageSearchPaths;
  /// The colour space the shader computes in (`--working-space`; a linear space of
  /// compiler/common/ColorSpace.h). Colour values and colour textures tagged with another
  /// `colorspace` are converted into it, as MaterialX converts toward its target space, whose
  /// default this is too.
  std::string workingSpace = "lin_rec709";
};

/// Every material of the document, in document order: each surfacematerial's surface shader.
/// A document without materials (a pbrlib test graph) gives one material per surfaceshader
/// output of its node graphs, named "graph/output". Errors (an unsupported node, a structure
/// that cannot be lowered) are reported at the element that causes them; the material is
/// still returned with what could be lowered.
std::vector<ir::Material> lowerDocument(const resolve::ResolvedDocument& document, const LoweringOptions& options,
                                        Diagnostics& diagnostics);

/// Says once for the run what `--set` and `--param` did over `materials` (the materials a
/// command compiles): an error when no material's shading node has the input (at that node when
/// there is one material), an error at the argument when a --set value is not of the input's
/// type, and a note naming the materials it applies to when only some have the input.
void checkUserInputs(const std::vector<ir::Material>& materials, const LoweringOptions& options,
                     Diagnostics& diagnostics);

}  // namespace mxc::lower
