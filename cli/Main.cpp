// mxc: a compiler for MaterialX material documents. See README.md for the commands.

#include <cstdio>
#include <new>

#include <CLI/CLI.hpp>

#include "cli/ExitCode.h"
#include "cli/CompileCommand.h"
#include "cli/EvalCommand.h"
#include "cli/InspectCommand.h"
#include "cli/ProcessSetup.h"
#include "cli/RenderCommand.h"
#include "compiler/common/LargeStack.h"

namespace {

int run(int argc, char** argv) {
  using namespace mxc::cli;
  CLI::App app{"mxc: compile MaterialX documents (Standard Surface, OpenPBR, pbrlib graphs) to shaders", "mxc"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "mxc 0.1.0");
  app.footer(
      "Exit codes: 0 success, 1 invalid document or library (errors name file:line:column), 2 usage error, "
      "3 an output could not be written, 4 out of memory.\nRun 'mxc COMMAND --help' for the options of a command.");
  int exitCode = kOk;
  registerInspect(app, exitCode);
  registerCompile(app, exitCode);
  registerEval(app, exitCode);
  registerFurnace(app, exitCode);
  registerRender(app, exitCode);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // prints the message
    return kUsage;
  }
  return exitCode;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace mxc::cli;
  setUpProcess();
  int exitCode = kOk;
  try {
    // Deep node graphs recurse deeply in resolution and lowering: commands run on a large stack.
    mxc::runWithLargeStack([&] { exitCode = run(argc, argv); });
  } catch (const std::bad_alloc&) {
    // Unwinding has removed every temporary of the command (OutputSet, StagedFile).
    std::fprintf(stderr, "error: out of memory\n");
    exitCode = kOutOfMemory;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    exitCode = kInvalidDocument;
  }
  // A command that failed to write its report has said so; everything else written to standard
  // output (summaries, "wrote ...") is checked here.
  if (exitCode != kOutputFailed && !flushStandardOutput() && exitCode == kOk) exitCode = kOutputFailed;
  return exitCode;
}
