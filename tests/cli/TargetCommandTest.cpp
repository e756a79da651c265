// `mxc compile --target` (compiler/target): the language from --target or -o's extension, both
// stages and the interface in that language, -o - for a text target, batches, and a failing
// translator leaving nothing written.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/CommandSupport.h"

namespace mxc::test {
namespace {

std::string brick() {
  return corpus("materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx");
}

nlohmann::json readJson(const fs::path& path) { return nlohmann::json::parse(readFileBytes(path)); }

TEST(TargetCommand, WritesBothStagesAndTheirPlacementsInTheTarget) {
  TempFolder folder("target_msl");
  const CommandRun run = mxc("compile " + brick() + " --target msl -o " + (folder / "brick.metal").string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find(", msl "), std::string::npos) << run.out;
  EXPECT_NE(readFileBytes(folder / "brick.metal").find("fragment main0_out main0("), std::string::npos);
  EXPECT_NE(readFileBytes(folder / "brick.vert.metal").find("vertex main0_out main0("), std::string::npos);
  const nlohmann::json j = readJson(folder / "brick.json");
  EXPECT_EQ(j["target"], "msl");
  EXPECT_EQ(j["stages"]["fragment"]["file"], "brick.metal");
  EXPECT_EQ(j["stages"]["fragment"]["entryPoint"], "main0");
  EXPECT_FALSE(j["stages"]["fragment"].contains("spirv"));
  EXPECT_EQ(j["stages"]["vertex"]["file"], "brick.vert.metal");
  for (const auto& d : j["descriptors"]) EXPECT_TRUE(d.contains("target")) << d["name"];
  EXPECT_TRUE(j["requires"].empty()) << "no subgroups outside mxc's own renderer";
}

TEST(TargetCommand, TheOutputExtensionChoosesTheTargetWhenNoneIsGiven) {
  TempFolder folder("target_ext");
  ASSERT_EQ(mxc("compile " + brick() + " -q -o " + (folder / "brick.hlsl").string()).exitCode, 0);
  EXPECT_NE(readFileBytes(folder / "brick.hlsl").find("cbuffer MxcView : register(b1, space0)"), std::string::npos);
  EXPECT_EQ(readJson(folder / "brick.json")["target"], "hlsl");
  ASSERT_EQ(mxc("compile " + brick() + " -q -o " + (folder / "brick.spv").string()).exitCode, 0);
  EXPECT_EQ(readFileBytes(folder / "brick.spv").substr(0, 4), std::string("\x03\x02\x23\x07", 4));
  EXPECT_EQ(readJson(folder / "brick.json")["target"], "spirv");
  EXPECT_EQ(readJson(folder / "brick.json")["stages"]["fragment"]["spirv"], "brick.spv");
}

TEST(TargetCommand, ATargetThatContradictsTheExtensionIsRefused) {
  TempFolder folder("target_clash");
  const CommandRun run = mxc("compile " + brick() + " --target msl -o " + (folder / "brick.spv").string());
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find("--target msl writes .metal but -o"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(folder / "brick.spv"));
  const CommandRun unknown = mxc("compile " + brick() + " --target dxil -o " + (folder / "brick.x").string());
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.err.find("--target"), std::string::npos) << unknown.err;
}

TEST(TargetCommand, ATextTargetGoesToStandardOutput) {
  const CommandRun run = mxc("compile " + brick() + " --target wgsl -o -");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("@fragment"), std::string::npos);
  EXPECT_EQ(run.out.find("compiled 1 material"), std::string::npos) << "no summary mixed into the shader";
}

TEST(TargetCommand, ABatchWritesEachMaterialWithTheTargetsExtension) {
  TempFolder folder("target_batch");
  const std::string documents = corpus("materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx") +
                                " " + corpus("materialx/examples/StandardSurface/standard_surface_marble_solid.mtlx");
  const CommandRun run = mxc("compile " + documents + " --target essl -q -o " + (folder / "out").string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_TRUE(fs::exists(folder / "out/standard_surface_brick_procedural/M_BrickPattern.essl"));
  EXPECT_TRUE(fs::exists(folder / "out/standard_surface_brick_procedural/M_BrickPattern.vert.essl"));
  EXPECT_TRUE(fs::exists(folder / "out/standard_surface_marble_solid/Marble_3D.essl"));
  EXPECT_EQ(readJson(folder / "out/standard_surface_marble_solid/Marble_3D.json")["target"], "essl");
}

TEST(TargetCommand, AFailingTranslatorLeavesNothingWritten) {
  TempFolder folder("target_fail");
  const std::string out = (folder / "brick.wgsl").string();
  // /bin/false as naga: it exits 1 and writes nothing.
  const CommandRun run = mxc("compile " + brick() + " --target wgsl -o " + out, "MXC_NAGA=/bin/false");
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("cannot translate the shader to WGSL"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("no output written"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(folder / "brick.json"));
  EXPECT_FALSE(fs::exists(folder / "brick.vert.wgsl"));
}

}  // namespace
}  // namespace mxc::test
