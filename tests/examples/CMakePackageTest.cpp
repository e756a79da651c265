// mxc's CMake package (cmake/MxcMaterials.cmake): the example project under examples/cmake,
// built against an installed mxc with Ninja, writes every material's files, is up to date when
// built again, and rebuilds only the documents whose inputs changed: the document, a file it
// includes (found through the depfile), not the others.

#include <gtest/gtest.h>

#include <cstdio>

#include "support/CommandSupport.h"

namespace mxc::test {
namespace {

/// Runs a shell command; its exit code and what it printed (both streams).
std::pair<int, std::string> shell(const std::string& command) {
  std::string out;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return {-1, out};
  char buffer[4096];
  size_t n;
  while ((n = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0) out.append(buffer, n);
  const int status = ::pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

/// The number of lines of `text` that contain `needle`.
int linesWith(const std::string& text, const std::string& needle) {
  int count = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++count;
  return count;
}

TEST(CMakePackage, BuildsAMaterialLibraryIncrementally) {
  TempFolder folder("cmake_package");
  const std::string cmake = MXC_CMAKE;
  const fs::path prefix = folder / "prefix", project = folder / "examples", build = folder / "build";
  auto [installed, installLog] = shell(cmake + " --install " + std::string(MXC_BUILD_DIR) + " --prefix " + prefix.string());
  ASSERT_EQ(installed, 0) << installLog;
  ASSERT_TRUE(fs::exists(prefix / "lib/cmake/mxc/mxcConfig.cmake"));
  // A copy of examples/, so that touching its files leaves the source tree alone.
  fs::copy(sourceDir() / "examples", project, fs::copy_options::recursive);
  auto [configured, configureLog] = shell(cmake + " -S " + (project / "cmake").string() + " -B " + build.string() +
                                          " -G Ninja -DCMAKE_PREFIX_PATH=" + prefix.string());
  ASSERT_EQ(configured, 0) << configureLog;
  auto [built, buildLog] = shell(cmake + " --build " + build.string());
  ASSERT_EQ(built, 0) << buildLog;
  for (const char* file : {"shaders/painted_metal.spv", "shaders/painted_metal.json", "shaders/painted_metal.vert.spv",
                           "shaders/open_pbr_coated_copper.spv", "shaders/pbrlib_glazed_ceramic.spv",
                           "shaders/mxc_albedo_tables.bin", "metal/painted_metal.metal", "metal/painted_metal.vert.metal",
                           "metal/open_pbr_coated_copper.json"}) {
    EXPECT_TRUE(fs::exists(build / file)) << file;
  }
  EXPECT_NE(readFileBytes(build / "metal/painted_metal.json").find("\"target\": \"msl\""), std::string::npos);

  auto [again, againLog] = shell(cmake + " --build " + build.string());
  EXPECT_EQ(again, 0);
  EXPECT_NE(againLog.find("no work to do"), std::string::npos) << againLog;

  // The included file changes: the document that includes it is compiled again, for both
  // targets, and nothing else (the depfile named it).
  // (Touched now: later than the outputs, not in the future, or they would stay older than it.)
  fs::last_write_time(project / "cmake/materials/include/paint.mtlx", fs::file_time_type::clock::now());
  auto [rebuilt, rebuildLog] = shell(cmake + " --build " + build.string());
  EXPECT_EQ(rebuilt, 0) << rebuildLog;
  EXPECT_EQ(linesWith(rebuildLog, "mxc: materials/painted_metal.mtlx"), 2) << rebuildLog;
  EXPECT_EQ(linesWith(rebuildLog, "mxc: "), 2) << rebuildLog;

  // A document changes: the configuration runs again (it may have a new material), then that
  // document alone is compiled, for its one target.
  fs::last_write_time(project / "pbrlib_glazed_ceramic.mtlx", fs::file_time_type::clock::now());
  auto [changed, changeLog] = shell(cmake + " --build " + build.string());
  EXPECT_EQ(changed, 0) << changeLog;
  EXPECT_EQ(linesWith(changeLog, "mxc: ../pbrlib_glazed_ceramic.mtlx"), 1) << changeLog;
  EXPECT_EQ(linesWith(changeLog, "mxc: "), 1) << changeLog;
}

}  // namespace
}  // namespace mxc::test
