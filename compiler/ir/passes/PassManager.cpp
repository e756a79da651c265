#include "compiler/ir/passes/Pass.h"

namespace mxc::ir {

const std::vector<Pass>& standardPasses() {
  // Folding first, so the structural passes see constants; the normal form last.
  static const std::vector<Pass> passes = {
      {"constant-folding", constantFolding},
      {"prune-coverage", pruneCoverage},
      {"collapse-mix", collapseMix},
      {"remove-empty-media", removeEmptyMedia},
      {"remove-thin-film", removeThinFilm},
      {"remove-default-slots", removeDefaultSlots},
      {"remove-dark-emission", removeDarkEmission},
      {"merge-dielectric-lobes", mergeDielectricLobes},
      {"bulk-under-transmission", bulkUnderTransmission},
      {"distribute-over-mix", distributeOverMix},
      {"fold-thin-film-mix", foldThinFilmMix},
      {"common-subexpressions", commonSubexpressions},
  };
  return passes;
}

std::vector<PassReport> runPasses(Material& m, const PassContext& context, int maxRounds) {
  std::vector<PassReport> reports;
  for (const Pass& p : standardPasses()) reports.push_back({p.name, 0});
  for (int round = 0; round < maxRounds; ++round) {
    int total = 0;
    for (size_t i = 0; i < standardPasses().size(); ++i) {
      int edits = standardPasses()[i].run(m, context);
      reports[i].edits += edits;
      total += edits;
    }
    if (total == 0) break;
  }
  reports.push_back({"dead-code", deadCode(m, context)});
  return reports;
}

}  // namespace mxc::ir
