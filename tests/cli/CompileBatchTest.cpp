// `mxc compile` of many documents in one process (cli/CompileBatch.cpp): folders and files
// together, one output per material under -o DIR, the run going on past a failing document,
// a summary and exit 1 when any failed; -j workers give the very same files as one.

#include <gtest/gtest.h>

#include <map>
#include <string>

#include "support/CommandSupport.h"

namespace mxc::test {
namespace {

/// Every file under `folder`, by its path relative to it, with its bytes.
std::map<std::string, std::string> filesUnder(const fs::path& folder) {
  std::map<std::string, std::string> out;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (entry.is_regular_file()) out[fs::relative(entry.path(), folder).string()] = readFileBytes(entry.path());
  }
  return out;
}

const char* const kGood =
    "<materialx version=\"1.39\">\n"
    "  <open_pbr_surface name=\"o\" type=\"surfaceshader\"/>\n"
    "  <surfacematerial name=\"RedPaint\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" "
    "nodename=\"o\"/></surfacematerial>\n"
    "  <standard_surface name=\"s\" type=\"surfaceshader\"/>\n"
    "  <surfacematerial name=\"Plastic\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" "
    "nodename=\"s\"/></surfacematerial>\n"
    "</materialx>\n";

TEST(CompileBatch, GoesOnPastAFailingDocumentAndSaysWhichFailed) {
  TempFolder folder("batch");
  fs::create_directories(folder / "docs/sub");
  writeText(folder / "docs/good.mtlx", kGood);
  writeText(folder / "docs/sub/broken.mtlx", "<materialx version=\"1.39\">\n  <nodegraph name=\"x\">\n</materialx>\n");
  writeText(folder / "docs/graph_only.mtlx", "<materialx version=\"1.39\">\n  <constant name=\"c\" type=\"color3\"/>\n</materialx>\n");
  writeText(folder / "single.mtlx", kGood);
  const fs::path out = folder / "out";
  CommandRun r = mxc("compile " + (folder / "docs").string() + " " + (folder / "single.mtlx").string() + " -o " +
                     out.string() + " --glsl " + out.string() + " -j 2");
  EXPECT_EQ(r.exitCode, 1) << r.err;
  // The broken document's error, with its position, then the summary naming it.
  EXPECT_NE(r.err.find("broken.mtlx:3:1: error: mismatched end tag"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("error: 1 of 4 document(s) failed:\n  " + (folder / "docs/sub/broken.mtlx").string()),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("compiled 4 material(s) of 2 document(s)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1 document(s) had nothing to compile"), std::string::npos) << r.out;
  // One file per material under DIR/<document>/.
  for (const char* path : {"docs/good/RedPaint.spv", "docs/good/Plastic.spv", "docs/good/RedPaint.frag",
                           "single/RedPaint.spv", "single/Plastic.frag"}) {
    EXPECT_TRUE(fs::is_regular_file(out / path)) << path;
  }
  EXPECT_EQ(readFileBytes(out / "docs/good/Plastic.spv").substr(0, 4), std::string("\x03\x02\x23\x07", 4));
  EXPECT_FALSE(fs::exists(out / "docs/sub/broken")) << "nothing of a failed document";
  // Without -o, a batch only checks that everything compiles.
  r = mxc("compile " + (folder / "docs/good.mtlx").string() + " " + (folder / "single.mtlx").string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("compiled 4 material(s) of 2 document(s)"), std::string::npos) << r.out;
}

TEST(CompileBatch, RefusesOutputsItCannotSeparate) {
  TempFolder folder("batch_refuse");
  fs::create_directories(folder / "a");
  fs::create_directories(folder / "b");
  writeText(folder / "a/same.mtlx", kGood);
  writeText(folder / "b/same.mtlx", kGood);
  CommandRun r = mxc("compile " + (folder / "a/same.mtlx").string() + " " + (folder / "b/same.mtlx").string() + " -o " +
                     (folder / "out").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("would both write their outputs to same/"), std::string::npos) << r.err;
  writeText(folder / "file.spv", "x");
  r = mxc("compile " + (folder / "a").string() + " -o " + (folder / "file.spv").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("-o and --glsl name folders"), std::string::npos) << r.err;
  r = mxc("compile " + (folder / "a").string() + " " + (folder / "nope").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("no such file or folder"), std::string::npos) << r.err;
}

// A scene in a batch compiles what `mxc compile SCENE` compiles: its objects' materials and
// those its look assigns (here the objects name none; the look assigns both).
TEST(CompileBatch, ASceneCompilesTheMaterialsItsLookAssigns) {
  TempFolder folder("batch_scene");
  std::string looked = kGood;
  looked.replace(looked.find("</materialx>"), std::string::npos,
                 "  <look name=\"Dressed\">\n    <materialassign name=\"a\" geom=\"/left\" material=\"RedPaint\"/>\n"
                 "    <materialassign name=\"b\" geom=\"/right\" material=\"Plastic\"/>\n  </look>\n</materialx>\n");
  writeText(folder / "looked.mtlx", looked);
  writeText(folder / "dressed.json",
            R"({"mxc_scene": 1, "documents": [")" + (folder / "looked.mtlx").string() +
                R"("], "look": "Dressed", "objects": [{"name": "left"}, {"name": "right"}]})");
  writeText(folder / "single.mtlx", kGood);
  CommandRun r = mxc("compile " + (folder / "dressed.json").string() + " " + (folder / "single.mtlx").string() + " -o " +
                     (folder / "out").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(folder / "out/dressed/RedPaint.spv"));
  EXPECT_TRUE(fs::is_regular_file(folder / "out/dressed/Plastic.spv"));
  EXPECT_NE(r.out.find("compiled 4 material(s) of 2 document(s)"), std::string::npos) << r.out;
}

