#include "cli/Verbosity.h"

#include <cstdio>

namespace mxc::cli {

namespace {
Verbosity level_ = Verbosity::Normal;
}

Verbosity verbosity() { return level_; }
void setVerbosity(Verbosity level) { level_ = level; }

void detailLine(const std::string& line) { std::fprintf(stderr, "mxc: %s\n", line.c_str()); }

}  // namespace mxc::cli
