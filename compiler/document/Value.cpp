#include "compiler/document/Value.h"

#include <charconv>
#include <cmath>
#include <utility>

#include <fmt/format.h>

namespace mxc::doc {

namespace {

struct TypeName {
  std::string_view name;
  ValueType type;
};

constexpr TypeName kValueTypes[] = {
    {"boolean", ValueType::Boolean},       {"integer", ValueType::Integer},
    {"float", ValueType::Float},           {"vector2", ValueType::Vector2},
    {"vector3", ValueType::Vector3},       {"vector4", ValueType::Vector4},
    {"color3", ValueType::Color3},         {"color4", ValueType::Color4},
    {"matrix33", ValueType::Matrix33},     {"matrix44", ValueType::Matrix44},
    {"string", ValueType::String},         {"filename", ValueType::Filename},
    {"geomname", ValueType::GeomName},     {"integerarray", ValueType::IntegerArray},
    {"floatarray", ValueType::FloatArray}, {"vector2array", ValueType::Vector2Array},
    {"vector3array", ValueType::Vector3Array}, {"vector4array", ValueType::Vector4Array},
    {"color3array", ValueType::Color3Array},   {"color4array", ValueType::Color4Array},
    {"stringarray", ValueType::StringArray},   {"geomnamearray", ValueType::GeomNameArray},
};

// Types of the specification without literal values.
constexpr std::string_view kValuelessTypes[] = {
    "surfaceshader", "displacementshader", "volumeshader", "lightshader", "material",
    "BSDF",          "EDF",                "VDF",          "none",        "multioutput",
};

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

/// A comma-separated component with its offset in the whole string, trimmed of whitespace.
struct Token {
  std::string_view text;
  size_t offset;
};

std::vector<Token> splitComponents(std::string_view text) {
  std::vector<Token> out;
  size_t start = 0;
  for (;;) {
    size_t comma = text.find(',', start);
    size_t end = comma == std::string_view::npos ? text.size() : comma;
    size_t b = start;
    size_t e = end;
    while (b < e && isSpace(text[b])) ++b;
    while (e > b && isSpace(text[e - 1])) --e;
    out.push_back({text.substr(b, e - b), b});
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

/// The numbers of a numeric value: separated by commas, by white space, or both, empty pieces
/// skipped. MaterialX reads "0.944 0.776 0.373" and "1 1,1" that way (its array separators are
/// ", "), and documents in the wild write both.
std::vector<Token> splitNumbers(std::string_view text) {
  std::vector<Token> out;
  size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ',' || isSpace(text[i]))) ++i;
    const size_t begin = i;
    while (i < text.size() && text[i] != ',' && !isSpace(text[i])) ++i;
    if (i > begin) out.push_back({text.substr(begin, i - begin), begin});
  }
  return out;
}

/// MaterialX reads each number as a C++ stream does (`std::stringstream >> value`, its
/// Value.cpp): the longest prefix that is a number, the rest of the component ignored, so its
/// own test suite's "0.5.0" is 0.5 and an integer written "2.5" is 2. mxc reads the same
/// numbers and says, through `ignored`, where it read past something (the first such place).
void noteIgnored(const Token& token, const char* begin, const char* end, std::string_view read, ValueError* ignored) {
  if (!ignored || !ignored->message.empty()) return;
  const auto used = static_cast<size_t>(end - begin) + (token.text.data() == begin ? 0u : 1u);  // the '+' skipped
  ignored->offset = token.offset + used;
  ignored->message = fmt::format("'{}' is read as {}, as MaterialX reads it: '{}' after the number is ignored", token.text,
                                 read, token.text.substr(used));
}

std::optional<float> parseFloat(const Token& token, ValueError& error, ValueError* ignored) {
  std::string_view t = token.text;
  if (t.empty()) {
    error = {token.offset, "expected a number"};
    return std::nullopt;
  }
  // from_chars does not take a leading '+', which documents sometimes write.
  if (t[0] == '+') t.remove_prefix(1);
  float value = 0;
  auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) {
    error = {token.offset, fmt::format("'{}' is out of the range of a 32-bit float", token.text)};
    return std::nullopt;
  }
  if (ec != std::errc()) {
    error = {token.offset, fmt::format("'{}' is not a number", token.text)};
    return std::nullopt;
  }
  // from_chars accepts "inf" and "nan"; a material parameter must be finite (and MaterialX's
  // stream does not read them).
  if (!std::isfinite(value)) {
    error = {token.offset, fmt::format("'{}' is not a finite number", token.text)};
    return std::nullopt;
  }
  if (end != t.data() + t.size()) noteIgnored(token, t.data(), end, formatFloat(value), ignored);
  return value;
}

