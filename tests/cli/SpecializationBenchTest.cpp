// `mxc bench specialize`: both files from one run, figures that agree with what specialization
// does, and nothing written when the command is refused.

#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "support/CommandSupport.h"

namespace mxc::test {
namespace {

std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string f;
  while (std::getline(in, f, ',')) out.push_back(f);
  return out;
}

// Small images: a test of the command, not a measurement.
const std::string kQuick = " --size 16 --frames 2 --repeat 1";

// A pbrlib graph whose roughness is a value: the general shader keeps it (and the scene) as
// uniforms, the specialized one folds them, and both render the same image.
TEST(SpecializationBench, WritesTheReportOfOneRunAndTheShadersAgree) {
  TempFolder folder("specialization_bench");
  const fs::path doc = folder / "diffuse.mtlx";
  std::ofstream(doc) << mtlx(
      "  <oren_nayar_diffuse_bsdf name=\"bsdf\" type=\"BSDF\">\n"
      "    <input name=\"color\" type=\"color3\" value=\"0.8, 0.5, 0.2\" />\n"
      "    <input name=\"roughness\" type=\"float\" value=\"0.3\" />\n"
      "  </oren_nayar_diffuse_bsdf>\n"
      "  <surface name=\"surf\" type=\"surfaceshader\"><input name=\"bsdf\" type=\"BSDF\" nodename=\"bsdf\" /></surface>\n"
      "  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" "
      "nodename=\"surf\" /></surfacematerial>\n");
  CommandRun r = mxc("bench specialize --report-dir " + folder.path().string() + kQuick + " " + doc.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("median specialized / general"), std::string::npos) << r.out;

  std::stringstream csv(readAll(folder / "specialization.csv"));
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  const std::vector<std::string> header = fields(line);
  ASSERT_EQ(header.size(), 11u) << line;
  EXPECT_EQ(header[3], "shader");
  EXPECT_EQ(header[6], "optimized");
  // (shader, scene) -> row
  std::map<std::pair<std::string, std::string>, std::vector<std::string>> rows;
  while (std::getline(csv, line)) {
    std::vector<std::string> f = fields(line);
    ASSERT_GE(f.size(), 10u) << line;
    EXPECT_EQ(f[0], "M");
    rows[{f[3], f[4]}] = f;
  }
  ASSERT_EQ(rows.size(), 4u) << "two shaders in two scenes";
  for (const char* scene : {"key light", "sky + key light"}) {
    const auto& general = rows.at({"general", scene});
    const auto& specialized = rows.at({"specialized", scene});
    EXPECT_LE(std::stoul(specialized[5]), std::stoul(general[5])) << scene << ": instructions";
    EXPECT_LE(std::stoul(specialized[6]), std::stoul(general[6])) << scene << ": -O instructions";
    EXPECT_GT(std::stoul(specialized[6]), 100u) << scene;
    EXPECT_GT(std::stod(specialized[8]), 0.0) << scene << ": ms per frame";
    EXPECT_GT(std::stod(specialized[9]), 0.0) << scene << ": pipeline ms";
    ASSERT_EQ(specialized.size(), 11u) << scene << ": the image difference";
    EXPECT_LT(std::stod(specialized[10]), 1e-3) << scene << ": the two images";
  }
  // The scene's constants fold away more of the shader with only a key light than with the
  // environment's sampling too.
  EXPECT_LT(std::stoul(rows.at({"specialized", "key light"})[6]), std::stoul(rows.at({"specialized", "sky + key light"})[6]));

  const std::string md = readAll(folder / "specialization.md");
  EXPECT_NE(md.find("mxc bench specialize --size 16 --frames 2 --repeat 1"), std::string::npos) << "the command";
  EXPECT_NE(md.find("## Medians"), std::string::npos);
  EXPECT_NE(md.find("## Targets"), std::string::npos);
  EXPECT_NE(md.find("| M (diffuse.mtlx) |"), std::string::npos);
  EXPECT_NE(md.find("its columns are empty"), std::string::npos) << "no MaterialX figures without --materialx";
}

// Refused before any measurement, with nothing written: a missing folder, an invalid document,
// a manifest that is not one.
TEST(SpecializationBench, RefusesBeforeMeasuringAndWritesNothing) {
  TempFolder folder("specialization_bench_refused");
  const fs::path doc = folder / "bad.mtlx";
  std::ofstream(doc) << "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\">\n  <surfacematerial name=\"M\"\n";
  const fs::path manifest = folder / "manifest.json";
  std::ofstream(manifest) << "{\"materials\": [{\"mtlx\": \"x.mtlx\"}]}";
  const std::string good = corpus("materialx/examples/OpenPbr/open_pbr_default.mtlx");
  CommandRun r = mxc("bench specialize --report-dir " + (folder / "missing").string() + kQuick + " " + good);
  EXPECT_EQ(r.exitCode, 3) << r.err;
  r = mxc("bench specialize --report-dir " + folder.path().string() + kQuick + " " + doc.string());
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("bad.mtlx:3:3"), std::string::npos) << r.err;
  r = mxc("bench specialize --report-dir " + folder.path().string() + kQuick + " --materialx " + manifest.string() + " " + good);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("manifest.json: not a manifest"), std::string::npos) << r.err;
  r = mxc("bench specialize --report-dir " + folder.path().string() + " --corpus " + folder.path().string() + kQuick);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("--corpus"), std::string::npos) << r.err;
  for (const char* name : {"specialization.md", "specialization.csv"}) EXPECT_FALSE(fs::exists(folder / name));
}

}  // namespace
}  // namespace mxc::test
