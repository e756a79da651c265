#include "compiler/document/DocumentLoader.h"

#include <variant>

#include <fmt/format.h>

#include "compiler/common/InputFile.h"
#include "compiler/document/DocumentBuilder.h"
#include "compiler/document/Upgrade.h"

namespace mxc::doc {

namespace fs = std::filesystem;

DocumentLoader::DocumentLoader(SourceManager& sources, Diagnostics& diagnostics, xml::ParseOptions options)
    : sources_(sources), diagnostics_(diagnostics), options_(options) {}

const Document* DocumentLoader::loadFile(const fs::path& path) { return load(path, SourceLocation{}); }

const Document* DocumentLoader::loadText(const std::string& name, std::string text) {
  const SourceFile& source = sources_.add(name, std::move(text));
  std::string key = fs::absolute(fs::path(name)).lexically_normal().string();
  loading_.push_back(key);
  loadingSet_.insert(key);
  const Document* doc = finish(source);
  loadingSet_.erase(key);
  loading_.pop_back();
  return doc;
}

const Document* DocumentLoader::load(const fs::path& path, SourceLocation includedFrom) {
  const std::string key = fs::absolute(path).lexically_normal().string();
  // The set answers "is it on the chain?" in constant time, so a chain of n includes loads in
  // O(n); the vector gives the order of the chain for the message.
  if (loadingSet_.count(key)) {
    size_t i = 0;
    while (loading_[i] != key) ++i;
    std::string chain;
    for (size_t k = i; k < loading_.size(); ++k) chain += fs::path(loading_[k]).filename().string() + " -> ";
    diagnostics_.error(includedFrom, fmt::format("include cycle: {}{}", chain, path.filename().string()));
    return nullptr;
  }
  if (auto it = byPath_.find(key); it != byPath_.end()) return it->second;

  auto text = readInputFile(path, options_.maxInputBytes);
  if (auto* error = std::get_if<1>(&text)) {
    if (includedFrom.valid()) {
      diagnostics_.error(includedFrom, fmt::format("cannot read the included file '{}': {}", path.string(), *error));
    } else {
      diagnostics_.error({}, fmt::format("cannot read '{}': {}", path.string(), *error));
    }
    return nullptr;
  }
  const SourceFile& source = sources_.add(path.string(), std::move(std::get<0>(text)));
  loading_.push_back(key);
  loadingSet_.insert(key);
  const Document* doc = finish(source);
  loadingSet_.erase(key);
  loading_.pop_back();
  return doc;
}

const Document* DocumentLoader::finish(const SourceFile& source) {
  std::unique_ptr<Document> doc;
  try {
    doc = buildDocument(xml::parse(source, options_), diagnostics_);
  } catch (const CompileError& e) {
    diagnostics_.add(e.diagnostic());
    return nullptr;
  }
  upgradeTo139(*doc, diagnostics_);
  const fs::path folder = fs::path(source.path()).parent_path();
  for (Include& include : doc->includes) {
    fs::path target = fs::path(std::string(include.href));
    if (target.is_relative()) target = folder / target;
    include.document = load(target, include.location);
  }
  Document* raw = doc.get();
  byPath_.emplace(loading_.back(), raw);  // a second text under the same name keeps the first entry
  owned_.push_back(std::move(doc));
  order_.push_back(raw);
  return raw;
}

}  // namespace mxc::doc
