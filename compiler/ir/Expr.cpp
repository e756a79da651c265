#include "compiler/ir/Expr.h"

#include <algorithm>
#include <cstring>
#include <type_traits>
#include <variant>

#include <fmt/format.h>

namespace mxc::ir {

std::string_view typeName(Type type) {
  switch (type) {
    case Type::Bool: return "bool";
    case Type::Int: return "int";
    case Type::Float: return "float";
    case Type::Vec2: return "vec2";
    case Type::Vec3: return "vec3";
    case Type::Vec4: return "vec4";
    case Type::Mat3: return "mat3";
    case Type::Mat4: return "mat4";
    case Type::String: return "string";
  }
  return "?";
}

int componentCount(Type type) {
  switch (type) {
    case Type::Float: return 1;
    case Type::Vec2: return 2;
    case Type::Vec3: return 3;
    case Type::Vec4: return 4;
    case Type::Mat3: return 9;
    case Type::Mat4: return 16;
    default: return 0;
  }
}

Type vectorType(int n) {
  switch (n) {
    case 2: return Type::Vec2;
    case 3: return Type::Vec3;
    case 4: return Type::Vec4;
    default: return Type::Float;
  }
}

bool irTypeOf(std::string_view t, Type& type) {
  if (t == "float") type = Type::Float;
  else if (t == "integer") type = Type::Int;
  else if (t == "boolean") type = Type::Bool;
  else if (t == "vector2") type = Type::Vec2;
  else if (t == "vector3" || t == "color3") type = Type::Vec3;
  else if (t == "vector4" || t == "color4") type = Type::Vec4;
  else if (t == "matrix33") type = Type::Mat3;
  else if (t == "matrix44") type = Type::Mat4;
  else if (t == "string" || t == "filename") type = Type::String;
  else return false;
  return true;
}

std::string_view opName(Op op) {
  static constexpr std::string_view names[] = {
      "constant", "parameter", "geomprop", "texture", "add", "sub", "mul", "div", "mod", "neg", "abs", "sign",
      "floor", "ceil", "round", "fract", "min", "max", "clamp", "mix", "pow", "sqrt", "exp", "ln", "sin", "cos",
      "tan", "asin", "acos", "atan2", "step", "smoothstep", "dot", "cross", "length", "normalize", "reflect",
      "refract", "splat", "construct", "extract", "swizzle", "greater", "greatereq", "equal", "and", "or", "not",
      "select", "matmul", "transpose", "determinant", "inverse", "luminance", "rgbtohsv", "hsvtorgb", "noise2d",
      "noise3d", "fractal3d", "cellnoise2d", "cellnoise3d", "worleynoise2d", "worleynoise3d", "flake", "image", "imagemissing", "normalmap",
      "heighttonormal", "rotate3d", "rotate2d", "transformpoint", "transformvector", "transformnormal", "local"};
  static_assert(sizeof(names) / sizeof(names[0]) == static_cast<size_t>(Op::Local) + 1,
                "every Op has a name");
  return names[static_cast<size_t>(op)];
}

bool hasTextPayload(Op op) {
  switch (op) {
    case Op::Parameter:
    case Op::GeomProp:
    case Op::Texture:
    case Op::Swizzle:
    case Op::ImageSample:
    case Op::ImageMissing:
    case Op::TransformPoint:
    case Op::TransformVector:
    case Op::TransformNormal:
    case Op::Local: return true;
    default: return false;
  }
}

uint32_t ExprGraph::internString(std::string_view text) {
  auto [it, inserted] = stringIndex_.emplace(std::string(text), static_cast<uint32_t>(strings_.size()));
  if (inserted) strings_.emplace_back(text);
  return it->second;
}

uint32_t ExprGraph::internConstant(const doc::Value& value) {
  // Key: the type, then the raw bytes of a scalar, vector or matrix (bit-exact, so 0 and -0
  // stay distinct constants), else the value's text. No float formatting on the common path.
  std::string key(1, static_cast<char>(value.type()));
  const bool raw = std::visit(
      [&key](const auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, int32_t> || std::is_same_v<T, float> ||
                      std::is_same_v<T, glm::vec2> || std::is_same_v<T, glm::vec3> || std::is_same_v<T, glm::vec4> ||
                      std::is_same_v<T, glm::mat3> || std::is_same_v<T, glm::mat4>) {
          key.append(reinterpret_cast<const char*>(&d), sizeof(d));
          return true;
        } else {
          return false;
        }
      },
      value.data());
  if (!raw) key += value.str();
  auto [it, inserted] = constantIndex_.emplace(std::move(key), static_cast<uint32_t>(constants_.size()));
  if (inserted) constants_.push_back(value);
  return it->second;
}

