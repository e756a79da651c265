#include "cli/InspectCommand.h"

#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include "cli/OutputSet.h"
#include "cli/ExitCode.h"
#include "cli/MaterialPipeline.h"
#include "cli/Session.h"
#include "compiler/document/DocumentLoader.h"
#include "compiler/inspect/Inspect.h"
#include "compiler/ir/Effects.h"
#include "compiler/ir/Print.h"
#include "compiler/ir/passes/Pass.h"
#include "compiler/lower/Lowering.h"
#include "compiler/resolve/Resolver.h"

namespace mxc::cli {

namespace {

struct InspectOptions {
  std::string file;
  bool json = false;
  bool dot = false;
  std::string output;
  bool partial = false;
  bool ir = false;
  bool shadingModelGraphs = false;
  MaterialOptions inputs;  ///< --set and --param, for --ir
  LibraryOptions libraries;
};

int runInspect(const InspectOptions& options) {
  const std::string output = options.output.empty() ? "-" : options.output;
  OutputSet outputs;
  if (printError(outputs.declare(output, "-o"))) return kOutputFailed;
  Session session;
  session.loadLibraries(options.libraries);
  doc::DocumentLoader loader(session.sources, session.diagnostics);
  const doc::Document* document = session.diagnostics.hasErrors() ? nullptr : loader.loadFile(options.file);
  if (!document) {
    session.printDiagnostics();
    return kInvalidDocument;
  }
  resolve::ResolvedDocument resolved = resolve::resolveDocument(*document, session.libraries.top(), session.diagnostics);
  session.printDiagnostics();
  bool failed = session.diagnostics.hasErrors();
  if (failed && !options.partial) {
    std::fprintf(stderr, "%s: %zu error(s); no report written (--partial writes one anyway)\n", options.file.c_str(),
                 session.diagnostics.errorCount());
    return kInvalidDocument;
  }
  std::string report;
  if (options.ir) {
    lower::LoweringOptions lowering;
    if (!inputOptions(options.inputs, lowering)) return kUsage;
    lowering.useShadingModelGraphs = options.shadingModelGraphs;
    std::vector<ir::Material> materials = lower::lowerDocument(resolved, lowering, session.diagnostics);
    for (ir::Material& m : materials) {
      ir::runPasses(m);
      ir::summarizeEffects(m);
    }
    session.printDiagnostics();
    if (session.diagnostics.hasErrors() && !options.partial) {
      std::fprintf(stderr, "%s: %zu error(s); no report written (--partial writes one anyway)\n", options.file.c_str(),
                   session.diagnostics.errorCount());
      return kInvalidDocument;
    }
    if (options.json) {
      nlohmann::json j{{"schema", "mxc-ir-1"}, {"document", document->path()}, {"materials", nlohmann::json::array()}};
      for (const ir::Material& m : materials) j["materials"].push_back(ir::materialJson(m));
      report = j.dump(2) + "\n";
    } else {
      for (const ir::Material& m : materials) report += ir::printMaterial(m, &document->source()) + "\n";
    }
  } else {
    inspect::InspectInput input{resolved, session.diagnostics, session.libraryInfo};
    report = options.json  ? inspect::inspectJson(input).dump(2) + "\n"
             : options.dot ? inspect::inspectDot(input)
                           : inspect::inspectText(input);
  }
  if (printError(session.checkOutputsAreNotSources(outputs))) return kUsage;
  if (printError(outputs.stage(output, std::move(report)))) return kOutputFailed;
  if (printError(outputs.commit())) return kOutputFailed;
  return failed || session.diagnostics.hasErrors() ? kInvalidDocument : kOk;
}

}  // namespace

void registerInspect(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<InspectOptions>();
  CLI::App* command = app.add_subcommand(
      "inspect",
      "Show a document: its materials, their shader nodes with every input (set or default, with its source "
      "line), and the resolved graph as an indented tree");
  command->add_option("file", options->file, "The .mtlx document")->required();
  auto* json = command->add_flag("--json", options->json, "Write JSON (schema mxc-inspect-1, docs/inspect-json.md)");
  auto* dot = command->add_flag("--dot", options->dot, "Write a Graphviz DOT graph");
  json->excludes(dot);
  auto* ir = command->add_flag("--ir", options->ir,
                               "Show the slab IR of each material after the passes (with --json: schema mxc-ir-1, "
                               "docs/ir-json.md)");
  ir->excludes(dot);
  command->add_flag("--shading-model-graphs", options->shadingModelGraphs,
                    "With --ir: lower open_pbr_surface and standard_surface through the node graphs that implement "
                    "them in the libraries (MaterialX's, with --library) instead of mxc's own lowering")
      ->needs(ir);
  command->add_option("-o,--output", options->output, "Write the report to this file (atomically) instead of stdout");
  command->add_flag("--partial", options->partial,
                    "Write the report even when the document has errors (the exit code is still 1)");
  addInputOptions(*command, options->inputs);
  addLibraryOptions(*command, options->libraries);
  command->callback([options, &exitCode] { exitCode = runInspect(*options); });
}

}  // namespace mxc::cli
