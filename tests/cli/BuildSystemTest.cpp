// What build systems ask of `mxc compile` (cmake/MxcMaterials.cmake uses each): --list-outputs
// names the files a compile writes and writes none, --depfile writes a Makefile rule from every
// output to every file read, and --tables DIR alone writes the tables.

#include <gtest/gtest.h>

#include "support/CommandSupport.h"

namespace mxc::test {
namespace {

TEST(BuildSystem, ListOutputsNamesEveryFileAndWritesNone) {
  TempFolder folder("list_outputs");
  const std::string out = (folder / "m.metal").string();
  const CommandRun run = mxc("compile " + corpus("materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx") +
                             " -o " + out + " --list-outputs");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(run.out, out + "\n" + (folder / "m.json").string() + "\n" + (folder / "m.vert.metal").string() + "\n");
  EXPECT_TRUE(fs::is_empty(folder.path()));
}

TEST(BuildSystem, TheDepfileListsIncludesAndImagesOnce) {
  TempFolder folder("depfile");
  writeText(folder / "inc.mtlx", "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\">\n"
                                 "  <constant name=\"c\" type=\"color3\"><input name=\"value\" type=\"color3\" value=\"0.5, 0.2, 0.1\"/></constant>\n"
                                 "</materialx>\n");
  writeText(folder / "my doc.mtlx",
            "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
            "  <xi:include href=\"inc.mtlx\"/>\n"
            "  <open_pbr_surface name=\"s\" type=\"surfaceshader\"><input name=\"base_color\" type=\"color3\" nodename=\"c\"/></open_pbr_surface>\n"
            "  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"s\"/></surfacematerial>\n"
            "</materialx>\n");
  const CommandRun run = mxc("compile '" + (folder / "my doc.mtlx").string() + "' -q -o " + (folder / "m.spv").string() +
                             " --depfile " + (folder / "m.d").string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::string depfile = readFileBytes(folder / "m.d");
  EXPECT_EQ(depfile.find((folder / "m.spv").string() + " " + (folder / "m.json").string() + " " +
                         (folder / "m.vert.spv").string() + ":"),
            0u)
      << depfile;
  EXPECT_NE(depfile.find((folder / "my\\ doc.mtlx").string()), std::string::npos) << "spaces escaped: " << depfile;
  EXPECT_NE(depfile.find((folder / "inc.mtlx").string()), std::string::npos) << depfile;

  const CommandRun images = mxc("compile " + corpus("materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx") +
                                " -q -o " + (folder / "b.spv").string() + " --depfile " + (folder / "b.d").string());
  ASSERT_EQ(images.exitCode, 0) << images.err;
  const std::string brick = readFileBytes(folder / "b.d");
  EXPECT_NE(brick.find("Images/brick_normal.jpg"), std::string::npos) << brick;
  EXPECT_EQ(brick.find("Images/brick_normal.jpg"), brick.rfind("Images/brick_normal.jpg")) << "each file once";
}

TEST(BuildSystem, DepfileNeedsAnOutputFileAndOneDocument) {
  TempFolder folder("depfile_usage");
  const std::string doc = corpus("openpbr-presets/open_pbr_default.mtlx");
  EXPECT_EQ(mxc("compile " + doc + " -o - --depfile " + (folder / "x.d").string()).exitCode, 2);
  EXPECT_EQ(mxc("compile " + doc + " " + doc + " -o " + folder.path().string() + " --list-outputs").exitCode, 2);
  EXPECT_FALSE(fs::exists(folder / "x.d"));
}

TEST(BuildSystem, TablesAloneNeedNoDocument) {
  TempFolder folder("tables_alone");
  const CommandRun run = mxc("compile --tables " + (folder / "t").string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(readFileBytes(folder / "t/mxc_albedo_tables.bin").substr(0, 8), "MXCTAB01");
  EXPECT_EQ(mxc("compile").exitCode, 2);
}

}  // namespace
}  // namespace mxc::test