void ExprGraph::reserve(size_t count) {
  exprs_.reserve(count);
  hashes_.reserve(count);
  args_.reserve(2 * count);
  growSlots(count);
}

void ExprGraph::growSlots(size_t minimum) {
  // Load factor at most 1/2 keeps linear-probing runs short; the size is a power of two so
  // that the slot is the hash's low bits.
  size_t size = slots_.empty() ? 64 : slots_.size();
  while (size < 2 * minimum) size *= 2;
  if (size == slots_.size()) return;
  slots_.assign(size, kNoExpr);
  const size_t mask = size - 1;
  for (ExprId id = 0; id < exprs_.size(); ++id) {
    size_t slot = hashes_[id] & mask;
    while (slots_[slot] != kNoExpr) slot = (slot + 1) & mask;
    slots_[slot] = id;
  }
}

ExprId ExprGraph::intern(Expr expr, const std::vector<ExprId>& args) {
  // Structural hash of op, type, payload and argument ids (FNV-1a over their bytes, then a
  // final avalanche so that the low bits used for the slot depend on every input bit); equal
  // hashes are confirmed by comparing the expressions, so a collision only costs a compare.
  uint64_t hash = 1469598103934665603ull;
  auto mix = [&hash](uint32_t v) {
    for (int b = 0; b < 4; ++b) {
      hash ^= (v >> (8 * b)) & 0xffu;
      hash *= 1099511628211ull;
    }
  };
  mix(static_cast<uint32_t>(expr.op) | (static_cast<uint32_t>(expr.type) << 8));
  mix(expr.payload);
  for (ExprId a : args) mix(a);
  hash ^= hash >> 33;
  hash *= 0xff51afd7ed558ccdull;
  hash ^= hash >> 33;
  if (2 * (exprs_.size() + 1) > slots_.size()) growSlots(exprs_.size() + 1);
  const size_t mask = slots_.size() - 1;
  size_t slot = hash & mask;
  for (; slots_[slot] != kNoExpr; slot = (slot + 1) & mask) {
    const ExprId id = slots_[slot];
    const Expr& e = exprs_[id];
    if (hashes_[id] != hash || e.op != expr.op || e.type != expr.type || e.payload != expr.payload ||
        e.argCount != args.size()) {
      continue;
    }
    if (std::equal(args.begin(), args.end(), args_.begin() + e.firstArg)) return id;
  }
  expr.firstArg = static_cast<uint32_t>(args_.size());
  expr.argCount = static_cast<uint16_t>(args.size());
  args_.insert(args_.end(), args.begin(), args.end());
  const auto id = static_cast<ExprId>(exprs_.size());
  exprs_.push_back(expr);
  hashes_.push_back(hash);
  slots_[slot] = id;
  return id;
}

ExprId ExprGraph::constant(doc::Value value) {
  Type type = Type::Float;
  switch (value.type()) {
    case doc::ValueType::Boolean: type = Type::Bool; break;
    case doc::ValueType::Integer: type = Type::Int; break;
    case doc::ValueType::Float: type = Type::Float; break;
    case doc::ValueType::Vector2: type = Type::Vec2; break;
    case doc::ValueType::Vector3:
    case doc::ValueType::Color3: type = Type::Vec3; break;
    case doc::ValueType::Vector4:
    case doc::ValueType::Color4: type = Type::Vec4; break;
    case doc::ValueType::Matrix33: type = Type::Mat3; break;
    case doc::ValueType::Matrix44: type = Type::Mat4; break;
    default: type = Type::String; break;
  }
  // Colours and vectors of the same components are the same IR constant.
  if (value.type() == doc::ValueType::Color3) value = doc::Value(doc::ValueType::Vector3, value.as<glm::vec3>());
  if (value.type() == doc::ValueType::Color4) value = doc::Value(doc::ValueType::Vector4, value.as<glm::vec4>());
  // Normalise -0 to 0 so that 0 and -0 are one constant (they compare equal in every use).
  if (value.type() == doc::ValueType::Float && value.as<float>() == 0.0f) value = doc::Value(doc::ValueType::Float, 0.0f);
  Expr e;
  e.op = Op::Constant;
  e.type = type;
  e.payload = internConstant(value);
  return intern(e, {});
}