// The workers share the libraries and glslang: two of them write exactly the files one writes.
TEST(CompileBatch, WorkersWriteWhatOneWrites) {
  TempFolder folder("batch_jobs");
  const std::string presets = corpus("openpbr-presets");
  CommandRun one = mxc("compile " + presets + " -o " + (folder / "one").string() + " -j 1");
  ASSERT_EQ(one.exitCode, 0) << one.err;
  CommandRun two = mxc("compile " + presets + " -o " + (folder / "two").string() + " -j 2");
  ASSERT_EQ(two.exitCode, 0) << two.err;
  const auto a = filesUnder(folder / "one");
  const auto b = filesUnder(folder / "two");
  EXPECT_GT(a.size(), 10u);
  EXPECT_TRUE(a == b) << a.size() << " against " << b.size() << " files";
}

// Materials whose shaders have the same code (here the same material under two names) compile
// once in a batch; the one served from the other's compile writes what it writes alone.
TEST(CompileBatch, AShaderCodeCompilesOnceAndWritesWhatItWritesAlone) {
  TempFolder folder("batch_shared");
  auto document = [](const std::string& name, const std::string& color = "0.7, 0.1, 0.1") {
    return "<materialx version=\"1.39\">\n  <open_pbr_surface name=\"o\" type=\"surfaceshader\">\n"
           "    <input name=\"base_color\" type=\"color3\" value=\"" + color + "\"/>\n  </open_pbr_surface>\n"
           "  <surfacematerial name=\"" + name + "\" type=\"material\"><input name=\"surfaceshader\" "
           "type=\"surfaceshader\" nodename=\"o\"/></surfacematerial>\n</materialx>\n";
  };
  fs::create_directories(folder / "docs");
  writeText(folder / "docs/red.mtlx", document("Red"));
  writeText(folder / "docs/crimson.mtlx", document("Crimson"));
  // Other code, the same library: compiled in one shader with red's, its module cut from it.
  writeText(folder / "docs/blue.mtlx", document("Blue", "0.1, 0.1, 0.7"));
  CommandRun batch = mxc("compile " + (folder / "docs").string() + " -o " + (folder / "out").string() + " -v");
  ASSERT_EQ(batch.exitCode, 0) << batch.err;
  EXPECT_NE(batch.err.find("1 material(s) had the code of a shader compiled for another"), std::string::npos) << batch.err;
  EXPECT_NE(batch.err.find("2 module(s) were cut from shaders compiled for several materials"), std::string::npos)
      << batch.err;
  EXPECT_NE(batch.err.find("Blue: "), std::string::npos) << batch.err;
  EXPECT_NE(batch.err.find("SPIR-V instructions, cut from its library's shader"), std::string::npos) << batch.err;
  EXPECT_NE(batch.err.find("SPIR-V instructions, the module of a shader of the same code"), std::string::npos)
      << batch.err;
  for (const auto& [name, material] : std::map<std::string, std::string>{{"red", "Red"}, {"crimson", "Crimson"}, {"blue", "Blue"}}) {
    const fs::path alone = folder / (name + ".spv");
    CommandRun single = mxc("compile " + (folder / "docs" / (name + ".mtlx")).string() + " -o " + alone.string());
    ASSERT_EQ(single.exitCode, 0) << single.err;
    EXPECT_EQ(readFileBytes(folder / "out/docs" / name / (material + ".spv")), readFileBytes(alone)) << name;
    EXPECT_FALSE(readFileBytes(alone).empty());
  }
  EXPECT_NE(readFileBytes(folder / "out/docs/blue/Blue.spv"), readFileBytes(folder / "out/docs/red/Red.spv"));
}

