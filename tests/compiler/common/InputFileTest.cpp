// compiler/common/InputFile: only regular files are read, and nothing blocks.

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

#include "compiler/common/InputFile.h"

namespace mxc {
namespace {

namespace fs = std::filesystem;

std::string problem(const fs::path& p, size_t limit = 1 << 20) {
  auto r = readInputFile(p, limit);
  return r.index() == 1 ? std::get<1>(r) : "";
}

TEST(InputFile, RefusesWhatIsNotARegularFile) {
  const fs::path folder = fs::temp_directory_path() / ("mxc_input_test_" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder);
  const fs::path fifo = folder / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // A FIFO with no writer: reading it would wait forever; it is refused at once.
  EXPECT_EQ(problem(fifo), "it is a FIFO (named pipe), not a regular file");
  EXPECT_EQ(problem("/dev/zero"), "it is a character device, not a regular file");
  EXPECT_EQ(problem(folder), "it is a directory, not a file");
  EXPECT_EQ(problem(folder / "missing"), "it does not exist");
  EXPECT_EQ(inputFileProblem(fifo), "it is a FIFO (named pipe), not a regular file");
  EXPECT_EQ(inputFileProblem(folder / "missing"), "it does not exist");
  std::ofstream(folder / "ten") << "0123456789";
  EXPECT_EQ(inputFileProblem(folder / "ten"), std::nullopt);
  auto ok = readInputFile(folder / "ten", 10);
  ASSERT_EQ(ok.index(), 0u);
  EXPECT_EQ(std::get<0>(ok), "0123456789");
  EXPECT_EQ(problem(folder / "ten", 9), "it is 10 bytes, above the limit of 9 bytes");
  fs::remove_all(folder);
}

}  // namespace
}  // namespace mxc
