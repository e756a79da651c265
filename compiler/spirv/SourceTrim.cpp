#include "compiler/spirv/SourceTrim.h"

#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace mxc::spirv {
namespace {

inline bool isIdentifierStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
inline bool isIdentifierPart(char c) { return isIdentifierStart(c) || (c >= '0' && c <= '9'); }
bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

/// Comments removed (GLSL 4.60 section 3.4: a comment is a single space; a block comment's
/// newlines stay, so every line keeps its number). Nothing when a block comment never ends.
std::optional<std::string> withoutComments(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  size_t i = 0;
  while (i < text.size()) {
    const size_t slash = text.find('/', i);
    if (slash == std::string_view::npos || slash + 1 == text.size()) break;
    const char after = text[slash + 1];
    if (after != '/' && after != '*') {
      out.append(text, i, slash + 1 - i);
      i = slash + 1;
      continue;
    }
    out.append(text, i, slash - i);
    if (after == '/') {
      i = text.find('\n', slash);
      if (i == std::string_view::npos) return out;
      continue;
    }
    const size_t end = text.find("*/", slash + 2);
    if (end == std::string_view::npos) return std::nullopt;
    out += ' ';
    for (size_t k = slash + 2; k < end; ++k) {
      if (text[k] == '\n') out += '\n';
    }
    i = end + 2;
  }
  if (i < text.size()) out.append(text, i, std::string_view::npos);
  return out;
}

/// One line without its leading and trailing blanks.
std::string_view stripped(std::string_view line) {
  size_t b = 0, e = line.size();
  while (b < e && isBlank(line[b])) ++b;
  while (e > b && isBlank(line[e - 1])) --e;
  return line.substr(b, e - b);
}

/// The expression of an #if or #elif, on the macros defined so far.
class ConditionReader {
 public:
  ConditionReader(std::string_view text, const std::unordered_set<std::string>& defined)
      : text_(text), defined_(defined) {}

  /// Nothing when the expression holds something the trim does not evaluate.
  std::optional<bool> read() {
    std::optional<long> value = disjunction();
    skipBlanks();
    if (!value || pos_ != text_.size()) return std::nullopt;
    return *value != 0;
  }

 private:
  void skipBlanks() {
    while (pos_ < text_.size() && isBlank(text_[pos_])) ++pos_;
  }
  bool take(std::string_view token) {
    skipBlanks();
    if (text_.substr(pos_, token.size()) != token) return false;
    pos_ += token.size();
    return true;
  }
  std::string_view identifier() {
    skipBlanks();
    const size_t start = pos_;
    if (pos_ < text_.size() && isIdentifierStart(text_[pos_])) {
      while (pos_ < text_.size() && isIdentifierPart(text_[pos_])) ++pos_;
    }
    return text_.substr(start, pos_ - start);
  }
  std::optional<long> disjunction() {
    std::optional<long> left = conjunction();
    while (left && take("||")) {
      std::optional<long> right = conjunction();
      if (!right) return std::nullopt;
      left = (*left != 0 || *right != 0) ? 1 : 0;
    }
    return left;
  }
  std::optional<long> conjunction() {
    std::optional<long> left = unary();
    while (left && take("&&")) {
      std::optional<long> right = unary();
      if (!right) return std::nullopt;
      left = (*left != 0 && *right != 0) ? 1 : 0;
    }
    return left;
  }
  std::optional<long> unary() {
    skipBlanks();
    // `!=` is a comparison, which the trim does not evaluate.
    if (pos_ + 1 < text_.size() && text_[pos_] == '!' && text_[pos_ + 1] != '=') {
      ++pos_;
      std::optional<long> operand = unary();
      if (!operand) return std::nullopt;
      return *operand == 0 ? 1 : 0;
    }
    return primary();
  }
  std::optional<long> primary() {
    if (take("(")) {
      std::optional<long> inner = disjunction();
      if (!inner || !take(")")) return std::nullopt;
      return inner;
    }
    skipBlanks();
    if (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9') {
      long value = 0;
      while (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9') {
        if (value > 100000000) return std::nullopt;  // no overflow: large numbers are left to glslang
        value = value * 10 + (text_[pos_++] - '0');
      }
      if (pos_ < text_.size() && isIdentifierPart(text_[pos_])) return std::nullopt;  // 0x10, 1u
      return value;
    }
    if (identifier() != "defined") return std::nullopt;
    const bool parenthesised = take("(");
    const std::string_view name = identifier();
    if (parenthesised && !take(")")) return std::nullopt;
    // Only mxc's own macros: GL_ES, VULKAN, __VERSION__ and the like are glslang's to define.
    if (name.substr(0, 4) != "MXC_") return std::nullopt;
    return defined_.count(std::string(name)) ? 1 : 0;
  }

