// mxc's own lowering of open_pbr_surface and standard_surface (from the specifications) and
// the lowering of MaterialX's node graphs for them (from its library) reach the same slab
// structure after the passes, for every corpus example.

#include <gtest/gtest.h>

#include "compiler/ir/Print.h"
#include "compiler/ir/passes/Pass.h"
#include "compiler/lower/Lowering.h"
#include "support/TestSupport.h"

namespace mxc::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> shadingModelExamples() {
  std::vector<std::string> files;
  for (const char* dir : {"corpus/materialx/examples/OpenPbr", "corpus/materialx/examples/StandardSurface",
                          "corpus/openpbr-presets"}) {
    for (const auto& e : fs::directory_iterator(sharedDir() / dir)) {
      if (e.path().extension() == ".mtlx") files.push_back(e.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::string> signatures(const std::string& file, bool viaGraphs) {
  Context context;
  EXPECT_TRUE(context.libraries.addFolder(sharedDir() / "reference/materialx/libraries"));
  CompileRequest request;
  request.document = file;
  request.lowering.useShadingModelGraphs = viaGraphs;
  Compiler compiler(context, request);
  EXPECT_NE(compiler.document(), nullptr);
  std::vector<std::string> out;
  for (const ir::Material& m : compiler.materials()) out.push_back(m.name + ": " + ir::structureSignature(m));
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  return out;
}

class ShadingModelGraphs : public ::testing::TestWithParam<std::string> {};

TEST_P(ShadingModelGraphs, SameStructureAsMaterialXGraph) {
  std::vector<std::string> ours = signatures(GetParam(), false);
  std::vector<std::string> theirs = signatures(GetParam(), true);
  ASSERT_FALSE(ours.empty());
  EXPECT_EQ(ours, theirs);
}

INSTANTIATE_TEST_SUITE_P(Corpus, ShadingModelGraphs, ::testing::ValuesIn(shadingModelExamples()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           std::string name = fs::path(param.param).parent_path().filename().string() + "_" +
                                              fs::path(param.param).stem().string();
                           for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

}  // namespace
}  // namespace mxc::test