ExprId ExprGraph::constantFloat(float value) { return constant(doc::Value(doc::ValueType::Float, value)); }
ExprId ExprGraph::constantBool(bool value) { return constant(doc::Value(doc::ValueType::Boolean, value)); }
ExprId ExprGraph::constantInt(int32_t value) { return constant(doc::Value(doc::ValueType::Integer, value)); }

ExprId ExprGraph::constantVector(Type type, const std::vector<float>& c) {
  switch (type) {
    case Type::Float: return constantFloat(c.at(0));
    case Type::Vec2: return constant(doc::Value(doc::ValueType::Vector2, glm::vec2(c.at(0), c.at(1))));
    case Type::Vec3: return constant(doc::Value(doc::ValueType::Vector3, glm::vec3(c.at(0), c.at(1), c.at(2))));
    case Type::Vec4:
      return constant(doc::Value(doc::ValueType::Vector4, glm::vec4(c.at(0), c.at(1), c.at(2), c.at(3))));
    case Type::Mat3: {
      glm::mat3 m;
      for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) m[k][r] = c.at(static_cast<size_t>(r * 3 + k));
      return constant(doc::Value(doc::ValueType::Matrix33, m));
    }
    case Type::Mat4: {
      glm::mat4 m;
      for (int r = 0; r < 4; ++r)
        for (int k = 0; k < 4; ++k) m[k][r] = c.at(static_cast<size_t>(r * 4 + k));
      return constant(doc::Value(doc::ValueType::Matrix44, m));
    }
    case Type::Bool: return constantBool(c.at(0) != 0.0f);
    case Type::Int: return constantInt(static_cast<int32_t>(c.at(0)));
    case Type::String: break;
  }
  return constantFloat(0.0f);
}

ExprId ExprGraph::named(Op op, Type type, std::string_view name) {
  Expr e;
  e.op = op;
  e.type = type;
  e.payload = internString(name);
  return intern(e, {});
}

ExprId ExprGraph::op(Op op, Type type, std::initializer_list<ExprId> args, uint32_t payload) {
  return this->op(op, type, std::vector<ExprId>(args), payload);
}

ExprId ExprGraph::op(Op op, Type type, const std::vector<ExprId>& args, uint32_t payload) {
  Expr e;
  e.op = op;
  e.type = type;
  e.payload = payload;
  return intern(e, args);
}

ExprId ExprGraph::opWithString(Op op, Type type, const std::vector<ExprId>& args, std::string_view text) {
  Expr e;
  e.op = op;
  e.type = type;
  e.payload = internString(text);
  return intern(e, args);
}

std::vector<ExprId> ExprGraph::argsOf(ExprId id) const {
  const Expr& e = exprs_[id];
  return std::vector<ExprId>(args_.begin() + e.firstArg, args_.begin() + e.firstArg + e.argCount);
}

std::vector<float> ExprGraph::constantComponents(ExprId id) const {
  const doc::Value& v = constantValue(id);
  switch (v.type()) {
    case doc::ValueType::Boolean: return {v.as<bool>() ? 1.0f : 0.0f};
    case doc::ValueType::Integer: return {static_cast<float>(v.as<int32_t>())};
    default: return v.components();
  }
}

bool ExprGraph::isConstantEqual(ExprId id, float value) const {
  if (!isConstant(id) || exprs_[id].type == Type::String) return false;
  std::vector<float> c = constantComponents(id);
  if (c.empty()) return false;
  for (float x : c) {
    if (x != value) return false;
  }
  return true;
}

}  // namespace mxc::ir
