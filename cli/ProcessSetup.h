#pragma once
/// \file
/// What the mxc process sets up before a command runs, so that its outputs stay whole whatever
/// happens to the process: termination signals, over-size writes and closed standard streams.

namespace mxc::cli {

/// Call first in main, before any thread starts:
/// - standard input, output and error that were closed are reopened on /dev/null (output
///   read-only, so a write to it fails and is reported) so no file mxc opens takes their numbers;
/// - SIGXFSZ is ignored: a write past the file-size limit fails with EFBIG and is reported
///   instead of killing the process with a half-written file;
/// - SIGINT, SIGTERM and SIGHUP are blocked in every thread and taken by one thread that removes
///   the registered temporary files (mxc::TemporaryFiles, waiting for a commit under way) and
///   then ends the process by the same signal.
void setUpProcess();

/// Call last in main: flushes standard output. False (with a message on stderr) when anything
/// written to it was lost (a full disk, a closed stream), which makes the exit code 3.
bool flushStandardOutput();

}  // namespace mxc::cli
