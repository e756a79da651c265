#include "cli/InspectCommand.h"

#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include "cli/OutputSet.h"
#include "cli/ExitCode.h"
#include "cli/MaterialPipeline.h"
#include "cli/Session.h"
#include "compiler/common/JsonText.h"
#include "compiler/driver/Compiler.h"
#include "compiler/inspect/Inspect.h"
#include "compiler/ir/Print.h"

namespace mxc::cli {

int runInspect(const InspectOptions& options) {
  if (options.effects) return runInspectEffects(options);
  if (!options.ir && (!options.inputs.set.empty() || !options.inputs.parameters.empty())) {
    // The plain report shows the document as written; --set and --param change what is compiled.
    std::fprintf(stderr, "error: --set and --param change the compiled material: use them with inspect --ir or "
                         "--effects (the plain report shows the document as written)\n");
    return kUsage;
  }
  const std::string output = options.output.empty() ? "-" : options.output;
  OutputSet outputs;
  if (printError(outputs.declare(output, "-o"))) return kOutputFailed;
  Session session;
  CompileRequest request;
  request.document = options.file;
  request.partial = options.partial;
  request.lowering.useShadingModelGraphs = options.shadingModelGraphs;
  if (!requestInputs(options.inputs, request)) return kUsage;
  const bool libraries = session.loadLibraries(options.libraries);
  Compiler compiler(session.workspace, std::move(request));
  const doc::Document* document = libraries ? compiler.document() : nullptr;
  const resolve::ResolvedDocument* resolved = document ? compiler.resolved() : nullptr;
  session.printDiagnostics();
  if (!resolved) return kInvalidDocument;
  const Diagnostics& diagnostics = session.workspace.diagnostics;
  auto stop = [&] {
    std::fprintf(stderr, "%s: %zu error(s); no report written (--partial writes one anyway)\n", options.file.c_str(),
                 diagnostics.errorCount());
    return kInvalidDocument;
  };
  bool failed = diagnostics.hasErrors();
  if (failed && !options.partial) return stop();
  std::string report;
  bool lossy = false;  // a name that is not UTF-8 in a JSON report
  if (options.ir) {
    const std::vector<ir::Material>& materials = compiler.materials();
    session.printDiagnostics();
    if (diagnostics.hasErrors() && !options.partial) return stop();
    // The IR does not change with the accuracy tier; the tier says what the back end makes of it.
    const Accuracy accuracy = options.inputs.accuracy;
    if (options.json) {
      nlohmann::json j{{"schema", "mxc-ir-1"},
                       {"document", document->path()},
                       {"accuracy", {{"tier", accuracyName(accuracy)}, {"description", accuracyDescription(accuracy)}}},
                       {"materials", nlohmann::json::array()}};
      for (const ir::Material& m : materials) j["materials"].push_back(ir::materialJson(m));
      report = jsonText(j, 2, &lossy) + "\n";
    } else {
      report = fmt::format("accuracy: {} ({})\n\n", accuracyName(accuracy), accuracyDescription(accuracy));
      for (const ir::Material& m : materials) report += ir::printMaterial(m, &document->source()) + "\n";
    }
  } else {
    inspect::InspectInput input{*resolved, diagnostics, session.workspace.libraryInfo};
    report = options.json  ? inspect::inspectJson(input, &lossy) + "\n"
             : options.dot ? inspect::inspectDot(input)
                           : inspect::inspectText(input);
  }
  if (lossy) std::fprintf(stderr, "warning: %s\n", notUtf8Warning("the JSON report").c_str());
  if (printError(session.checkOutputsAreNotSources(outputs))) return kUsage;
  if (printError(outputs.stage(output, std::move(report)))) return kOutputFailed;
  if (printError(outputs.commit())) return kOutputFailed;
  return failed || diagnostics.hasErrors() ? kInvalidDocument : kOk;
}

}  // namespace mxc::cli
