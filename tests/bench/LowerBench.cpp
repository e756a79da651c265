// Lowering time: open_pbr_surface documents lowered to the slab IR and run through the passes,
// with the library loaded and the document resolved beforehand; the resolve of the same
// document is the baseline measured in the same run.
//
//   build/tests/bench/lower_bench [benchmark flags]

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <memory>

#include "BenchSummary.h"
#include "compiler/document/DocumentLoader.h"
#include "compiler/ir/Effects.h"
#include "compiler/ir/passes/Pass.h"
#include "compiler/library/LibraryStack.h"
#include "compiler/lower/Lowering.h"
#include "compiler/resolve/Resolver.h"

namespace {

namespace fs = std::filesystem;

const fs::path kShared = MXC_SHARED_DIR;

/// A loaded library and document, kept for the whole benchmark.
struct Loaded {
  mxc::SourceManager sources;
  mxc::Diagnostics diagnostics;
  mxc::lib::LibraryStack stack{sources, diagnostics};
  mxc::doc::DocumentLoader loader{sources, diagnostics};
  const mxc::doc::Document* document = nullptr;

  explicit Loaded(const fs::path& file) {
    stack.addBuiltin();
    document = loader.loadFile(file);
  }
};

const fs::path kDefault = kShared / "corpus/materialx/examples/OpenPbr/open_pbr_default.mtlx";
const fs::path kCarpaint = kShared / "corpus/materialx/examples/OpenPbr/open_pbr_carpaint.mtlx";

void BM_Resolve(benchmark::State& state, const fs::path* file) {
  Loaded loaded(*file);
  for (auto _ : state) {
    mxc::Diagnostics diagnostics;
    auto resolved = mxc::resolve::resolveDocument(*loaded.document, loaded.stack.top(), diagnostics);
    benchmark::DoNotOptimize(resolved.materials.size());
  }
}

void BM_LowerAndPasses(benchmark::State& state, const fs::path* file) {
  Loaded loaded(*file);
  mxc::Diagnostics diagnostics;
  auto resolved = mxc::resolve::resolveDocument(*loaded.document, loaded.stack.top(), diagnostics);
  for (auto _ : state) {
    std::vector<mxc::ir::Material> materials = mxc::lower::lowerDocument(resolved, {}, diagnostics);
    for (mxc::ir::Material& m : materials) {
      mxc::ir::runPasses(m);
      mxc::ir::summarizeEffects(m);
    }
    benchmark::DoNotOptimize(materials.size());
  }
  if (diagnostics.hasErrors()) state.SkipWithError("lowering reported errors");
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
      std::printf("  %-18s lower + passes %7.1f us   resolve %6.1f us   (lowering takes %.1fx the resolve)\n", name,
                  lower * 1e6, resolve * 1e6, lower / resolve);
    }
  }
  benchmark::Shutdown();
  return 0;
}
