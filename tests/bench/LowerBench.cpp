// Lowering time: open_pbr_surface documents resolved, lowered to the slab IR and run through
// the passes, with the library loaded and the document parsed beforehand; the resolve of the
// same document is the baseline measured in the same run.
//
//   build/tests/bench/lower_bench [benchmark flags]

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <memory>

#include "BenchSummary.h"
#include "compiler/driver/Compiler.h"

namespace {

namespace fs = std::filesystem;

const fs::path kShared = MXC_SHARED_DIR;

/// The library and the document, loaded once: every compilation of the benchmark finds the
/// document in the workspace's loader, so what is timed is what comes after parsing.
struct Loaded {
  mxc::Workspace workspace;
  mxc::CompileRequest request;
  explicit Loaded(const fs::path& file) {
    workspace.loadLibraries();
    request.document = file;
    mxc::Compiler(workspace, request).document();
  }
};

const fs::path kDefault = kShared / "corpus/materialx/examples/OpenPbr/open_pbr_default.mtlx";
const fs::path kCarpaint = kShared / "corpus/materialx/examples/OpenPbr/open_pbr_carpaint.mtlx";

void BM_Resolve(benchmark::State& state, const fs::path* file) {
  Loaded loaded(*file);
  for (auto _ : state) {
    mxc::Compiler compiler(loaded.workspace, loaded.request);
    benchmark::DoNotOptimize(compiler.resolved()->materials.size());
  }
}

void BM_LowerAndPasses(benchmark::State& state, const fs::path* file) {
  Loaded loaded(*file);
  for (auto _ : state) {
    // Resolve, lower, the passes to their fixed point and the features (the resolve is the
    // other benchmark: a few per cent of this one).
    mxc::Compiler compiler(loaded.workspace, loaded.request);
    benchmark::DoNotOptimize(compiler.materials().size());
  }
  if (loaded.workspace.diagnostics.hasErrors()) state.SkipWithError("lowering reported errors");
}

BENCHMARK_CAPTURE(BM_Resolve, open_pbr_default, &kDefault)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_LowerAndPasses, open_pbr_default, &kDefault)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Resolve, open_pbr_carpaint, &kCarpaint)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_LowerAndPasses, open_pbr_carpaint, &kCarpaint)->Unit(benchmark::kMicrosecond);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  mxc::bench::SummaryReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf("\nsummary (library loaded, document parsed):\n");
  for (const char* name : {"open_pbr_default", "open_pbr_carpaint"}) {
    const double resolve = reporter.seconds(std::string("BM_Resolve/") + name);
    const double lower = reporter.seconds(std::string("BM_LowerAndPasses/") + name);
    if (resolve > 0 && lower > 0) {
      std::printf("  %-18s resolve + lower + passes %7.1f us   resolve %6.1f us   (%.1fx the resolve)\n", name,
                  lower * 1e6, resolve * 1e6, lower / resolve);
    }
  }
  benchmark::Shutdown();
  return 0;
}
