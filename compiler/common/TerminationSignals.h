#pragma once
/// \file
/// The signals that end a process by default and come from outside it (kill, a terminal, a
/// timer, a closed pipe): mxc takes them on one thread to remove its temporaries
/// (cli/ProcessSetup.h), and gives the programs it runs their default handling back
/// (compiler/common/ChildProcess.h).

#include <signal.h>

namespace mxc {

inline constexpr int kTerminationSignals[] = {SIGINT, SIGTERM, SIGHUP,    SIGQUIT, SIGUSR1,
                                              SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF, SIGPIPE};

}  // namespace mxc
