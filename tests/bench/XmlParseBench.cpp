// Parser throughput: parses a generated MaterialX-like document (50 MB by default) and
// prints MB/s, against memchr scanning the same bytes for '<' as the baseline measured in
// the same run (the least work any XML parser must do).
//
//   build/tests/bench/xml_parse_bench [--size-mb=N] [benchmark flags]

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "BenchSummary.h"
#include "compiler/document/DocumentBuilder.h"
#include "compiler/xml/XmlParser.h"

namespace {

size_t sizeMB = 50;

/// A document shaped like MaterialX files: node graphs of nodes with typed inputs, comments,
/// entities and both quote styles, repeated to `bytes`.
std::string generateDocument(size_t bytes) {
  std::string text = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<materialx version=\"1.39\" colorspace=\"lin_rec709\">\n";
  text.reserve(bytes + 4096);
  for (size_t graph = 0; text.size() < bytes; ++graph) {
    text += "  <!-- graph " + std::to_string(graph) + ": generated &amp; repeated -->\n";
    text += "  <nodegraph name=\"NG_" + std::to_string(graph) + "\">\n";
    text += "    <input name=\"tint\" type=\"color3\" value=\"0.8, 0.6, 0.4\" uiname=\"Tint &amp; Shade\" />\n";
    for (int node = 0; node < 40; ++node) {
      std::string n = std::to_string(node);
      text += "    <multiply name=\"mul_" + n + "\" type=\"color3\">\n";
      text += "      <input name=\"in1\" type=\"color3\" " +
              (node ? "nodename=\"mul_" + std::to_string(node - 1) + "\"" : std::string("interfacename=\"tint\"")) +
              " />\n";
      text += "      <input name='in2' type='float' value='0." + n + "5' />\n";
      text += "    </multiply>\n";
    }
    text += "    <output name=\"out\" type=\"color3\" nodename=\"mul_39\" />\n  </nodegraph>\n";
  }
  text += "</materialx>\n";
  return text;
}

const mxc::SourceFile& source() {
  static mxc::SourceFile file("generated.mtlx", generateDocument(sizeMB << 20));
  return file;
}

void BM_MemchrBaseline(benchmark::State& state) {
  std::string_view text = source().text();
  for (auto _ : state) {
    size_t count = 0;
    for (const char* p = text.data(); (p = static_cast<const char*>(std::memchr(p, '<', text.data() + text.size() - p)));
         ++p) {
      ++count;
    }
    benchmark::DoNotOptimize(count);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}

void BM_ParseXml(benchmark::State& state) {
  for (auto _ : state) {
    mxc::xml::Document d = mxc::xml::parse(source());
    benchmark::DoNotOptimize(d.nodeCount());
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * source().text().size()));
}

void BM_ParseXmlAndBuildModel(benchmark::State& state) {
  for (auto _ : state) {
    mxc::Diagnostics diagnostics;
    auto d = mxc::doc::buildDocument(mxc::xml::parse(source()), diagnostics);
    benchmark::DoNotOptimize(d->nodegraphs.size());
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * source().text().size()));
}

BENCHMARK(BM_MemchrBaseline)->Unit(benchmark::kMillisecond)->MinTime(0.5);
BENCHMARK(BM_ParseXml)->Unit(benchmark::kMillisecond)->MinTime(0.5);
BENCHMARK(BM_ParseXmlAndBuildModel)->Unit(benchmark::kMillisecond)->MinTime(0.5);

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--size-mb=", 10) == 0) sizeMB = std::stoul(argv[i] + 10);
  }
  benchmark::Initialize(&argc, argv);
  std::printf("document: %.1f MB generated\n", static_cast<double>(source().text().size()) / (1 << 20));
  mxc::bench::SummaryReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  const double mb = static_cast<double>(source().text().size()) / 1e6;
  const double baseline = reporter.seconds("BM_MemchrBaseline");
  const double parse = reporter.seconds("BM_ParseXml");
  const double model = reporter.seconds("BM_ParseXmlAndBuildModel");
  if (baseline > 0 && parse > 0 && model > 0) {
    std::printf("\nsummary (%.0f MB):\n", mb);
    std::printf("  memchr baseline        %8.0f MB/s\n", mb / baseline);
    std::printf("  XML parse              %8.0f MB/s   (%.1fx the baseline's time)\n", mb / parse, parse / baseline);
    std::printf("  XML parse + model      %8.0f MB/s   (%.1fx the baseline's time)\n", mb / model, model / baseline);
  }
  benchmark::Shutdown();
  return 0;
}
