#include "compiler/document/DocumentLoader.h"

#include <optional>
#include <variant>

#include <fmt/format.h>

#include "compiler/common/InputFile.h"
#include "compiler/document/DocumentBuilder.h"
#include "compiler/document/Upgrade.h"

namespace mxc::doc {

namespace fs = std::filesystem;

DocumentLoader::DocumentLoader(SourceManager& sources, Diagnostics& diagnostics, xml::ParseOptions options)
    : sources_(sources), diagnostics_(diagnostics), options_(options) {}

const Document* DocumentLoader::loadFile(const fs::path& path) {
  const std::string key = fs::absolute(path).lexically_normal().string();
  if (auto it = byPath_.find(key); it != byPath_.end()) return it->second;
  const SourceFile* source = read(path, SourceLocation{});
  return source ? loadTree(*source, key) : nullptr;
}

const Document* DocumentLoader::loadText(const std::string& name, std::string text) {
  const SourceFile& source = sources_.add(name, std::move(text));
  return loadTree(source, fs::absolute(fs::path(name)).lexically_normal().string());
}

const SourceFile* DocumentLoader::read(const fs::path& path, SourceLocation includedFrom) {
  auto text = readInputFile(path, options_.maxInputBytes);
  if (auto* error = std::get_if<1>(&text)) {
    if (includedFrom.valid()) {
      diagnostics_.error(includedFrom, fmt::format("cannot read the included file '{}': {}", path.string(), *error));
    } else {
      diagnostics_.error({}, fmt::format("cannot read '{}': {}", path.string(), *error));
    }
    return nullptr;
  }
  return &sources_.add(path.string(), std::move(std::get<0>(text)));
}

std::unique_ptr<Document> DocumentLoader::parse(const SourceFile& source) {
  std::vector<Diagnostic> warnings;
  xml::ParseOptions options = options_;
  options.warnings = &warnings;  // MaterialX's leniencies, reported (xml::ParseOptions::warnings)
  std::optional<xml::Document> xml;
  std::optional<Diagnostic> error;
  try {
    xml.emplace(xml::parse(source, options));
  } catch (const CompileError& e) {
    error = e.diagnostic();
  }
  // The warnings come first: they are at positions before the error that stopped the parse.
  for (Diagnostic& w : warnings) diagnostics_.add(std::move(w));
  if (error) {
    diagnostics_.add(std::move(*error));
    return nullptr;
  }
  std::unique_ptr<Document> doc = buildDocument(std::move(*xml), diagnostics_);
  upgradeTo138(*doc, diagnostics_);
  upgradeTo139(*doc, diagnostics_);
  return doc;
}

const Document* DocumentLoader::loadTree(const SourceFile& root, const std::string& rootKey) {
  // Depth first over the includes with an explicit stack (a chain of 100,000 includes must not
  // need 100,000 frames of the machine's stack). A document is registered once all its
  // includes are: includes come before their includers in documents().
  struct Frame {
    std::unique_ptr<Document> doc;
    std::string key;
    fs::path folder;
    size_t next = 0;                      ///< the next include to follow
    const Document** slot = nullptr;      ///< the includer's Include::document, set when done
  };
  std::vector<Frame> stack;
  const Document* result = nullptr;
  auto open = [&](const SourceFile& source, const std::string& key, const Document** slot) {
    std::unique_ptr<Document> doc = parse(source);
    if (!doc) return;
    loading_.push_back(key);
    loadingSet_.insert(key);
    stack.push_back({std::move(doc), key, fs::path(source.path()).parent_path(), 0, slot});
  };
  open(root, rootKey, &result);
  while (!stack.empty()) {
    Frame& frame = stack.back();
    if (frame.next < frame.doc->includes.size()) {
      Include& include = frame.doc->includes[frame.next++];
      include.document = nullptr;
      fs::path target = fs::path(std::string(include.href));
      if (target.is_relative()) target = frame.folder / target;
      const std::string key = fs::absolute(target).lexically_normal().string();
      // The set answers "is it on the chain?" in constant time, so a chain of n includes loads
      // in O(n); the vector gives the order of the chain for the message.
      if (loadingSet_.count(key)) {
        size_t i = 0;
        while (loading_[i] != key) ++i;
        std::string chain;
        for (size_t k = i; k < loading_.size(); ++k) chain += fs::path(loading_[k]).filename().string() + " -> ";
        diagnostics_.error(include.location, fmt::format("include cycle: {}{}", chain, target.filename().string()));
        continue;
      }
      if (auto it = byPath_.find(key); it != byPath_.end()) {
        include.document = it->second;
        continue;
      }
      if (const SourceFile* source = read(target, include.location)) open(*source, key, &include.document);
      continue;
    }
    Document* raw = frame.doc.get();
    byPath_.emplace(frame.key, raw);  // a second text under the same name keeps the first entry
    owned_.push_back(std::move(frame.doc));
    order_.push_back(raw);
    *frame.slot = raw;
    loadingSet_.erase(frame.key);
    loading_.pop_back();
    stack.pop_back();
  }
  return result;
}

}  // namespace mxc::doc
