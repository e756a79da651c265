// `mxc bench accuracy`: the report's three files from one run, figures that agree with what the
// material is, and nothing written when the command is refused.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "runtime/ImageIO.h"
#include "support/CommandSupport.h"

namespace mxc::test {
namespace {

std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// The fields of a CSV line without quoted commas.
std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string f;
  while (std::getline(in, f, ',')) out.push_back(f);
  return out;
}

// Small counts: a test of the command, not a measurement.
const std::string kQuick =
    " --albedo-walks 2048 --eval-walks 64 --image-frames 4 --tier-frames 4 --image-size 32 --frame-size 32";

// A Lambertian is exact on every tier (no layering, no microfacet): the errors the report gives
// against the reference are within the reference's own noise, and every cost is measured.
TEST(AccuracyBench, WritesTheReportOfOneRunAndTheTiersAgreeOnALambertian) {
  TempFolder folder("accuracy_bench");
  const fs::path doc = folder / "lambert.mtlx";
  std::ofstream(doc) << mtlx(
      "  <oren_nayar_diffuse_bsdf name=\"bsdf\" type=\"BSDF\">\n"
      "    <input name=\"color\" type=\"color3\" value=\"0.8, 0.8, 0.8\" />\n"
      "  </oren_nayar_diffuse_bsdf>\n"
      "  <surface name=\"surf\" type=\"surfaceshader\"><input name=\"bsdf\" type=\"BSDF\" nodename=\"bsdf\" /></surface>\n"
      "  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" "
      "nodename=\"surf\" /></surfacematerial>\n");
  CommandRun r = mxc("bench accuracy --report-dir " + folder.path().string() + kQuick + " " + doc.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("wrote"), std::string::npos) << r.out;

  std::stringstream csv(readAll(folder / "accuracy.csv"));
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  const std::vector<std::string> header = fields(line);
  ASSERT_EQ(header.size(), 13u) << line;
  EXPECT_EQ(header[3], "albedo_error");
  EXPECT_EQ(header[4], "albedo_mean_abs");
  std::vector<std::vector<std::string>> rows;
  while (std::getline(csv, line)) rows.push_back(fields(line));
  ASSERT_EQ(rows.size(), 3u);
  const char* tiers[] = {"fast", "balanced", "reference"};
  const double referenceImageNoise = std::stod(rows[2][6]);
  for (size_t t = 0; t < 3; ++t) {
    ASSERT_EQ(rows[t].size(), 13u);
    EXPECT_EQ(rows[t][2], tiers[t]);
    const double albedo = std::stod(rows[t][3]), albedoAbs = std::stod(rows[t][4]), fcos = std::stod(rows[t][5]),
                 image = std::stod(rows[t][6]);
    // The albedo of a Lambertian is its colour at every view on every tier: fast and balanced
    // sample it exactly, and the reference's walk leaves it at once.
    EXPECT_LT(albedo, 1e-3) << tiers[t];
    EXPECT_LT(albedoAbs, 1e-3) << tiers[t];
    EXPECT_LT(fcos, 0.05) << tiers[t];  // reference: 64 walks per pair, of a lobe with one event
    // The image's error is the reference's noise (4 frames) and the tiers' (4 frames each).
    if (t < 2) {
      EXPECT_LT(image, 3.0 * referenceImageNoise + 0.02) << tiers[t];
    }
    EXPECT_GT(std::stod(rows[t][7]), 0.0) << "ns per eval";
    EXPECT_GT(std::stod(rows[t][8]), 0.0) << "ms per frame";
    EXPECT_GT(std::stoul(rows[t][9]), 100u) << "SPIR-V instructions";
    EXPECT_GE(std::stoul(rows[t][10]), 2048u) << "the albedo cap is reached: there is no error to resolve";
  }

  const std::string md = readAll(folder / "accuracy.md");
  EXPECT_NE(md.find("mxc bench accuracy --albedo-walks 2048"), std::string::npos) << "the reproducing command";
  EXPECT_NE(md.find("| balanced |"), std::string::npos);
  EXPECT_NE(md.find("Balanced's median albedo error is"), std::string::npos);
  EXPECT_NE(md.find("## The worst five per tier"), std::string::npos);
  auto png = rt::readImage(folder / "accuracy.png");
  ASSERT_TRUE(std::holds_alternative<rt::RgbaImage>(png)) << std::get<std::string>(png);
  const rt::RgbaImage& plot = std::get<rt::RgbaImage>(png);
  EXPECT_EQ(plot.width, 1000u);
  EXPECT_EQ(plot.height, 640u);
  // Not blank: the axes, the text and the points are drawn in colours other than the white paper.
  size_t inked = 0;
  for (size_t i = 0; i < plot.pixels.size(); i += 4) inked += plot.pixels[i] < 0.5f ? 1 : 0;
  EXPECT_GT(inked, 2000u);
}

// Refused before any measurement, with nothing written: a bad option, a missing folder, an
// invalid document.
TEST(AccuracyBench, RefusesBeforeMeasuringAndWritesNothing) {
  TempFolder folder("accuracy_bench_refused");
  const fs::path doc = folder / "bad.mtlx";
  std::ofstream(doc) << "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\">\n  <surfacematerial name=\"M\"\n";
  const std::string good = corpus("materialx/examples/OpenPbr/open_pbr_default.mtlx");
  CommandRun r = mxc("bench accuracy --report-dir " + folder.path().string() + " --image-size 40 " + good);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("multiple of 16"), std::string::npos) << r.err;
  r = mxc("bench accuracy --report-dir " + (folder / "missing").string() + kQuick + " " + good);
  EXPECT_EQ(r.exitCode, 3) << r.err;
  r = mxc("bench accuracy --report-dir " + folder.path().string() + kQuick + " " + doc.string());
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("bad.mtlx:3:3"), std::string::npos) << r.err;
  r = mxc("bench accuracy --report-dir " + folder.path().string() + " --corpus " + folder.path().string() + kQuick);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("--corpus"), std::string::npos) << r.err;
  // The fixed set as well as a document: its documents are looked for first.
  r = mxc("bench accuracy --fixed-set --report-dir " + folder.path().string() + " --corpus " + folder.path().string() +
          kQuick + " " + good);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("--corpus"), std::string::npos) << r.err;
  for (const char* name : {"accuracy.md", "accuracy.csv", "accuracy.png"}) EXPECT_FALSE(fs::exists(folder / name));
}

}  // namespace
}  // namespace mxc::test
