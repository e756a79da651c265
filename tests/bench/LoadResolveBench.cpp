// Library load and document resolution times: the built-in node library, MaterialX's library
// folder for comparison (same run), and open_pbr_default / a textured Standard Surface
// document resolved against the loaded built-in library.
//
//   build/tests/bench/load_resolve_bench [benchmark flags]

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>

#include "BenchSummary.h"
#include "compiler/document/DocumentLoader.h"
#include "compiler/library/LibraryStack.h"
#include "compiler/resolve/Resolver.h"

namespace {

namespace fs = std::filesystem;

const fs::path kShared = MXC_SHARED_DIR;

void BM_LoadBuiltinLibrary(benchmark::State& state) {
  for (auto _ : state) {
    mxc::SourceManager sources;
    mxc::Diagnostics diagnostics;
    mxc::lib::LibraryStack stack(sources, diagnostics);
    stack.addBuiltin();
    benchmark::DoNotOptimize(stack.top().nodeDefCount());
  }
}

void BM_LoadMaterialXLibraryFolder(benchmark::State& state) {
  for (auto _ : state) {
    mxc::SourceManager sources;
    mxc::Diagnostics diagnostics;
    mxc::lib::LibraryStack stack(sources, diagnostics);
    stack.addFolder(kShared / "reference/materialx/libraries");
    benchmark::DoNotOptimize(stack.top().nodeDefCount());
  }
}

/// Parse + build + resolve one document against an already loaded built-in library.
void resolveDocument(benchmark::State& state, const fs::path& file) {
  mxc::SourceManager librarySources;
  mxc::Diagnostics libraryDiagnostics;
  mxc::lib::LibraryStack stack(librarySources, libraryDiagnostics);
  stack.addBuiltin();
  for (auto _ : state) {
    mxc::SourceManager sources;
    mxc::Diagnostics diagnostics;
    mxc::doc::DocumentLoader loader(sources, diagnostics);
    const mxc::doc::Document* d = loader.loadFile(file);
    auto resolved = mxc::resolve::resolveDocument(*d, stack.top(), diagnostics);
    benchmark::DoNotOptimize(resolved.materials.size());
    if (diagnostics.hasErrors()) state.SkipWithError("document has errors");
  }
}

void BM_ResolveOpenPbrDefault(benchmark::State& state) {
  resolveDocument(state, kShared / "corpus/materialx/examples/OpenPbr/open_pbr_default.mtlx");
}

void BM_ResolveBrickProcedural(benchmark::State& state) {
  resolveDocument(state, kShared / "corpus/materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx");
}

BENCHMARK(BM_LoadBuiltinLibrary)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LoadMaterialXLibraryFolder)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ResolveOpenPbrDefault)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ResolveBrickProcedural)->Unit(benchmark::kMicrosecond);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  mxc::bench::SummaryReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  const double builtin = reporter.seconds("BM_LoadBuiltinLibrary");
  const double materialx = reporter.seconds("BM_LoadMaterialXLibraryFolder");
  const double openpbr = reporter.seconds("BM_ResolveOpenPbrDefault");
  const double brick = reporter.seconds("BM_ResolveBrickProcedural");
  if (builtin > 0 && materialx > 0 && openpbr > 0) {
    std::printf("\nsummary:\n");
    std::printf("  load built-in library (776 nodedefs)        %8.2f ms\n", builtin * 1e3);
    std::printf("  load MaterialX library folder (36 files)    %8.2f ms   (%.2fx the built-in load)\n", materialx * 1e3,
                materialx / builtin);
    std::printf("  open_pbr_default: load + resolve            %8.1f us   (%.3fx the library load)\n", openpbr * 1e6,
                openpbr / builtin);
    if (brick > 0) std::printf("  brick_procedural: load + resolve            %8.1f us\n", brick * 1e6);
    std::printf("  open_pbr_default with its library, cold     %8.2f ms\n", (builtin + openpbr) * 1e3);
  }
  benchmark::Shutdown();
  return 0;
}
