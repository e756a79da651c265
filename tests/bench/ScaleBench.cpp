// Scaling with graph size: generated documents of 1k, 10k and 100k math nodes feeding an
// open_pbr_surface, timed stage by stage (parse + document model, resolve, lower + passes,
// GLSL, glslang + validation), with the growth from one size to the next (10x more nodes: a
// ratio near 10 is linear) for mxc's own stages, for glslang, and for the whole compile. Then the peak resident memory of the
// `mxc compile` process, for open_pbr_default and for the 100k-node document. Last, a chain of
// documents each including the next (N/4 and N files): loading is linear when the growth is
// near 4. Last, documents of 1k, 10k, ... materials (up to --materials), each its own
// open_pbr_surface, compiled by `mxc compile DOC -o DIR/out.spv` as a user runs it: the time per
// material and its growth (10x the materials: linear near 10), and the peak memory per material.
// Last, `mxc render` of scenes of 1 and of --objects spheres of one material: the peak memory
// each further object takes (its mesh is shared with the others: only its own blocks are not).
//
//   build/tests/bench/scale_bench [--max N] [--no-glslang] [--includes N] [--materials N] [--objects N]
//
// --no-glslang stops after GLSL (glslang's own constant lookup is quadratic in the number of
// distinct literals, which dominates beyond 100k nodes).


#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "compiler/common/LargeStack.h"
#include "compiler/driver/Compiler.h"
#include "ChildProcess.h"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

/// A DAG of `nodes` float nodes: each adds, multiplies or takes the sine of earlier ones, so
/// that nothing folds to a constant or merges as a common subexpression; the last node is the
/// base_weight of an open_pbr_surface. Appended to `out` (a string or a file).
template <typename Out>
void generate(int nodes, Out& out) {
  auto put = [&](const std::string& text) { out += text; };
  put("<?xml version=\"1.0\"?>\n<materialx version=\"1.39\">\n");
  put("  <texcoord name=\"uv\" type=\"vector2\" />\n");
  put("  <extract name=\"n0\" type=\"float\">\n    <input name=\"in\" type=\"vector2\" nodename=\"uv\" />\n"
         "    <input name=\"index\" type=\"integer\" value=\"0\" />\n  </extract>\n");
  for (int i = 1; i < nodes; ++i) {
    switch (i % 3) {
      case 0:
        put(fmt::format("  <add name=\"n{}\" type=\"float\"><input name=\"in1\" type=\"float\" nodename=\"n{}\" />"
                           "<input name=\"in2\" type=\"float\" nodename=\"n{}\" /></add>\n",
                           i, i - 1, i / 2));
        break;
      case 1:
        put(fmt::format("  <multiply name=\"n{}\" type=\"float\"><input name=\"in1\" type=\"float\" nodename=\"n{}\" />"
                           "<input name=\"in2\" type=\"float\" value=\"{}\" /></multiply>\n",
                           i, i - 1, 1.0 + 1e-4 * i));
        break;
      default:
        put(fmt::format("  <sin name=\"n{}\" type=\"float\"><input name=\"in\" type=\"float\" nodename=\"n{}\" /></sin>\n",
                           i, i - 1));
        break;
    }
  }
  put(fmt::format("  <open_pbr_surface name=\"s\" type=\"surfaceshader\">\n"
                     "    <input name=\"base_weight\" type=\"float\" nodename=\"n{}\" />\n  </open_pbr_surface>\n"
                     "  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" "
                     "nodename=\"s\" /></surfacematerial>\n</materialx>\n",
                     nodes - 1));
}

std::string generate(int nodes) {
  std::string out;
  generate(nodes, out);
  return out;
}

/// Writes the generated document for `nodes` to a file, streaming (the bench stays small).
fs::path generateFile(int nodes) {
  const fs::path path = fs::temp_directory_path() / fmt::format("mxc_scale_{}_{}.mtlx", nodes, ::getpid());
  struct File {
    std::ofstream stream;
    File& operator+=(const std::string& text) {
      stream << text;
      return *this;
    }
  } file{std::ofstream(path)};
  generate(nodes, file);
  return path;
}

