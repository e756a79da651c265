#pragma once
/// \file
/// Reading documents from files or memory, with xi:include.

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <unordered_set>
#include <variant>
#include <vector>

#include "compiler/common/Diagnostic.h"
#include "compiler/document/Document.h"
#include "compiler/xml/XmlParser.h"

namespace mxc::doc {

/// Loads documents and the documents they include, and owns them all. A file included twice
/// (a diamond) is loaded once; an include cycle is an error at the <xi:include> that closes it.
class DocumentLoader {
 public:
  DocumentLoader(SourceManager& sources, Diagnostics& diagnostics, xml::ParseOptions options = {});

  /// Loads a file. Returns null when it cannot be read or is not well-formed XML (the reason
  /// is in the diagnostics); otherwise the document, possibly with reported problems.
  const Document* loadFile(const std::filesystem::path& path);
  /// Loads a text held in memory under `name` (includes resolve relative to `name`'s folder).
  const Document* loadText(const std::string& name, std::string text);

  /// Every document loaded so far, in load order (includes before their includers).
  const std::vector<const Document*>& documents() const { return order_; }

 private:
  /// Reads a file into the sources; null (reported at `includedFrom`, or without a position)
  /// when it cannot.
  const SourceFile* read(const std::filesystem::path& path, SourceLocation includedFrom);
  /// Parses a text into a document (null when it is not well-formed XML), upgraded to 1.39.
  std::unique_ptr<Document> parse(const SourceFile& source);
  /// Loads `root` (known as `rootKey`) and every document it includes.
  const Document* loadTree(const SourceFile& root, const std::string& rootKey);

  SourceManager& sources_;
  Diagnostics& diagnostics_;
  xml::ParseOptions options_;
  std::vector<std::unique_ptr<Document>> owned_;
  std::map<std::string, const Document*> byPath_;  // files by normalised absolute path
  std::vector<std::string> loading_;            // include chain, for the message of a cycle
  std::unordered_set<std::string> loadingSet_;  // the same chain, for finding a cycle
  std::vector<const Document*> order_;
};

}  // namespace mxc::doc
