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
/// - SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF and
///   SIGPIPE are blocked in every thread and taken by one thread that removes the registered
///   temporary files (mxc::TemporaryFiles, waiting for a commit under way) and then ends the
///   process by the same signal; a write to a closed pipe fails with EPIPE instead;
/// - 64 MB of address space is held back for the unwinding of an out-of-memory error, and given
///   back at the first failed allocation, which then throws std::bad_alloc (exit 4).
void setUpProcess();

/// Call last in main: flushes standard output. False (with a message on stderr) when anything
/// written to it was lost (a full disk, a closed stream), which makes the exit code 3.
bool flushStandardOutput();

}  // namespace mxc::cli
