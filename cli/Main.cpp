// mxc: a compiler for MaterialX material documents. See README.md for the commands.

#include <cstdio>
#include <new>
#include <string_view>

#include "cli/CommandLine.h"
#include "cli/ExitCode.h"
#include "cli/ProcessSetup.h"
#include "compiler/common/LargeStack.h"

int main(int argc, char** argv) {
  using namespace mxc::cli;
  setUpProcess();
  int exitCode = kOk;
  try {
    // Deep node graphs recurse deeply in resolution and lowering: commands run on a large stack.
    mxc::runWithLargeStack([&] { exitCode = runCommandLine(argc, argv); });
  } catch (const std::bad_alloc& e) {
    // Unwinding has removed every temporary of the command (OutputSet, StagedFile). A Vulkan
    // call says which call and which memory (rt::VulkanOutOfMemory); operator new says nothing.
    const std::string_view what = e.what();
    if (what == std::bad_alloc().what()) {
      std::fprintf(stderr, "error: out of memory\n");
    } else {
      std::fprintf(stderr, "error: out of memory: %s\n", e.what());
    }
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
