#pragma once
/// \file
/// The exit codes of mxc, as documented in README.md.

namespace mxc::cli {

enum ExitCode : int {
  kOk = 0,               ///< success (warnings may have been printed)
  kInvalidDocument = 1,  ///< the document or a library has errors (printed with file:line:column)
  kUsage = 2,            ///< bad command line
  kOutputFailed = 3,     ///< an output could not be written (nothing partial is left behind)
  kOutOfMemory = 4,      ///< memory ran out (nothing partial is left behind)
  kNoDevice = 5,         ///< no usable Vulkan device (none, none matching --device, or it failed to start)
};

}  // namespace mxc::cli