// One document of several materials compiles them by library, as a batch does: the shaders of
// one library are one glslang compile, each material's module cut from it, and each module is
// byte for byte what the material compiles to alone (--material).
TEST(CompileBatch, ADocumentsMaterialsCompileByLibraryAndWriteWhatEachWritesAlone) {
  TempFolder folder("document_groups");
  std::string body;
  const char* colors[] = {"0.7, 0.1, 0.1", "0.1, 0.7, 0.1", "0.1, 0.1, 0.7"};
  for (int i = 0; i < 3; ++i) {
    body += "  <open_pbr_surface name=\"s" + std::to_string(i) + "\" type=\"surfaceshader\"><input name=\"base_color\" "
            "type=\"color3\" value=\"" + colors[i] + "\"/></open_pbr_surface>\n  <surfacematerial name=\"M" + std::to_string(i) +
            "\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"s" + std::to_string(i) +
            "\"/></surfacematerial>\n";
  }
  writeText(folder / "three.mtlx", "<materialx version=\"1.39\">\n" + body + "</materialx>\n");
  CommandRun all = mxc("compile " + (folder / "three.mtlx").string() + " -o " + (folder / "out.spv").string() + " -v");
  ASSERT_EQ(all.exitCode, 0) << all.err;
  size_t cut = 0;
  for (size_t at = all.err.find("SPIR-V cut from the compile of its library's group"); at != std::string::npos;
       at = all.err.find("SPIR-V cut from the compile of its library's group", at + 1)) {
    ++cut;
  }
  EXPECT_EQ(cut, 3u) << all.err;
  for (int i = 0; i < 3; ++i) {
    const std::string material = "M" + std::to_string(i);
    const fs::path alone = folder / (material + ".spv");
    CommandRun single = mxc("compile " + (folder / "three.mtlx").string() + " --material " + material + " -o " + alone.string());
    ASSERT_EQ(single.exitCode, 0) << single.err;
    EXPECT_FALSE(readFileBytes(alone).empty());
    EXPECT_EQ(readFileBytes(folder / ("out_" + material + ".spv")), readFileBytes(alone)) << material;
  }
  EXPECT_NE(readFileBytes(folder / "out_M0.spv"), readFileBytes(folder / "out_M1.spv"));
}

}  // namespace
}  // namespace mxc::test
