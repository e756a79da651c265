// MaterialX conformance (issue 16): every document of MaterialX's own test suite and examples
// (../shared/conformance/materialx-tree, laid out as MaterialX's repository) goes through
// `mxc inspect`, `inspect --ir`, `compile` and, where it has a shader, `render`, as a user runs
// them: the tree as --search-path (its documents name resources/Images/...) and MaterialX's
// library folder as --library. A document passes every stage it has; a document without a
// shader compiles to "nothing to compile" and exits 0. The documents that do not pass yet are
// listed below with the reason, and the test fails when one of them starts passing, so the list
// stays true. (The corpus's own documents are rendered by the corpus tests.)
// scripts/conformance writes the README's table and the contact sheet from the same commands.

#include <gtest/gtest.h>

#include <array>

#include <string_view>

#include "support/CommandSupport.h"

namespace mxc::test {
namespace {

fs::path tree() { return sharedDir() / "conformance/materialx-tree"; }

/// Every document of the tree's test suite and examples, relative to the tree.
std::vector<std::string> conformanceDocuments() {
  std::vector<std::string> files;
  for (const char* folder : {"resources/Materials/TestSuite", "resources/Materials/Examples"}) {
    for (const auto& e : fs::recursive_directory_iterator(tree() / folder)) {
      if (e.path().extension() == ".mtlx") files.push_back(fs::relative(e.path(), tree()).string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// A document that does not pass every stage yet: the first stage it fails, and why.
struct KnownFailure {
  std::string_view document;  ///< relative to the tree
  std::string_view stage;     ///< inspect, ir, compile or render
  std::string_view reason;
};
/// None today: every document of the tree passes every stage it has.
constexpr std::array<KnownFailure, 0> kKnownFailures{};

const KnownFailure* knownFailure(const std::string& document) {
  for (const KnownFailure& k : kKnownFailures) {
    if (k.document == document) return &k;
  }
  return nullptr;
}

std::string documentTestName(const ::testing::TestParamInfo<std::string>& param) {
  std::string name = fs::path(param.param).lexically_relative("resources/Materials").replace_extension().string();
  for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

class Conformance : public ::testing::TestWithParam<std::string> {};

TEST_P(Conformance, EveryStageTheDocumentHasPasses) {
  const std::string document = (tree() / GetParam()).string();
  const std::string options = " --library " + (tree() / "libraries").string() + " --search-path " + tree().string();
  TempFolder out("conformance");
  // Each stage's command; the first that fails is the document's failing stage.
  std::string failed, why;
  auto stage = [&](const std::string& name, const std::string& command) {
    if (!failed.empty()) return CommandRun{};
    CommandRun r = mxc(command + options);
    EXPECT_TRUE(r.exitCode == 0 || r.exitCode == 1) << name << " crashed or misused: exit " << r.exitCode << "\n" << r.err;
    if (r.exitCode != 0) {
      failed = name;
      why = r.err;
    }
    return r;
  };
  stage("inspect", "inspect " + document);
  stage("ir", "inspect --ir " + document);
  const CommandRun compiled = stage("compile", "compile " + document + " -o " + (out / "shader.spv").string());
  const bool nothing = compiled.out.find("nothing to compile") != std::string::npos;
  if (failed.empty() && nothing) {
    EXPECT_FALSE(fs::exists(out / "shader.spv")) << "written, with nothing to compile";
  }
  if (failed.empty() && !nothing) {
    stage("render", "render " + document + " -o " + (out / "image.png").string() + " --size 24 --spp 1");
    size_t images = 0;
    for (const std::string& e : out.entries()) images += e.ends_with(".png") ? 1 : 0;
    if (failed.empty()) {
      EXPECT_GT(images, 0u) << "render wrote no image";
    }
  }
  if (const KnownFailure* known = knownFailure(GetParam())) {
    EXPECT_EQ(failed, known->stage) << GetParam() << ": listed as failing at " << known->stage << " (" << known->reason
                                    << "); remove or update kKnownFailures\n"
                                    << why;
    return;
  }
  EXPECT_EQ(failed, "") << GetParam() << " fails at " << failed << ":\n" << why;
}

INSTANTIATE_TEST_SUITE_P(MaterialXTree, Conformance, ::testing::ValuesIn(conformanceDocuments()), documentTestName);

}  // namespace
}  // namespace mxc::test
