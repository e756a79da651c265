#pragma once
/// \file
/// SPIR-V to WGSL with naga, wgpu's shader translator (the `naga` program of naga-cli 30,
/// installed by scripts/setup with cargo; MXC_NAGA names another).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "compiler/target/CrossCompiler.h"

namespace mxc::target {

/// The naga program used: $MXC_NAGA, else `naga` on PATH, else the one the build found; empty
/// when there is none.
std::filesystem::path nagaProgram();

/// "naga 30.0.1 (/path/to/naga)", or a line saying none was found, for `mxc --version`.
std::string nagaVersion();

/// Translates a validated module to WGSL. The module must have been built with separate
/// samplers (glsl::BuildOptions::separateSamplers): WGSL has no combined image sampler. Its
/// specialization constants are fixed at their defaults first (naga reads no expression of
/// them); mxc's defaults read the values from the uniform block at run time. naga validates the
/// module it translates, and the WGSL it wrote is read back and validated again.
bool nagaTranslate(const std::vector<uint32_t>& words, Translation& out, std::string& error);

}  // namespace mxc::target
