// Start-up and scale of `mxc render`, as a user meets them: whole processes of the built mxc,
// timed from fork to exit, with their peak resident memory from the kernel (wait4).
//
//   1. the floor: `mxc compile` of one material (no device, no image module), the baseline
//      every other figure is a ratio to;
//   2. the first frame: `mxc render` of one material, 64x64, 1 spp;
//   3. scale: a scene of 1 and of N corpus materials (one sphere each, analytic sky), at the
//      issue's 256x256 and 16 spp; each further material costs (T_N - T_1) / (N - 1) seconds
//      and (M_N - M_1) / (N - 1) MiB.
//
// Each run is repeated (--repeat, default 3) and the median kept: a shared machine's noise is
// tens of percent. The targets (issue 14) are printed beside the figures, not asserted.
//
//   build/tests/bench/startup_bench [--repeat N] [--materials N] [--size N] [--spp N] [--mxc PATH]
//
// --mxc measures another build of mxc (an older commit's, for a before-and-after).


#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "ChildProcess.h"

namespace {

namespace fs = std::filesystem;

const char* mxcBinary = MXC_BINARY;

struct Run {
  double seconds = 0.0;
  double mib = 0.0;  ///< peak resident set
};

/// One mxc process with `args`; its output is discarded. Exits the benchmark when it fails.
Run runMxc(const std::vector<std::string>& args) {
  const mxc::bench::ChildRun run = mxc::bench::runChild(mxcBinary, args);
  if (!run.ok) {
    std::string line = "mxc";
    for (const std::string& a : args) line += " " + a;
    std::fprintf(stderr, "startup_bench: failed: %s\n", line.c_str());
    std::exit(1);
  }
  return {run.seconds, run.peakMiB};
}

/// The median run of `repeat` (by time; memory of the same run's median, separately).
Run median(const std::vector<std::string>& args, int repeat) {
  std::vector<double> seconds, mib;
  for (int r = 0; r < repeat; ++r) {
    const Run run = runMxc(args);
    seconds.push_back(run.seconds);
    mib.push_back(run.mib);
  }
  std::sort(seconds.begin(), seconds.end());
  std::sort(mib.begin(), mib.end());
  return {seconds[seconds.size() / 2], mib[mib.size() / 2]};
}

/// The corpus documents of the scale scene: materials of distinct names, with and without
/// textures and procedurals (the chess set's mix).
std::vector<fs::path> scaleDocuments(size_t count) {
  const fs::path examples = fs::path(MXC_SHARED_DIR) / "corpus/materialx/examples";
  const char* names[] = {
      "StandardSurface/standard_surface_brick_procedural", "StandardSurface/standard_surface_carpaint",
      "StandardSurface/standard_surface_chrome",           "StandardSurface/standard_surface_copper",
      "StandardSurface/standard_surface_default",          "StandardSurface/standard_surface_glass",
      "StandardSurface/standard_surface_gold",             "StandardSurface/standard_surface_jade",
      "StandardSurface/standard_surface_marble_solid",     "StandardSurface/standard_surface_metal_brushed",
      "StandardSurface/standard_surface_plastic",          "StandardSurface/standard_surface_velvet",
      "StandardSurface/standard_surface_wood_tiled",       "OpenPbr/open_pbr_pearl",
      "OpenPbr/open_pbr_aluminum_brushed"};
  std::vector<fs::path> out;
  for (size_t i = 0; i < std::min(count, std::size(names)); ++i) out.push_back(examples / (std::string(names[i]) + ".mtlx"));
  return out;
}

/// The name of the (one) surface material of a corpus document.
std::string materialName(const fs::path& document) {
  std::ifstream in(document);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string tag = "<surfacematerial name=\"";
  const size_t at = text.find(tag);
  if (at == std::string::npos) {
    std::fprintf(stderr, "startup_bench: no surfacematerial in %s\n", document.c_str());
    std::exit(1);
  }
  const size_t begin = at + tag.size();
  return text.substr(begin, text.find('"', begin) - begin);
}

/// A scene (docs/scenes.md) of the first `count` scale documents, one sphere each in a grid.
fs::path writeScene(const fs::path& folder, size_t count, int size, int spp) {
  const std::vector<fs::path> documents = scaleDocuments(count);
  std::string json = "{\n  \"mxc_scene\": 1,\n  \"documents\": [";
  for (size_t i = 0; i < documents.size(); ++i) json += (i ? ", \"" : "\"") + documents[i].string() + "\"";
  json += "],\n  \"objects\": [\n";
  for (size_t i = 0; i < documents.size(); ++i) {
    char line[512];
    std::snprintf(line, sizeof line, "    {\"name\": \"o%zu\", \"mesh\": \"sphere\", \"material\": \"%s\", \"translate\": [%.1f, %.1f, 0]}%s\n",
                  i, materialName(documents[i]).c_str(), double(i % 5) * 2.2 - 4.4, double(i / 5) * 2.2 - 2.2,
                  i + 1 < documents.size() ? "," : "");
    json += line;
  }
  char tail[256];
  std::snprintf(tail, sizeof tail,
                "  ],\n  \"environment\": {\"type\": \"sky\"},\n  \"camera\": {\"position\": [0, 0, 14], \"target\": [0, 0, 0], "
                "\"fov\": 40},\n  \"render\": {\"size\": [%d, %d], \"spp\": %d}\n}\n",
                size, size, spp);
  json += tail;
  const fs::path path = folder / ("scene_" + std::to_string(count) + ".json");
  std::ofstream(path) << json;
  return path;
}

const char* verdict(bool met) { return met ? "met" : "NOT met"; }

}  // namespace

