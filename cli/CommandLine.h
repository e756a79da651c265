#pragma once
/// \file
/// The command line of mxc (cli/CommandLine.cpp): parses it and runs the command it names.

namespace mxc::cli {

/// Parses the arguments, runs the command, and returns its exit code (cli/ExitCode.h); --help
/// and usage errors are printed here.
int runCommandLine(int argc, char** argv);

}  // namespace mxc::cli