struct Stages {
  double parse = 0, resolve = 0, lower = 0, glsl = 0, spirv = 0;
  size_t glslLines = 0;
  double ours() const { return parse + resolve + lower + glsl; }
  double total() const { return ours() + spirv; }
};

Stages run(const mxc::lib::LibraryStack& libraries, const std::string& text, bool glslang) {
  Stages s;
  mxc::Workspace workspace;
  mxc::CompileRequest request;
  request.document = "generated.mtlx";
  request.text = text;
  request.libraries = &libraries;
  mxc::Compiler compiler(workspace, request);
  // Stage by stage: each call runs its stage once, on the result of the one before.
  auto t = Clock::now();
  compiler.document();
  s.parse = msSince(t);
  t = Clock::now();
  compiler.resolved();
  s.resolve = msSince(t);
  t = Clock::now();
  std::vector<mxc::ir::Material>& materials = compiler.materials();
  s.lower = msSince(t);
  t = Clock::now();
  mxc::glsl::MaterialShader shader = compiler.shader(materials.at(0));
  s.glsl = msSince(t);
  s.glslLines = shader.glsl.origins.size();
  if (!glslang) return s;
  t = Clock::now();
  auto words = compiler.spirv(shader);
  s.spirv = msSince(t);
  if (!words || workspace.diagnostics.hasErrors()) {
    std::fprintf(stderr, "%s", workspace.diagnostics.format().c_str());
    std::exit(1);
  }
  return s;
}

/// Loads a chain of `files` documents, each including the next, written to a fresh folder;
/// returns the load time in ms.
double includeChainMs(int files) {
  const fs::path folder = fs::temp_directory_path() / fmt::format("mxc_chain_{}_{}", files, ::getpid());
  fs::create_directories(folder);
  for (int i = 0; i < files; ++i) {
    std::ofstream(folder / fmt::format("c{}.mtlx", i))
        << "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
        << (i + 1 < files ? fmt::format("  <xi:include href=\"c{}.mtlx\" />\n", i + 1) : std::string())
        << fmt::format("  <constant name=\"k{}\" type=\"float\" />\n</materialx>\n", i);
  }
  mxc::Workspace workspace;
  mxc::CompileRequest request;
  request.document = folder / "c0.mtlx";
  mxc::Compiler compiler(workspace, request);
  const auto t = Clock::now();
  const bool loaded = compiler.document() != nullptr && workspace.loader.documents().size() == size_t(files);
  const double ms = msSince(t);
  fs::remove_all(folder);
  if (!loaded || workspace.diagnostics.hasErrors()) {
    std::fprintf(stderr, "the include chain did not load: %s", workspace.diagnostics.format().c_str());
    std::exit(1);
  }
  return ms;
}

/// A document of `count` materials, each an open_pbr_surface of its own colour and roughness
/// (distinct values: no two compile to the same shader), written to a file.
fs::path generateMaterials(int count) {
  const fs::path path = fs::temp_directory_path() / fmt::format("mxc_materials_{}_{}.mtlx", count, ::getpid());
  std::ofstream out(path);
  out << "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\">\n";
  for (int i = 0; i < count; ++i) {
    const double t = double(i) / std::max(count, 1);
    out << fmt::format("  <open_pbr_surface name=\"s{0}\" type=\"surfaceshader\">\n"
                       "    <input name=\"base_color\" type=\"color3\" value=\"{1:.6f}, 0.5, {2:.6f}\" />\n"
                       "    <input name=\"specular_roughness\" type=\"float\" value=\"{3:.6f}\" />\n  </open_pbr_surface>\n"
                       "  <surfacematerial name=\"M{0}\" type=\"material\"><input name=\"surfaceshader\" "
                       "type=\"surfaceshader\" nodename=\"s{0}\" /></surfacematerial>\n",
                       i, t, 1.0 - t, 0.1 + 0.8 * t);
  }
  out << "</materialx>\n";
  return path;
}

