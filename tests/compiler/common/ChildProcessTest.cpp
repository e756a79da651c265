// A spawned program starts with no signal blocked and default dispositions, whatever mxc itself
// blocks (cli/ProcessSetup.h blocks its termination signals in every thread): a child that
// inherited them outlived an interrupted mxc.

#include "compiler/common/ChildProcess.h"

#include <gtest/gtest.h>
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <filesystem>

namespace mxc {
namespace {

TEST(ChildProcess, StartsWithNoSignalBlockedOrIgnored) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("mxc_child_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  sigset_t blocked, previous;
  sigemptyset(&blocked);
  sigaddset(&blocked, SIGINT);
  sigaddset(&blocked, SIGTERM);
  sigaddset(&blocked, SIGPIPE);
  ASSERT_EQ(pthread_sigmask(SIG_BLOCK, &blocked, &previous), 0);
  void (*xfsz)(int) = ::signal(SIGXFSZ, SIG_IGN);
  std::string error;
  // /proc/self/status of the child: SigBlk and SigIgn as hexadecimal masks.
  auto result = runProcess({"grep", "-E", "^Sig(Blk|Ign)", "/proc/self/status"}, folder, error);
  ::signal(SIGXFSZ, xfsz);
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  std::filesystem::remove_all(folder);
  ASSERT_TRUE(result) << error;
  EXPECT_EQ(result->exitCode, 0) << result->output;
  EXPECT_NE(result->output.find("SigBlk:\t0000000000000000"), std::string::npos) << result->output;
  // SIGXFSZ is signal 25: bit 24 of SigIgn.
  const size_t ignored = result->output.find("SigIgn:\t");
  ASSERT_NE(ignored, std::string::npos) << result->output;
  const unsigned long long mask = std::stoull(result->output.substr(ignored + 8, 16), nullptr, 16);
  EXPECT_EQ(mask & (1ull << (SIGXFSZ - 1)), 0u) << result->output;
}

}  // namespace
}  // namespace mxc
