#include "compiler/target/NagaTranslator.h"

#include <cstdlib>
#include <fstream>
#include <string_view>

#include <fmt/format.h>

#include "compiler/common/ChildProcess.h"
#include "compiler/spirv/SpirvCompiler.h"

namespace mxc::target {

namespace fs = std::filesystem;

namespace {

/// naga's output without its warnings about decorations it ignores (NoContraction: WGSL has no
/// way to say it), which every module of mxc's has.
std::string meaningful(const std::string& output) {
  std::string out;
  size_t start = 0;
  while (start < output.size()) {
    size_t end = output.find('\n', start);
    if (end == std::string::npos) end = output.size();
    const std::string line = output.substr(start, end - start);
    start = end + 1;
    if (line.find("Unknown decoration NoContraction") != std::string::npos || line.empty()) continue;
    out += (out.empty() ? "" : "\n") + line;
  }
  return out;
}

}  // namespace

fs::path nagaProgram() {
  const char* chosen = std::getenv("MXC_NAGA");
  if (chosen && *chosen) return findProgram(chosen);
  if (fs::path onPath = findProgram("naga"); !onPath.empty()) return onPath;
  // Where the build found it (scripts/setup installs it in cargo's folder, often not on PATH).
  return std::string_view(MXC_NAGA_PROGRAM).empty() ? fs::path() : findProgram(MXC_NAGA_PROGRAM);
}

std::string nagaVersion() {
  const fs::path naga = nagaProgram();
  if (naga.empty()) return "naga: not found (the WGSL target needs it; scripts/setup installs it)";
  std::string error;
  TemporaryFolder folder(error);
  if (folder.path().empty()) return "naga " + naga.string() + ": " + error;
  auto run = runProcess({naga.string(), "--version"}, folder.path(), error);
  if (!run || run->exitCode != 0) return "naga " + naga.string() + ": does not run";
  std::string version = run->output;
  while (!version.empty() && (version.back() == '\n' || version.back() == '\r')) version.pop_back();
  return fmt::format("naga {} ({})", version, naga.string());
}

bool nagaTranslate(const std::vector<uint32_t>& words, Translation& out, std::string& error) {
  const fs::path naga = nagaProgram();
  if (naga.empty()) {
    error = "the WGSL target needs naga (wgpu's shader translator), which is not on PATH: install it with "
            "`cargo install naga-cli --version 30.0.1 --locked` (scripts/setup does), or name it with MXC_NAGA";
    return false;
  }
  std::optional<std::vector<uint32_t>> frozen = spirv::freezeSpecialization(words, error);
  if (!frozen) return false;
  TemporaryFolder folder(error);
  if (folder.path().empty()) return false;
  const fs::path input = folder.path() / "shader.spv", output = folder.path() / "shader.wgsl";
  {
    std::ofstream file(input, std::ios::binary);
    file.write(reinterpret_cast<const char*>(frozen->data()), static_cast<std::streamsize>(frozen->size() * 4));
    if (!file.flush()) {
      error = "cannot write " + input.string();
      return false;
    }
  }
  auto run = runProcess({naga.string(), input.string(), output.string()}, folder.path(), error);
  if (!run) return false;
  if (run->exitCode != 0) {
    error = fmt::format("naga ({}) cannot translate the shader to WGSL: {}", naga.string(), meaningful(run->output));
    return false;
  }
  std::ifstream file(output, std::ios::binary);
  out.text.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
  if (out.text.empty()) {
    error = fmt::format("naga ({}) wrote no WGSL: {}", naga.string(), meaningful(run->output));
    return false;
  }
  // The WGSL read back by naga's own front end and validator: what a WebGPU implementation does
  // with it first.
  auto check = runProcess({naga.string(), output.string()}, folder.path(), error);
  if (!check) return false;
  if (check->exitCode != 0) {
    error = fmt::format("the WGSL naga wrote does not validate: {}", meaningful(check->output));
    return false;
  }
  out.entryPoint = "main";  // naga keeps the SPIR-V entry point's name
  return true;
}

}  // namespace mxc::target