/// A scene (docs/scenes.md) of `count` unit spheres of open_pbr_default in a square grid, all
/// in view, rendered at 32x32 with 1 sample.
fs::path generateObjects(int count) {
  const fs::path path = fs::temp_directory_path() / fmt::format("mxc_objects_{}_{}.json", count, ::getpid());
  const fs::path document = fs::path(MXC_SHARED_DIR) / "corpus/materialx/examples/OpenPbr/open_pbr_default.mtlx";
  int side = 1;
  while (side * side < count) ++side;
  std::ofstream out(path);
  out << fmt::format("{{\"mxc_scene\": 1, \"documents\": [\"{}\"], \"objects\": [\n", document.string());
  for (int i = 0; i < count; ++i) {
    out << fmt::format("  {{\"name\": \"o{}\", \"mesh\": \"sphere\", \"material\": \"Default\", \"translate\": [{}, {}, 0]}}{}\n", i,
                       2.5 * (i % side - 0.5 * (side - 1)), 2.5 * (i / side - 0.5 * (side - 1)), i + 1 < count ? "," : "");
  }
  out << fmt::format("], \"environment\": {{\"type\": \"sky\"}}, \"camera\": {{\"position\": [0, 0, {}], \"target\": [0, 0, 0], "
                     "\"fov\": 40}}, \"render\": {{\"size\": [32, 32], \"spp\": 1}}}}\n",
                     4.0 + 3.5 * side);
  return path;
}

/// Peak resident memory (MiB) of `mxc compile FILE -q`, from the kernel's accounting.
double peakMiB(const fs::path& file) {
  const mxc::bench::ChildRun run = mxc::bench::runChild(MXC_BINARY, {"compile", "-q", file.string()}, true);
  return run.ok ? run.peakMiB : -1.0;
}

}  // namespace