int main(int argc, char** argv) {
  int repeat = 3, materials = 15, size = 256, spp = 16;
  for (int i = 1; i + 1 < argc; ++i) {
    if (!std::strcmp(argv[i], "--repeat")) repeat = std::max(1, std::atoi(argv[i + 1]));
    if (!std::strcmp(argv[i], "--materials")) materials = std::clamp(std::atoi(argv[i + 1]), 2, 15);
    if (!std::strcmp(argv[i], "--size")) size = std::clamp(std::atoi(argv[i + 1]), 8, 4096);
    if (!std::strcmp(argv[i], "--spp")) spp = std::max(1, std::atoi(argv[i + 1]));
    if (!std::strcmp(argv[i], "--mxc")) mxcBinary = argv[i + 1];
  }
  const fs::path folder = fs::temp_directory_path() / ("mxc_startup_bench_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const std::string one = (fs::path(MXC_SHARED_DIR) / "corpus/materialx/examples/OpenPbr/open_pbr_default.mtlx").string();
  const std::string png = (folder / "out.png").string();

  const Run floor = median({"compile", "-q", one, "-o", (folder / "out.spv").string()}, repeat);
  const Run first = median({"render", one, "-o", png, "--size", "64", "--spp", "1"}, repeat);
  const fs::path sceneOne = writeScene(folder, 1, size, spp);
  const fs::path sceneMany = writeScene(folder, size_t(materials), size, spp);
  const Run single = median({"render", sceneOne.string(), "-o", png}, repeat);
  const Run many = median({"render", sceneMany.string(), "-o", png}, repeat);
  fs::remove_all(folder);

  const double perSeconds = (many.seconds - single.seconds) / double(materials - 1);  // materials >= 2
  const double perMib = (many.mib - single.mib) / double(materials - 1);
  std::printf("mxc start-up and scale: %s (median of %d runs; whole processes, fork to exit)\n\n", mxcBinary, repeat);
  std::printf("%-52s %9s %9s %10s\n", "", "seconds", "peak MiB", "x floor");
  std::printf("%-52s %9.2f %9.0f %10s\n", "floor: mxc compile, one material", floor.seconds, floor.mib, "1.0");
  std::printf("%-52s %9.2f %9.0f %10.1f\n", "first frame: mxc render, one material, 64x64, 1 spp", first.seconds,
              first.mib, first.seconds / floor.seconds);  // the floor's run takes > 0 s
  char label[96];
  std::snprintf(label, sizeof label, "scene of 1 material, %dx%d, %d spp", size, size, spp);
  std::printf("%-52s %9.2f %9.0f %10.1f\n", label, single.seconds, single.mib, single.seconds / floor.seconds);
  std::snprintf(label, sizeof label, "scene of %d materials, %dx%d, %d spp", materials, size, size, spp);
  std::printf("%-52s %9.2f %9.0f %10.1f\n", label, many.seconds, many.mib, many.seconds / floor.seconds);
  std::printf("%-52s %9.2f %9.0f\n\n", "each further material", perSeconds, perMib);
  std::printf("targets (issue 14): first frame <= 0.5 s: %s; each further material <= 0.3 s: %s, <= 50 MB: %s",
              verdict(first.seconds <= 0.5), verdict(perSeconds <= 0.3), verdict(perMib * 1.048576 <= 50.0));
  if (materials == 15 && size == 256 && spp == 16) std::printf("; 15 materials < 10 s: %s", verdict(many.seconds < 10.0));
  std::printf("\n");
  return 0;
}
