#pragma once
/// \file
/// Source texts and positions inside them.

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace mxc {

/// A 1-based line and column. Columns count Unicode code points, so a caret under a
/// non-ASCII name lines up in a UTF-8 terminal.
struct LineColumn {
  uint32_t line = 0;
  uint32_t column = 0;
};

/// A text that was read (from a file or from memory) with the name used in messages.
/// Positions inside it are byte offsets; lines and columns are computed only when a
/// message or a report needs them, so parsing never pays for them.
class SourceFile {
 public:
  SourceFile(std::string path, std::string text);

  const std::string& path() const { return path_; }
  std::string_view text() const { return text_; }

  /// Line and column of a byte offset (offsets past the end map to the end).
  LineColumn lineColumn(uint32_t offset) const;
  /// The text of a 1-based line, without its line break.
  std::string_view lineText(uint32_t line) const;

 private:
  void buildLineIndex() const;

  std::string path_;
  std::string text_;
  mutable std::vector<uint32_t> lineStarts_;  // built on first use
};

/// A position in a source file. A default-constructed location means "no position"
/// (for example an input whose value comes from a built-in default).
struct SourceLocation {
  const SourceFile* file = nullptr;
  uint32_t offset = 0;

  bool valid() const { return file != nullptr; }
  LineColumn lineColumn() const { return file ? file->lineColumn(offset) : LineColumn{}; }
  uint32_t line() const { return lineColumn().line; }
  /// "path:line:column", or "" when there is no position.
  std::string str() const;
};

/// Owns every source text of a compilation so that locations stay valid while any
/// document, library or diagnostic refers to them.
class SourceManager {
 public:
  /// Keeps a text in memory under a name; returns the stable file object.
  const SourceFile& add(std::string path, std::string text);
  /// Every text kept so far, in the order they were added.
  const std::deque<std::unique_ptr<SourceFile>>& files() const { return files_; }

 private:
  std::deque<std::unique_ptr<SourceFile>> files_;
};

}  // namespace mxc