int main(int argc, char** argv) {
  int max = 100000;
  for (int i = 1; i + 1 < argc; ++i) {
    if (!std::strcmp(argv[i], "--max")) max = std::atoi(argv[i + 1]);
  }
  bool glslang = true;
  int includes = 40000;
  int materials = 10000;
  int objects = 10000;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--objects") && i + 1 < argc) objects = std::max(2, std::atoi(argv[i + 1]));
    if (!std::strcmp(argv[i], "--no-glslang")) glslang = false;
    if (!std::strcmp(argv[i], "--includes") && i + 1 < argc) includes = std::max(4, std::atoi(argv[i + 1]));
    if (!std::strcmp(argv[i], "--materials") && i + 1 < argc) materials = std::atoi(argv[i + 1]);
  }
  // Memory first, while this process is small: a child's peak counts the pages it had from
  // fork until exec.
  const fs::path openPbr = fs::path(MXC_SHARED_DIR) / "corpus/materialx/examples/OpenPbr/open_pbr_default.mtlx";
  const fs::path largest = generateFile(max);
  const double openPbrPeak = peakMiB(openPbr);
  const double largestPeak = peakMiB(largest);
  fs::remove(largest);

  mxc::runWithLargeStack([&] {
    mxc::Workspace library;
    library.loadLibraries();
    std::printf("%8s %9s %9s %9s %9s %10s %8s %10s %8s %10s %8s %8s\n", "nodes", "parse", "resolve", "lower", "glsl",
                "mxc", "growth", "glslang", "growth", "total", "growth", "lines");
    Stages previous;
    for (int nodes = 1000; nodes <= max; nodes *= 10) {
      const Stages s = run(library.libraries, generate(nodes), glslang);
      auto growth = [&](double now, double before) {
        return before > 0 ? fmt::format("{:.1f}x", now / before) : std::string("-");
      };
      std::printf("%8d %7.1fms %7.1fms %7.1fms %7.1fms %8.1fms %8s %8.1fms %8s %8.1fms %8s %8zu\n", nodes, s.parse,
                  s.resolve, s.lower, s.glsl, s.ours(), growth(s.ours(), previous.ours()).c_str(), s.spirv,
                  growth(s.spirv, previous.spirv).c_str(), s.total(), growth(s.total(), previous.total()).c_str(),
                  s.glslLines);
      previous = s;
    }
    // Each include is one deeper on the loader's recursion: the large stack holds the chain.
    const double quarter = includeChainMs(includes / 4), whole = includeChainMs(includes);
    std::printf("\ninclude chain of %d / %d documents: %.1f / %.1f ms to load (growth %.1fx for 4x the files; linear is 4)\n",
                includes / 4, includes, quarter, whole, whole / quarter);
  });
  std::printf("\npeak resident memory of `mxc compile` (one process, library, glslang and SPIRV-Tools included):\n");
  std::printf("  %-28s %8.1f MiB   (target: at most 48 MiB)\n", "open_pbr_default.mtlx", openPbrPeak);
  std::printf("  %-28s %8.1f MiB   (target: under 1 GiB)\n", fmt::format("{} generated nodes", max).c_str(), largestPeak);

  // Many materials, one process: `mxc compile DOC -o DIR/out.spv` (DIR/out_<material>.spv each).
  std::printf("\n%10s %10s %14s %8s %10s %14s\n", "materials", "wall", "per material", "growth", "peak", "per material");
  double previous = 0.0;
  for (int count = 1000; count <= materials; count *= 10) {
    const fs::path document = generateMaterials(count);
    const fs::path folder = fs::temp_directory_path() / fmt::format("mxc_materials_out_{}_{}", count, ::getpid());
    fs::create_directories(folder);
    const mxc::bench::ChildRun run =
        mxc::bench::runChild(MXC_BINARY, {"compile", "-q", document.string(), "-o", (folder / "out.spv").string()}, true);
    size_t written = 0;
    for (const auto& e : fs::directory_iterator(folder)) {
      written += e.path().extension() == ".spv" && e.path().stem().extension() != ".vert";
    }
    fs::remove_all(folder);
    fs::remove(document);
    if (!run.ok || written < size_t(count)) {
      std::fprintf(stderr, "compiling %d materials failed (%zu shaders written)\n", count, written);
      return 1;
    }
    const double perMaterial = 1000.0 * run.seconds / count;
    std::printf("%10d %8.1f s %11.3f ms %8s %7.0f MiB %11.1f KiB\n", count, run.seconds, perMaterial,
                previous > 0 ? fmt::format("{:.1f}x", run.seconds / previous).c_str() : "-", run.peakMiB,
                1024.0 * run.peakMiB / count);
    previous = run.seconds;
  }

  // Many objects of one material and one mesh: `mxc render SCENE -o out.png`.
  std::printf("\n%10s %10s %10s %14s\n", "objects", "wall", "peak", "per object");
  double onePeak = 0.0;
  for (const int count : {1, objects}) {
    const fs::path scene = generateObjects(count);
    const fs::path image = fs::temp_directory_path() / fmt::format("mxc_objects_{}_{}.png", count, ::getpid());
    const mxc::bench::ChildRun run = mxc::bench::runChild(MXC_BINARY, {"render", scene.string(), "-o", image.string()}, true);
    const bool written = fs::exists(image);
    fs::remove(scene);
    fs::remove(image);
    if (!run.ok || !written) {
      std::fprintf(stderr, "rendering %d objects failed\n", count);
      return 1;
    }
    if (count == 1) onePeak = run.peakMiB;
    std::printf("%10d %8.1f s %6.0f MiB %11s\n", count, run.seconds, run.peakMiB,
                count == 1 ? "-" : fmt::format("{:.1f} KiB", 1024.0 * (run.peakMiB - onePeak) / (count - 1)).c_str());
  }
  return 0;
}
