#pragma once
/// \file
/// `mxc compile` of many documents in one process: folders (every .mtlx under them), documents
/// and scenes given together. The libraries are loaded once and shared; -j workers compile the
/// documents at once (glslang's symbol tables are built once for the process); each document's
/// outputs go under `-o DIR` as DIR/<document>/<material>.spv, committed together or not at
/// all; a failing document is reported and the run goes on; a progress bar, then a summary,
/// and exit 1 when any document failed.

#include "cli/CompileCommand.h"

namespace mxc::cli {

/// True when `options` asks for a batch: more than one file, or a folder.
bool isBatch(const CompileOptions& options);

int runCompileBatch(const CompileOptions& options);

}  // namespace mxc::cli
