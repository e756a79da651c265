#include "compiler/library/StructType.h"

#include <fmt/format.h>

#include "compiler/library/NodeLibrary.h"

namespace mxc::lib {

const StructType::Member* StructType::findMember(std::string_view memberName) const {
  for (const Member& m : members) {
    if (m.name == memberName) return &m;
  }
  return nullptr;
}

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

/// Reads `text` (which starts at `base` in the whole literal) as a value of `type` into `out`.
std::optional<doc::ValueError> parseInto(const StructType& type, const NodeLibrary& library, std::string_view text,
                                         size_t base, std::vector<doc::Value>& out) {
  size_t begin = 0;
  size_t end = text.size();
  while (begin < end && isSpace(text[begin])) ++begin;
  while (end > begin && isSpace(text[end - 1])) --end;
  if (begin == end || text[begin] != '{' || text[end - 1] != '}') {
    return doc::ValueError{base + begin, fmt::format("a {} value is written {{member;member;...}} with {} member{}",
                                                     type.name, type.members.size(),
                                                     type.members.size() == 1 ? "" : "s")};
  }
  // The parts between the outer braces, split at the semicolons outside nested braces.
  std::vector<std::pair<size_t, size_t>> parts;  // [start, end) in text
  int depth = 0;
  size_t start = begin + 1;
  for (size_t i = begin + 1; i + 1 < end; ++i) {
    if (text[i] == '{') ++depth;
    if (text[i] == '}') {
      if (depth == 0) return doc::ValueError{base + i, "unbalanced '}'"};
      --depth;
    }
    if (text[i] == ';' && depth == 0) {
      parts.emplace_back(start, i);
      start = i + 1;
    }
  }
  if (depth != 0) return doc::ValueError{base + begin, "unbalanced '{'"};
  parts.emplace_back(start, end - 1);
  if (parts.size() != type.members.size()) {
    std::vector<std::string_view> names;
    for (const StructType::Member& m : type.members) names.push_back(m.name);
    return doc::ValueError{base + begin, fmt::format("{} has {} member{} ({}), the value gives {}", type.name,
                                                     names.size(), names.size() == 1 ? "" : "s",
                                                     fmt::join(names, ", "), parts.size())};
  }
  for (size_t i = 0; i < parts.size(); ++i) {
    const StructType::Member& member = type.members[i];
    const std::string_view part = text.substr(parts[i].first, parts[i].second - parts[i].first);
    if (const StructType* inner = library.structType(member.type)) {
      if (auto error = parseInto(*inner, library, part, base + parts[i].first, out)) return error;
      continue;
    }
    auto value = doc::parseValue(doc::valueTypeOf(member.type), part);
    if (auto* error = std::get_if<doc::ValueError>(&value)) {
      return doc::ValueError{base + parts[i].first + error->offset,
                             fmt::format("member '{}' ({}): {}", member.name, member.type, error->message)};
    }
    out.push_back(std::get<doc::Value>(std::move(value)));
  }
  return std::nullopt;
}

}  // namespace

std::variant<std::vector<doc::Value>, doc::ValueError> parseStructValue(const StructType& type,
                                                                        const NodeLibrary& library,
                                                                        std::string_view text) {
  std::vector<doc::Value> leaves;
  if (auto error = parseInto(type, library, text, 0, leaves)) return *error;
  return leaves;
}

}  // namespace mxc::lib
