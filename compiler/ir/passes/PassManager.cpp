#include "compiler/ir/passes/Pass.h"

#include <string>

#include <fmt/format.h>

#include "compiler/ir/Verify.h"

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

namespace {

/// With context.verify, the IR must keep every rule after `stage`.
void check(const Material& m, const PassContext& context, std::string_view stage) {
  if (!context.verify) return;
  std::vector<VerifyError> errors = verify(m);
  if (!errors.empty()) throw VerifyFailure(std::string(stage), m, errors);
}

}  // namespace

std::vector<PassReport> runPasses(Material& m, const PassContext& context, int maxRounds) {
  check(m, context, "lowering");
  std::vector<PassReport> reports;
  for (const Pass& p : standardPasses()) reports.push_back({p.name, 0});
  for (int round = 0; round < maxRounds; ++round) {
    int total = 0;
    for (size_t i = 0; i < standardPasses().size(); ++i) {
      int edits = standardPasses()[i].run(m, context);
      if (edits > 0) check(m, context, fmt::format("pass {}", standardPasses()[i].name));
      reports[i].edits += edits;
      total += edits;
    }
    if (total == 0) break;
  }
  reports.push_back({"dead-code", deadCode(m, context)});
  check(m, context, "pass dead-code");
  return reports;
}

}  // namespace mxc::ir