  std::string_view text_;
  const std::unordered_set<std::string>& defined_;
  size_t pos_ = 0;
};

struct Branch {
  bool parentActive;
  bool taken;  ///< a branch of this conditional was (or is being) taken
  bool active;
  bool sawElse = false;
};

/// The text with its lines stripped, conditional directives evaluated and the branches not taken
/// left as empty lines; where each directive line left starts, in `directiveStarts`.
std::optional<std::string> withConditionalsResolved(std::string_view text, std::vector<size_t>& directiveStarts) {
  std::string out;
  out.reserve(text.size());
  std::vector<Branch> branches;
  std::unordered_set<std::string> defined;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    const bool last = end == std::string_view::npos;
    if (last) end = text.size();
    const std::string_view line = stripped(text.substr(start, end - start));
    const bool active = branches.empty() || branches.back().active;
    bool keep = active;
    if (!line.empty() && line[0] == '#') {
      const std::string_view rest = stripped(line.substr(1));
      size_t n = 0;
      while (n < rest.size() && isIdentifierPart(rest[n])) ++n;
      const std::string_view directive = rest.substr(0, n);
      const std::string_view operand = stripped(rest.substr(n));
      auto evaluate = [&](std::string_view expression) -> std::optional<bool> {
        return ConditionReader(expression, defined).read();
      };
      if (directive == "if" || directive == "ifdef" || directive == "ifndef") {
        bool value = false;
        if (active) {
          std::optional<bool> v;
          if (directive == "if") {
            v = evaluate(operand);
          } else {
            v = evaluate("defined(" + std::string(operand) + ")");
            if (v && directive == "ifndef") v = !*v;
          }
          if (!v) return std::nullopt;
          value = *v;
        }
        branches.push_back({active, value, active && value});
        keep = false;
      } else if (directive == "elif" || directive == "else") {
        if (branches.empty() || branches.back().sawElse) return std::nullopt;
        Branch& b = branches.back();
        bool value = false;
        if (b.parentActive && !b.taken) {
          if (directive == "elif") {
            std::optional<bool> v = evaluate(operand);
            if (!v) return std::nullopt;
            value = *v;
          } else {
            value = true;
          }
        }
        b.active = value;
        b.taken = b.taken || value;
        b.sawElse = directive == "else";
        keep = false;
      } else if (directive == "endif") {
        if (branches.empty()) return std::nullopt;
        branches.pop_back();
        keep = false;
      } else if (active && (directive == "define" || directive == "undef")) {
        size_t m = 0;
        while (m < operand.size() && isIdentifierPart(operand[m])) ++m;
        const std::string name(operand.substr(0, m));
        if (directive == "define") {
          defined.insert(name);
        } else {
          defined.erase(name);
        }
      }
      if (keep) directiveStarts.push_back(out.size());
    }
    if (keep) out += line;
    if (last) break;
    out += '\n';
    start = end + 1;
  }
  if (!branches.empty()) return std::nullopt;
  return out;
}

/// A function definition at the top level of the text.
struct FunctionSpan {
  std::string_view name;
  size_t begin = 0, end = 0;  ///< characters, from its first token to its closing brace
  std::vector<std::string_view> uses;  ///< identifiers in it
  bool pinned = false;                 ///< never removed: holds a directive, or text not its own
};

}  // namespace

