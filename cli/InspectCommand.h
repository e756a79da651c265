#pragma once
/// \file
/// `mxc inspect`: what a document holds, resolved against the node libraries.

#include <CLI/CLI.hpp>

namespace mxc::cli {

/// Adds the `inspect` subcommand; `exitCode` receives its result when it runs.
void registerInspect(CLI::App& app, int& exitCode);

}  // namespace mxc::cli
