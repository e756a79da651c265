#include "compiler/common/SourceFile.h"

#include <algorithm>
#include <cstring>

namespace mxc {

SourceFile::SourceFile(std::string path, std::string text) : path_(std::move(path)), text_(std::move(text)) {}

void SourceFile::buildLineIndex() const {
  lineStarts_.push_back(0);
  const char* begin = text_.data();
  const char* end = begin + text_.size();
  for (const char* p = begin; p < end;) {
    const void* hit = std::memchr(p, '\n', static_cast<size_t>(end - p));
    if (!hit) break;
    p = static_cast<const char*>(hit) + 1;
    lineStarts_.push_back(static_cast<uint32_t>(p - begin));
  }
}

LineColumn SourceFile::lineColumn(uint32_t offset) const {
  if (lineStarts_.empty()) buildLineIndex();
  offset = std::min<uint32_t>(offset, static_cast<uint32_t>(text_.size()));
  // The last line start that is <= offset; lineStarts_[0] == 0 so the search never falls off the front.
  auto it = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset) - 1;
  uint32_t line = static_cast<uint32_t>(it - lineStarts_.begin()) + 1;
  uint32_t column = 1;
  uint32_t from = *it;
  // A UTF-8 byte-order mark is not a character of the first line.
  if (from == 0 && text_.size() >= 3 && text_.compare(0, 3, "\xEF\xBB\xBF") == 0 && offset >= 3) from = 3;
  for (uint32_t i = from; i < offset; ++i) {
    // UTF-8 continuation bytes (10xxxxxx) do not start a new code point.
    if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) ++column;
  }
  return {line, column};
}

std::string_view SourceFile::lineText(uint32_t line) const {
  if (lineStarts_.empty()) buildLineIndex();
  if (line == 0 || line > lineStarts_.size()) return {};
  uint32_t begin = lineStarts_[line - 1];
  uint32_t end = line < lineStarts_.size() ? lineStarts_[line] - 1 : static_cast<uint32_t>(text_.size());
  if (end > begin && text_[end - 1] == '\r') --end;
  return std::string_view(text_).substr(begin, end - begin);
}

std::string SourceLocation::str() const {
  if (!file) return {};
  LineColumn lc = lineColumn();
  return file->path() + ":" + std::to_string(lc.line) + ":" + std::to_string(lc.column);
}

const SourceFile& SourceManager::add(std::string path, std::string text) {
  files_.push_back(std::make_unique<SourceFile>(std::move(path), std::move(text)));
  return *files_.back();
}

}  // namespace mxc
