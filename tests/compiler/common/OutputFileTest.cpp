// compiler/common/OutputFile: where an output path leads, staging, and what a failure leaves.

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

#include "compiler/common/OutputFile.h"

namespace mxc {
namespace {

namespace fs = std::filesystem;

struct Folder {
  fs::path path = fs::temp_directory_path() / ("mxc_output_test_" + std::to_string(::getpid()));
  Folder() {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~Folder() { fs::remove_all(path); }
  size_t count() const { return static_cast<size_t>(std::distance(fs::directory_iterator(path), fs::directory_iterator())); }
};

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

OutputTarget resolved(const fs::path& p) {
  auto r = resolveOutput(p);
  EXPECT_TRUE(std::holds_alternative<OutputTarget>(r)) << std::get<std::string>(r);
  return std::holds_alternative<OutputTarget>(r) ? std::get<OutputTarget>(r) : OutputTarget{};
}

TEST(OutputFile, ResolvesKinds) {
  Folder f;
  EXPECT_EQ(resolved("-").kind, OutputTarget::Kind::Standard);
  EXPECT_EQ(resolved(f.path / "new.txt").kind, OutputTarget::Kind::File);
  EXPECT_EQ(resolved("/dev/null").kind, OutputTarget::Kind::Special);
  ASSERT_EQ(::mkfifo((f.path / "fifo").c_str(), 0600), 0);
  EXPECT_EQ(resolved(f.path / "fifo").kind, OutputTarget::Kind::Special);
  // A chain of links ends at the file that is written.
  std::ofstream(f.path / "real") << "x";
  fs::create_symlink("real", f.path / "a");
  fs::create_symlink("a", f.path / "b");
  OutputTarget t = resolved(f.path / "b");
  EXPECT_EQ(t.kind, OutputTarget::Kind::File);
  EXPECT_EQ(t.path, f.path / "real");
  EXPECT_EQ(t.requested, f.path / "b");
  // Refused: a folder, a missing folder, a loop of links.
  EXPECT_TRUE(std::holds_alternative<std::string>(resolveOutput(f.path)));
  EXPECT_TRUE(std::holds_alternative<std::string>(resolveOutput(f.path / "no/such/x.txt")));
  fs::create_symlink("loop2", f.path / "loop1");
  fs::create_symlink("loop1", f.path / "loop2");
  auto loop = resolveOutput(f.path / "loop1");
  ASSERT_TRUE(std::holds_alternative<std::string>(loop));
  EXPECT_NE(std::get<std::string>(loop).find("loop of symbolic links"), std::string::npos);
}

TEST(OutputFile, AStagedFileIsInvisibleUntilCommitted) {
  Folder f;
  const fs::path out = f.path / "out.txt";
  std::ofstream(out) << "old";
  {
    auto staged = StagedFile::write(resolved(out), "new");
    ASSERT_TRUE(std::holds_alternative<StagedFile>(staged));
    EXPECT_EQ(read(out), "old");
    EXPECT_EQ(f.count(), 2u);  // the old file and the temporary
  }
  // Destroyed uncommitted: the temporary is gone and the old file stays.
  EXPECT_EQ(f.count(), 1u);
  EXPECT_EQ(read(out), "old");
  auto staged = StagedFile::write(resolved(out), "new");
  ASSERT_TRUE(std::holds_alternative<StagedFile>(staged));
  EXPECT_FALSE(std::get<StagedFile>(staged).commit().has_value());
  EXPECT_EQ(read(out), "new");
  EXPECT_EQ(f.count(), 1u);
}

TEST(OutputFile, WriteErrorsAreReportedForTheOutput) {
  // /dev/full takes no byte: written through, the failure is reported, never ignored.
  auto error = writeOutputFile("/dev/full", "bytes");
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(error->find("No space left on device"), std::string::npos) << *error;
  EXPECT_EQ(writeOutputFile("/dev/null", "bytes"), std::nullopt);
}

TEST(OutputFile, SameExistingFile) {
  Folder f;
  std::ofstream(f.path / "x") << "x";
  fs::create_hard_link(f.path / "x", f.path / "y");
  fs::create_symlink("x", f.path / "z");
  EXPECT_TRUE(sameExistingFile(f.path / "x", f.path / "y"));
  EXPECT_TRUE(sameExistingFile(f.path / "x", f.path / "z"));
  EXPECT_TRUE(sameExistingFile(f.path / "x", f.path / "../" / f.path.filename() / "x"));
  EXPECT_FALSE(sameExistingFile(f.path / "x", f.path / "missing"));
}

}  // namespace
}  // namespace mxc
