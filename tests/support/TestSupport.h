#pragma once
// Helpers shared by the tests: load a document from text against the built-in library and
// look at what was reported.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "compiler/common/Diagnostic.h"
#include "compiler/document/DocumentLoader.h"
#include "compiler/driver/Compiler.h"
#include "compiler/library/LibraryStack.h"
#include "compiler/resolve/Resolver.h"

namespace mxc::test {

/// The shared reference data (corpus, MaterialX libraries), at ../shared from the source tree.
inline std::filesystem::path sharedDir() { return std::filesystem::path(MXC_SHARED_DIR); }
inline std::filesystem::path sourceDir() { return std::filesystem::path(MXC_SOURCE_DIR); }

/// The whole content of a file ("" when it cannot be read).
inline std::string readFileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Every .mtlx under ../shared/corpus, relative to the shared folder (so outputs hold no machine
/// paths), sorted.
inline std::vector<std::string> corpusDocuments() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(sharedDir() / "corpus")) {
    if (e.path().extension() == ".mtlx") files.push_back(std::filesystem::relative(e.path(), sharedDir()).string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// A GoogleTest parameter name for a corpus document: its path without extension, [A-Za-z0-9_].
inline std::string corpusTestName(const ::testing::TestParamInfo<std::string>& param) {
  std::string name = std::filesystem::path(param.param).replace_extension("").string();
  for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

/// Compares `actual` with the committed golden file, or rewrites it (and skips) when
/// MXC_UPDATE_GOLDENS=1 (scripts/update-goldens). `what` names the golden folder for the hint.
inline void matchGolden(const std::filesystem::path& golden, const std::string& actual, const std::string& what) {
  if (const char* update = std::getenv("MXC_UPDATE_GOLDENS"); update && std::string(update) == "1") {
    std::filesystem::create_directories(golden.parent_path());
    std::ofstream(golden, std::ios::binary) << actual;
    GTEST_SKIP() << "updated " << golden;
  }
  std::ifstream in(golden, std::ios::binary);
  ASSERT_TRUE(in) << "no golden file " << golden << ": run scripts/update-goldens";
  std::stringstream expected;
  expected << in.rdbuf();
  EXPECT_EQ(actual, expected.str()) << golden << " differs; if the change is intended, run scripts/update-goldens and "
                                    << "review the diff of " << what;
}

/// Golden files under `folder` that belong to no corpus document (a renamed document leaves
/// none behind), for goldens named after the document with extension `extension`.
inline std::vector<std::string> staleGoldens(const std::filesystem::path& folder, const std::string& extension) {
  std::vector<std::string> expected, stale;
  for (const std::string& doc : corpusDocuments()) {
    expected.push_back(std::filesystem::path(doc).replace_extension(extension).string());
  }
  for (const auto& e : std::filesystem::recursive_directory_iterator(folder)) {
    if (!e.is_regular_file()) continue;
    std::string rel = std::filesystem::relative(e.path(), folder).string();
    if (std::find(expected.begin(), expected.end(), rel) == expected.end()) stale.push_back(rel);
  }
  return stale;
}

/// One test's workspace (sources, diagnostics, the built-in library, a loader), with helpers
/// to load and resolve texts for the tests of those stages.
struct Context : Workspace {
  explicit Context(bool builtin = true) {
    if (builtin) loadLibraries();
  }

  const doc::Document* load(const std::string& text, const std::string& name = "test.mtlx") {
    return loader.loadText(name, text);
  }

  /// Loads and resolves (the resolver's own tests); the result stays valid as long as the
  /// context.
  resolve::ResolvedDocument resolve(const std::string& text, const std::string& name = "test.mtlx") {
    const doc::Document* d = load(text, name);
    if (!d) return {};
    return resolve::resolveDocument(*d, libraries.top(), diagnostics);
  }

  /// The first error, or a null diagnostic with an empty message.
  Diagnostic firstError() const {
    for (const Diagnostic& d : diagnostics.all()) {
      if (d.severity == Severity::Error) return d;
    }
    return {};
  }
};

/// Wraps node elements in a <materialx version="1.39"> document.
inline std::string mtlx(const std::string& body) {
  return "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\">\n" + body + "</materialx>\n";
}

/// A document with one open_pbr_surface (given its <input> elements) as material M.
inline std::string openPbrDocument(const std::string& inputs) {
  return mtlx("  <open_pbr_surface name=\"s\" type=\"surfaceshader\">\n" + inputs +
              "  </open_pbr_surface>\n  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" "
              "type=\"surfaceshader\" nodename=\"s\" /></surfacematerial>\n");
}

}  // namespace mxc::test
