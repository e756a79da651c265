#pragma once
/// \file
/// `mxc compile`: materials to GLSL and SPIR-V.

#include <CLI/CLI.hpp>

namespace mxc::cli {

void registerCompile(CLI::App& app, int& exitCode);

}  // namespace mxc::cli
