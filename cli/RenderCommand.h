#pragma once
/// \file
/// `mxc render`: materials on a sphere (or a plane, or an OBJ mesh) to EXR or PNG.

#include <CLI/CLI.hpp>

namespace mxc::cli {

void registerRender(CLI::App& app, int& exitCode);

}  // namespace mxc::cli
