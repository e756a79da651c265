#pragma once
/// \file
/// MaterialX data types and typed values (MaterialX Specification 1.39, "MaterialX Data Types").

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

namespace mxc::doc {

/// The types whose values can be written in a document. Shader, closure and material types
/// (surfaceshader, BSDF, EDF, VDF, material, ...) and user typedefs have no literal values:
/// they are ValueType::None here and carry an empty value string.
enum class ValueType : uint8_t {
  None,
  Boolean,
  Integer,
  Float,
  Vector2,
  Vector3,
  Vector4,
  Color3,
  Color4,
  Matrix33,
  Matrix44,
  String,
  Filename,
  GeomName,
  IntegerArray,
  FloatArray,
  Vector2Array,
  Vector3Array,
  Vector4Array,
  Color3Array,
  Color4Array,
  StringArray,
  GeomNameArray,
};

/// The value type named by a MaterialX type name, or ValueType::None for types without literal
/// values (shader, closure, material and custom types).
ValueType valueTypeOf(std::string_view typeName);
/// The MaterialX name of a value type ("none" for ValueType::None).
std::string_view typeName(ValueType type);
/// True for the MaterialX types the specification itself defines (values, shaders, closures,
/// material, "none" and "multioutput"); other names must come from a <typedef>.
bool isStandardTypeName(std::string_view typeName);
/// Number of float components of a vector, colour or matrix type (1 for float, 0 otherwise).
int componentCount(ValueType type);

/// A typed value. Vectors and colours are glm vectors. Documents write matrices row by row;
/// glm indexes column first, so the document's element in row r, column c is m[c][r].
class Value {
 public:
  using Data = std::variant<std::monostate, bool, int32_t, float, glm::vec2, glm::vec3, glm::vec4, glm::mat3,
                            glm::mat4, std::string, std::vector<int32_t>, std::vector<float>, std::vector<glm::vec2>,
                            std::vector<glm::vec3>, std::vector<glm::vec4>, std::vector<std::string>>;

  Value() = default;
  Value(ValueType type, Data data) : type_(type), data_(std::move(data)) {}

  ValueType type() const { return type_; }
  const Data& data() const { return data_; }
  template <typename T>
  const T& as() const {
    return std::get<T>(data_);
  }
  /// The float components of a float, vector, colour or matrix value (row-major for matrices).
  std::vector<float> components() const;

  /// The canonical document spelling: "0.8, 0.8, 0.8", "true", "1.5", strings as they are.
  std::string str() const;

  bool operator==(const Value& other) const = default;

 private:
  ValueType type_ = ValueType::None;
  Data data_;
};

/// Why a value string does not parse: `offset` is the byte inside the string where the bad
/// component starts, so the caller can point at it.
struct ValueError {
  size_t offset = 0;
  std::string message;
};

/// Parses a document value string of the given type (whitespace around components is allowed;
/// floats must be finite; integers must fit 32 bits). Types without literal values accept only
/// the empty string. Each number is read as MaterialX reads it, its longest prefix that is a
/// number ("0.5.0" is 0.5, an integer "2.5" is 2); where something after a number was ignored,
/// `ignored` (when given) says where and what, for a warning.
std::variant<Value, ValueError> parseValue(ValueType type, std::string_view text, ValueError* ignored = nullptr);

/// Parses, and returns nullopt with `error` filled on failure.
std::optional<Value> tryParseValue(ValueType type, std::string_view text, ValueError* error = nullptr,
                                   ValueError* ignored = nullptr);

/// Formats a float the shortest way that reads back to the same float ("0.8", "1", "1e-05").
std::string formatFloat(float value);

}  // namespace mxc::doc