std::optional<int32_t> parseInteger(const Token& token, ValueError& error, ValueError* ignored) {
  std::string_view t = token.text;
  if (!t.empty() && t[0] == '+') t.remove_prefix(1);
  int32_t value = 0;
  auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec == std::errc::result_out_of_range) {
    error = {token.offset, fmt::format("'{}' does not fit a 32-bit integer", token.text)};
    return std::nullopt;
  }
  if (t.empty() || ec != std::errc()) {
    error = {token.offset, fmt::format("'{}' is not an integer", token.text)};
    return std::nullopt;
  }
  if (end != t.data() + t.size()) noteIgnored(token, t.data(), end, std::to_string(value), ignored);
  return value;
}

/// Parses exactly `count` floats (count > 0), or a multiple of `count` when `array` is set.
std::optional<std::vector<float>> parseFloats(std::string_view text, size_t count, bool array, std::string_view name,
                                              ValueError& error, ValueError* ignored) {
  std::vector<float> out;
  std::vector<Token> tokens = splitNumbers(text);
  for (const Token& token : tokens) {
    std::optional<float> f = parseFloat(token, error, ignored);
    if (!f) return std::nullopt;
    out.push_back(*f);
  }
  if (array ? out.size() % count != 0 : out.size() != count) {
    error = {0, array ? fmt::format("a {} value needs a multiple of {} numbers, found {}", name, count, out.size())
                      : fmt::format("a {} value needs {} number{}, found {}", name, count, count == 1 ? "" : "s",
                                    out.size())};
    return std::nullopt;
  }
  return out;
}

template <typename Vec>
std::vector<Vec> group(const std::vector<float>& f) {
  constexpr int n = Vec::length();
  std::vector<Vec> out(f.size() / n);
  for (size_t i = 0; i < out.size(); ++i) {
    for (int k = 0; k < n; ++k) out[i][k] = f[i * n + static_cast<size_t>(k)];
  }
  return out;
}

}  // namespace

ValueType valueTypeOf(std::string_view name) {
  for (const TypeName& t : kValueTypes) {
    if (t.name == name) return t.type;
  }
  return ValueType::None;
}

std::string_view typeName(ValueType type) {
  for (const TypeName& t : kValueTypes) {
    if (t.type == type) return t.name;
  }
  return "none";
}

bool isStandardTypeName(std::string_view name) {
  if (valueTypeOf(name) != ValueType::None) return true;
  for (std::string_view t : kValuelessTypes) {
    if (t == name) return true;
  }
  return false;
}

int componentCount(ValueType type) {
  switch (type) {
    case ValueType::Float: return 1;
    case ValueType::Vector2: return 2;
    case ValueType::Vector3:
    case ValueType::Color3: return 3;
    case ValueType::Vector4:
    case ValueType::Color4: return 4;
    case ValueType::Matrix33: return 9;
    case ValueType::Matrix44: return 16;
    default: return 0;
  }
}

std::variant<Value, ValueError> parseValue(ValueType type, std::string_view text, ValueError* ignored) {
  ValueError error;
  auto fail = [&]() -> std::variant<Value, ValueError> { return error; };
  switch (type) {
    case ValueType::None: {
      if (text.find_first_not_of(" \t\n\r") != std::string_view::npos) {
        return ValueError{0, "this type has no literal values (only an empty value is allowed)"};
      }
      return Value();
    }
    case ValueType::Boolean: {
      Token t = splitComponents(text)[0];
      if (t.text == "true") return Value(type, true);
      if (t.text == "false") return Value(type, false);
      return ValueError{t.offset, fmt::format("'{}' is not a boolean (write true or false)", t.text)};
    }
    case ValueType::Integer: {
      std::vector<Token> tokens = splitNumbers(text);
      if (tokens.size() != 1) return ValueError{0, fmt::format("an integer value needs 1 number, found {}", tokens.size())};
      auto i = parseInteger(tokens[0], error, ignored);
      if (!i) return fail();
      return Value(type, *i);
    }
    case ValueType::Float:
    case ValueType::Vector2:
    case ValueType::Vector3:
    case ValueType::Vector4:
    case ValueType::Color3:
    case ValueType::Color4:
    case ValueType::Matrix33:
    case ValueType::Matrix44: {
      const auto n = static_cast<size_t>(componentCount(type));
      auto f = parseFloats(text, n, false, typeName(type), error, ignored);
      if (!f) return fail();
      const std::vector<float>& v = *f;
      switch (type) {
        case ValueType::Float: return Value(type, v[0]);
        case ValueType::Vector2: return Value(type, glm::vec2(v[0], v[1]));
        case ValueType::Vector3:
        case ValueType::Color3: return Value(type, glm::vec3(v[0], v[1], v[2]));
        case ValueType::Vector4:
        case ValueType::Color4: return Value(type, glm::vec4(v[0], v[1], v[2], v[3]));
        case ValueType::Matrix33: {
          glm::mat3 m;
          for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) m[c][r] = v[static_cast<size_t>(r * 3 + c)];
          return Value(type, m);
        }
        default: {
          glm::mat4 m;
          for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) m[c][r] = v[static_cast<size_t>(r * 4 + c)];
          return Value(type, m);
        }
      }
    }
    case ValueType::String:
    case ValueType::Filename:
    case ValueType::GeomName: return Value(type, std::string(text));
    case ValueType::IntegerArray: {
      std::vector<int32_t> out;
      for (const Token& t : splitNumbers(text)) {
        auto i = parseInteger(t, error, ignored);
        if (!i) return fail();
        out.push_back(*i);
      }
      return Value(type, std::move(out));
    }
    case ValueType::FloatArray: {
      auto f = parseFloats(text, 1, true, "floatarray", error, ignored);
      if (!f) return fail();
      return Value(type, std::move(*f));
    }
    case ValueType::Vector2Array: {
      auto f = parseFloats(text, 2, true, "vector2array", error, ignored);
      if (!f) return fail();
      return Value(type, group<glm::vec2>(*f));
    }
    case ValueType::Vector3Array:
    case ValueType::Color3Array: {
      auto f = parseFloats(text, 3, true, typeName(type), error, ignored);
      if (!f) return fail();
      return Value(type, group<glm::vec3>(*f));
    }
    case ValueType::Vector4Array:
    case ValueType::Color4Array: {
      auto f = parseFloats(text, 4, true, typeName(type), error, ignored);
      if (!f) return fail();
      return Value(type, group<glm::vec4>(*f));
    }
    case ValueType::StringArray:
    case ValueType::GeomNameArray: {
      std::vector<std::string> out;
      if (text.find_first_not_of(" \t\n\r") != std::string_view::npos) {
        for (const Token& t : splitComponents(text)) out.emplace_back(t.text);
      }
      return Value(type, std::move(out));
    }
  }
  return ValueError{0, "unknown type"};
}

