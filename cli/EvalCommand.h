#pragma once
/// \file
/// `mxc eval` (f cos for direction pairs) and `mxc furnace` (directional albedo), on the device.

#include <CLI/CLI.hpp>

namespace mxc::cli {

void registerEval(CLI::App& app, int& exitCode);
void registerFurnace(CLI::App& app, int& exitCode);

}  // namespace mxc::cli
