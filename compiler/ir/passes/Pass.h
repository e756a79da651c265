#pragma once
/// \file
/// IR passes: each has a name and one job, and returns how many edits it made. runPasses
/// runs the standard list to a fixed point, then sweeps what nothing refers to any more.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/common/Accuracy.h"
#include "compiler/ir/Material.h"

namespace mxc::ir {

/// What a pass may read besides the material: the compile request's choices, read-only, so a
/// pass can specialise without a global.
struct PassContext {
  Accuracy accuracy = Accuracy::Balanced;
  /// Inputs of the shading node the user keeps variable (`--param`): their Op::Parameter
  /// expressions must survive, whatever their default value.
  std::span<const std::string> keptParameters;
  /// Run the IR verifier (compiler/ir/Verify.h) on the material before the passes and after
  /// each one; a broken rule throws VerifyFailure naming the pass. On in tests and debug builds.
  bool verify = false;
};

struct Pass {
  std::string_view name;
  int (*run)(Material&, const PassContext&);
};

// Expressions
/// Replaces operations on constants by their value and applies algebraic identities
/// (x * 1 = x, x + 0 = x, mix(a, b, 0) = a, select(true, a, b) = a, ...).
int constantFolding(Material& m, const PassContext& context = {});
/// Drops expressions and scattering entries nothing reachable refers to, and renumbers.
int deadCode(Material& m, const PassContext& context = {});
/// Merges structurally identical interfaces, media, emissions and scattering nodes.
/// (Identical expressions are shared when they are built: ExprGraph interns them.)
int commonSubexpressions(Material& m, const PassContext& context = {});

// Scattering structure
/// A slab whose coverage is 0 is its base; coverage 1 is dropped (absent means 1).
int pruneCoverage(Material& m, const PassContext& context = {});
/// mix(a, b, 0) = a, mix(a, b, 1) = b, mix(a, a, w) = a; add with an absorber; tint by 1.
int collapseMix(Material& m, const PassContext& context = {});
/// A medium that neither absorbs nor scatters (nor refracts: a bulk dielectric with an IOR
/// stays) is removed.
int removeEmptyMedia(Material& m, const PassContext& context = {});
/// A thin film of thickness 0 or coverage 0 is removed.
int removeThinFilm(Material& m, const PassContext& context = {});
/// A slot holding its default value (slotDefault) is dropped: absent means the default.
int removeDefaultSlots(Material& m, const PassContext& context = {});
/// Emission of colour 0 is removed.
int removeDarkEmission(Material& m, const PassContext& context = {});
/// A reflection-only dielectric over a transmission-only one with the same interface
/// parameters is one dielectric; an index-matched slab under an interface takes that
/// interface (MaterialX's layer(dielectric, subsurface) and layer(dielectric_R, dielectric_T)).
int mergeDielectricLobes(Material& m, const PassContext& context = {});
/// A transmitting dielectric at the bottom of a stack gets the clear bulk it transmits into
/// (a medium with the interface's IOR; a thin sheet when the material is thin-walled), so
/// "a dielectric over a medium" reads the same from every lowering.
int bulkUnderTransmission(Material& m, const PassContext& context = {});
/// Slab(top, base = mix(a, b, w)) = mix(Slab(top, a), Slab(top, b), w), and likewise for
/// emissive and tint nodes: the normal form is a mixture of slab stacks.
int distributeOverMix(Material& m, const PassContext& context = {});
/// mix(Slab(f), Slab(f with thin film), w) = Slab(f with thin film of coverage w).
int foldThinFilmMix(Material& m, const PassContext& context = {});

/// The standard pass list, in order.
const std::vector<Pass>& standardPasses();

struct PassReport {
  std::string_view name;
  int edits = 0;
};

/// Runs the standard passes until none edits (at most `maxRounds` rounds), then deadCode.
/// Returns the edits of each pass summed over the rounds.
std::vector<PassReport> runPasses(Material& m, const PassContext& context = {}, int maxRounds = 32);

}  // namespace mxc::ir