std::optional<Value> tryParseValue(ValueType type, std::string_view text, ValueError* error, ValueError* ignored) {
  auto result = parseValue(type, text, ignored);
  if (auto* v = std::get_if<Value>(&result)) return std::move(*v);
  if (error) *error = std::get<ValueError>(result);
  return std::nullopt;
}

std::string formatFloat(float value) {
  // Shortest round-trip spelling (std::to_chars without a precision).
  char buffer[32];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);
  (void)ec;  // 32 bytes always hold a float's shortest form
  return std::string(buffer, end);
}

std::vector<float> Value::components() const {
  return std::visit(
      [&](const auto& d) -> std::vector<float> {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, float>) {
          return {d};
        } else if constexpr (std::is_same_v<T, glm::vec2> || std::is_same_v<T, glm::vec3> ||
                             std::is_same_v<T, glm::vec4>) {
          std::vector<float> out;
          for (int i = 0; i < T::length(); ++i) out.push_back(d[i]);
          return out;
        } else if constexpr (std::is_same_v<T, glm::mat3> || std::is_same_v<T, glm::mat4>) {
          std::vector<float> out;
          for (int r = 0; r < T::length(); ++r)
            for (int c = 0; c < T::length(); ++c) out.push_back(d[c][r]);
          return out;
        } else if constexpr (std::is_same_v<T, std::vector<float>>) {
          return d;
        } else {
          return {};
        }
      },
      data_);
}

std::string Value::str() const {
  return std::visit(
      [&](const auto& d) -> std::string {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, std::monostate>) {
          return "";
        } else if constexpr (std::is_same_v<T, bool>) {
          return d ? "true" : "false";
        } else if constexpr (std::is_same_v<T, int32_t>) {
          return std::to_string(d);
        } else if constexpr (std::is_same_v<T, std::string>) {
          return d;
        } else if constexpr (std::is_same_v<T, std::vector<int32_t>>) {
          std::string out;
          for (size_t i = 0; i < d.size(); ++i) out += (i ? ", " : "") + std::to_string(d[i]);
          return out;
        } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
          std::string out;
          for (size_t i = 0; i < d.size(); ++i) out += (i ? ", " : "") + d[i];
          return out;
        } else {
          std::vector<float> parts;
          if constexpr (std::is_same_v<T, std::vector<glm::vec2>> || std::is_same_v<T, std::vector<glm::vec3>> ||
                        std::is_same_v<T, std::vector<glm::vec4>>) {
            for (const auto& v : d)
              for (int k = 0; k < v.length(); ++k) parts.push_back(v[k]);
          } else {
            parts = components();
          }
          std::string out;
          for (size_t i = 0; i < parts.size(); ++i) out += (i ? ", " : "") + formatFloat(parts[i]);
          return out;
        }
      },
      data_);
}

}  // namespace mxc::doc
