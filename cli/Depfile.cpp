#include "cli/Depfile.h"

#include <algorithm>
#include <string_view>

#include <fmt/format.h>

namespace mxc::cli {
namespace {

/// Characters with no spelling both tools read back, and why. Measured with GNU Make 4.3 and
/// Ninja 1.11.1 (a rule per character, checked up to date after a build and out of date after
/// its input is touched):
/// - Make reads '%' as a pattern, '=' as an assignment, '(' ')' as an archive member and ';' as
///   the start of a recipe; '|' starts order-only prerequisites in both.
/// - Ninja 1.11's depfile lexer ends a file name at any character outside its set
///   [A-Za-z0-9+,/_:.~()}{%=@[]!-] and bytes >= 0x80 (besides the escapes below), so
///   * ? ' " & ^ < > ` would split the path in two and track the wrong files.
/// - A line break or tab ends a word in both.
constexpr std::string_view kUnspellable = "%=();|*?'\"&^<>`\t\n\r\v\f";

std::string_view reasonFor(char c) {
  switch (c) {
    case '%': return "GNU Make reads it as a pattern";
    case '=': return "GNU Make reads it as an assignment";
    case '(': case ')': return "GNU Make reads it as an archive member";
    case ';': return "GNU Make reads it as the start of a recipe";
    case '|': return "Make and Ninja read it as the start of order-only prerequisites";
    case '\t': case '\n': case '\r': case '\v': case '\f': return "it ends a word in Make and Ninja";
    default: return "Ninja 1.11 ends a file name there";
  }
}

std::string printable(char c) {
  if (c == '\t') return "a tab";
  if (c == '\n') return "a line break";
  if (c == '\r' || c == '\v' || c == '\f') return fmt::format("control character 0x{:02x}", static_cast<unsigned char>(c));
  return fmt::format("'{}'", c);
}

}  // namespace

std::optional<std::string> depfileWord(const std::string& path, std::string& error) {
  std::string out;
  size_t backslashes = 0;  // the run of backslashes just before the character at hand
  for (char c : path) {
    if (kUnspellable.find(c) != std::string_view::npos) {
      error = fmt::format("{} holds {}, which a depfile cannot spell: {}", path, printable(c), reasonFor(c));
      return std::nullopt;
    }
    if (c == '\\') {
      ++backslashes;
      continue;
    }
    if (backslashes > 0 && (c == '#' || c == ':' || c == '$')) {
      // Make reads 2N+1 backslashes and '#' as N and '#' where Ninja drops just one, and a
      // backslash before "\:" or "$$" means something else in each: no spelling agrees.
      error = fmt::format("{} holds a backslash before '{}', which Make and Ninja read differently in a depfile", path, c);
      return std::nullopt;
    }
    if (c == ' ') {
      // Both read 2N+1 backslashes and a space as N backslashes and a space (GCC's spelling).
      out.append(2 * backslashes + 1, '\\');
    } else {
      out.append(backslashes, '\\');
      // '#' would start a comment, ':' end the targets (both read "\#" and "\:" back), and '$'
      // a variable (both read "$$" back).
      if (c == '#' || c == ':') out += '\\';
      if (c == '$') out += '$';
    }
    backslashes = 0;
    out += c;
  }
  if (backslashes > 0) {
    // A trailing backslash before the separating space or line break would escape it.
    error = fmt::format("{} ends in a backslash, which a depfile cannot spell", path);
    return std::nullopt;
  }
  return out;
}

std::optional<std::string> depfileText(const std::vector<std::filesystem::path>& written,
                                       std::vector<std::filesystem::path> read, std::string& error) {
  for (auto& path : read) path = std::filesystem::absolute(path).lexically_normal();
  std::sort(read.begin(), read.end());
  read.erase(std::unique(read.begin(), read.end()), read.end());
  std::string out;
  for (const auto& path : written) {
    auto word = depfileWord(path.string(), error);
    if (!word) return std::nullopt;
    out += (out.empty() ? "" : " ") + *word;
  }
  out += ":";
  for (const auto& path : read) {
    auto word = depfileWord(path.string(), error);
    if (!word) return std::nullopt;
    out += " \\\n  " + *word;
  }
  return out + "\n";
}

}  // namespace mxc::cli