TrimmedSource trimForParse(std::string_view glsl) {
  TrimmedSource result;
  auto unchanged = [&] {
    result.text = std::string(glsl);
    return result;
  };
  std::optional<std::string> code = withoutComments(glsl);
  std::vector<size_t> directives;
  std::optional<std::string> resolved = code ? withConditionalsResolved(*code, directives) : std::nullopt;
  if (!resolved) return unchanged();
  std::string& text = *resolved;

  // Top-level units: declarations end at a `;` outside braces, function definitions at the `}`
  // that closes a body (a `{` right after a `)` at the top level: `struct S {` and
  // `uniform Block {` have a name before their brace).
  std::vector<FunctionSpan> functions;
  std::vector<std::string_view> roots{"main"};
  std::vector<std::string_view> pending;  // identifiers of the unit being read
  size_t unitBegin = std::string::npos;
  int depth = 0, parens = 0;
  char previous = 0;  // the previous token: its character if punctuation, 'a' an identifier, '0' a number
  std::string_view lastIdentifier, calledName;
  bool inFunction = false;
  bool directiveInUnit = false;  // a directive between the tokens of the unit being read
  int parenGroups = 0;           // parenthesised groups at the top level of the unit being read
  auto endUnit = [&] {
    unitBegin = std::string::npos;
    directiveInUnit = false;
    parenGroups = 0;
  };
  size_t next = 0;
  for (size_t i = 0; i < text.size();) {
    while (next < directives.size() && directives[next] < i) ++next;
    if (next < directives.size() && i == directives[next]) {
      // A directive runs to the end of its line; its identifiers (a macro's body) are roots.
      ++next;
      size_t end = text.find('\n', i);
      if (end == std::string::npos) end = text.size();
      for (size_t k = i; k < end;) {
        if (isIdentifierStart(text[k])) {
          const size_t s = k;
          while (k < end && isIdentifierPart(text[k])) ++k;
          roots.push_back(std::string_view(text).substr(s, k - s));
        } else {
          ++k;
        }
      }
      if (inFunction) functions.back().pinned = true;
      if (unitBegin != std::string::npos) directiveInUnit = true;
      i = end;
      continue;
    }
    const char c = text[i];
    if (isBlank(c) || c == '\n') {
      ++i;
      continue;
    }
    if (unitBegin == std::string::npos) unitBegin = i;
    if (isIdentifierStart(c)) {
      const size_t s = i;
      while (i < text.size() && isIdentifierPart(text[i])) ++i;
      lastIdentifier = std::string_view(text).substr(s, i - s);
      pending.push_back(lastIdentifier);
      previous = 'a';
      continue;
    }
    if (c >= '0' && c <= '9') {  // a number with its suffix or exponent letters: 1.0e-5f, 0x1Fu
      while (i < text.size() && (isIdentifierPart(text[i]) || text[i] == '.')) ++i;
      previous = '0';
      continue;
    }
    ++i;
    if (depth == 0 && !inFunction) {
      if (c == '(') {
        if (parens++ == 0) {
          calledName = previous == 'a' ? lastIdentifier : std::string_view{};
          ++parenGroups;
        }
      } else if (c == ')') {
        --parens;
      } else if (c == '{' && previous == ')' && parens == 0 && !calledName.empty()) {
        inFunction = true;
        // A definition has one parenthesised group before its body, its parameters; more (a
        // macro invoked without a `;` before it) and its text is not only the function's.
        functions.push_back({calledName, unitBegin, 0, {}, directiveInUnit || parenGroups > 1});
      } else if (c == ';' && parens == 0) {
        roots.insert(roots.end(), pending.begin(), pending.end());
        pending.clear();
        endUnit();
      }
    }
    if (c == '{') ++depth;
    if (c == '}') {
      if (--depth < 0) return unchanged();  // unbalanced: glslang will say so
      if (depth == 0 && inFunction) {
        FunctionSpan& f = functions.back();
        f.end = i;
        f.uses = std::move(pending);
        pending.clear();
        inFunction = false;
        endUnit();
      }
    }
    previous = c;
  }
  if (depth != 0 || inFunction) return unchanged();
  roots.insert(roots.end(), pending.begin(), pending.end());  // a last unit without its `;`

  // Functions reachable from the roots, overloads together. Most identifiers name no function:
  // one lookup each, and a name is followed once.
  struct Overloads {
    std::vector<size_t> functions;
    bool followed = false;
  };
  std::unordered_map<std::string_view, Overloads> byName;
  byName.reserve(functions.size());
  for (size_t k = 0; k < functions.size(); ++k) {
    byName[functions[k].name].functions.push_back(k);
    if (functions[k].pinned) roots.push_back(functions[k].name);
  }
  std::vector<bool> kept(functions.size(), false);
  while (!roots.empty()) {
    auto found = byName.find(roots.back());
    roots.pop_back();
    if (found == byName.end() || found->second.followed) continue;
    found->second.followed = true;
    for (size_t k : found->second.functions) {
      kept[k] = true;
      roots.insert(roots.end(), functions[k].uses.begin(), functions[k].uses.end());
    }
  }

  // Removed functions leave their newlines.
  std::string out;
  out.reserve(text.size());
  size_t from = 0;
  for (size_t k = 0; k < functions.size(); ++k) {
    if (kept[k]) continue;
    out.append(text, from, functions[k].begin - from);
    for (size_t p = functions[k].begin; p < functions[k].end; ++p) {
      if (text[p] == '\n') out += '\n';
    }
    from = functions[k].end;
    ++result.functionsRemoved;
  }
  out.append(text, from, std::string::npos);
  result.text = std::move(out);
  result.trimmed = true;
  return result;
}

}  // namespace mxc::spirv
