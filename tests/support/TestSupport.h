#pragma once
// Helpers shared by the tests: load a document from text against the built-in library and
// look at what was reported.

#include <filesystem>
#include <memory>
#include <string>

#include "compiler/common/Diagnostic.h"
#include "compiler/document/DocumentLoader.h"
#include "compiler/library/LibraryStack.h"
#include "compiler/resolve/Resolver.h"

namespace mxc::test {

/// The shared reference data (corpus, MaterialX libraries), at ../shared from the source tree.
inline std::filesystem::path sharedDir() { return std::filesystem::path(MXC_SHARED_DIR); }
inline std::filesystem::path sourceDir() { return std::filesystem::path(MXC_SOURCE_DIR); }

/// One compilation context: sources, diagnostics, the built-in library, and a loader.
struct Context {
  SourceManager sources;
  Diagnostics diagnostics;
  lib::LibraryStack libraries{sources, diagnostics};
  doc::DocumentLoader loader{sources, diagnostics};

  explicit Context(bool builtin = true) {
    if (builtin) libraries.addBuiltin();
  }

  const doc::Document* load(const std::string& text, const std::string& name = "test.mtlx") {
    return loader.loadText(name, text);
  }

  /// Loads and resolves; the result stays valid as long as the context.
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

}  // namespace mxc::test
