#include "cli/InspectCommand.h"

#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include "cli/AtomicFile.h"
#include "cli/ExitCode.h"
#include "cli/Session.h"
#include "compiler/document/DocumentLoader.h"
#include "compiler/inspect/Inspect.h"
#include "compiler/resolve/Resolver.h"

namespace mxc::cli {

namespace {

struct InspectOptions {
  std::string file;
  bool json = false;
  bool dot = false;
  std::string output;
  bool partial = false;
  LibraryOptions libraries;
};

int runInspect(const InspectOptions& options) {
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
  const bool failed = session.diagnostics.hasErrors();
  if (failed && !options.partial) {
    std::fprintf(stderr, "%s: %zu error(s); no report written (--partial writes one anyway)\n", options.file.c_str(),
                 session.diagnostics.errorCount());
    return kInvalidDocument;
  }
  inspect::InspectInput input{resolved, session.diagnostics, session.libraryInfo};
  std::string report = options.json  ? inspect::inspectJson(input).dump(2) + "\n"
                       : options.dot ? inspect::inspectDot(input)
                                     : inspect::inspectText(input);
  if (options.output.empty() || options.output == "-") {
    std::fwrite(report.data(), 1, report.size(), stdout);
  } else if (auto error = writeFileAtomically(options.output, report)) {
    std::fprintf(stderr, "error: %s\n", error->c_str());
    return kOutputFailed;
  }
  return failed ? kInvalidDocument : kOk;
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
  command->add_option("-o,--output", options->output, "Write the report to this file (atomically) instead of stdout");
  command->add_flag("--partial", options->partial,
                    "Write the report even when the document has errors (the exit code is still 1)");
  addLibraryOptions(*command, options->libraries);
  command->callback([options, &exitCode] { exitCode = runInspect(*options); });
}

}  // namespace mxc::cli
