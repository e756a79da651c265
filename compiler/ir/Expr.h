#pragma once
/// \file
/// The expression part of the IR: a typed SSA DAG of the math a node graph computes
/// (parameters of interfaces, media, coverage and mix weights).
///
/// Expressions are hash-consed: adding an expression equal to an existing one (same op,
/// type, arguments and payload) returns the existing id, so common subexpressions are shared
/// by construction. Arguments always have smaller ids than their users, so id order is a
/// topological order.

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "compiler/document/Value.h"

namespace mxc::ir {

/// Value types of expressions. Colours are vectors here: color3 is Vec3, color4 is Vec4.
enum class Type : uint8_t { Bool, Int, Float, Vec2, Vec3, Vec4, Mat3, Mat4, String };

std::string_view typeName(Type type);
/// Number of float components (1 for Float, 3 for Vec3, 9 for Mat3); 0 for Bool, Int, String.
int componentCount(Type type);
/// The IR type of a MaterialX value type; false when it has no IR type (shader types, arrays).
bool irTypeOf(std::string_view materialxType, Type& type);
/// The vector type with `n` float components (1 gives Float).
Type vectorType(int n);

using ExprId = uint32_t;
constexpr ExprId kNoExpr = UINT32_MAX;

/// Operations. The set is closed: every backend and pass switches over all of it.
enum class Op : uint8_t {
  // Leaves
  Constant,   ///< payload: constant index
  Parameter,  ///< a shader input the user marked as varying; payload: name
  GeomProp,   ///< a geometric property (Nworld, Tworld, Bworld, Pworld, Pobject, UV0, ...); payload: name
  Texture,    ///< an image file (a texture binding); payload: path
  // Component-wise arithmetic (vector op scalar broadcasts the scalar)
  Add, Sub, Mul, Div, Mod, Neg, Abs, Sign, Floor, Ceil, Round, Fract, Min, Max, Clamp, Mix,
  Pow, Sqrt, Exp, Ln, Sin, Cos, Tan, Asin, Acos, Atan2, Step, SmoothStep,
  // Vector
  Dot, Cross, Length, Normalize, Reflect, Refract,
  // Construction and access
  Splat,      ///< float to a vector type
  Construct,  ///< components (floats or vectors) to a vector of the result type
  Extract,    ///< payload: component index
  Swizzle,    ///< payload: channel string such as "xyz" or "r01"
  // Comparison and selection
  Greater, GreaterEq, Equal, And, Or, Not, Select,  ///< Select(condition, ifTrue, ifFalse)
  // Matrices
  MatMul, Transpose, Determinant, Inverse,
  // Colour
  Luminance, RgbToHsv, HsvToRgb,
  // Procedural and sampled (implemented in the shader library; not folded on the host)
  Noise2D, Noise3D, Fractal3D, CellNoise2D, CellNoise3D, WorleyNoise2D, WorleyNoise3D,
  Flake,        ///< (position in flake cells, probability): vec4(presence, rand, xi0, xi1) of the flake seen, 0 where none
  ImageSample,  ///< (texture, texcoord, default) with payload "uaddress,vaddress,filter"
  ImageMissing,  ///< (texture) with payload its colour space: true where the texture's file could not be read
  NormalMap,    ///< (tangent-space sample, scale, normal, tangent, bitangent)
  HeightToNormal,  ///< (height, scale, texcoord): the height field's tangent-space normal, encoded in [0, 1]
  Rotate3D,     ///< (vector, degrees, axis)
  Rotate2D,     ///< (vector, degrees)
  TransformPoint, TransformVector, TransformNormal,  ///< payload: "fromspace,tospace"
  // The back end's own values (never in a material's IR)
  Local,  ///< a value the generated code computes at run time (a lobe's albedo, a library call); payload: its GLSL
};

std::string_view opName(Op op);
/// True for ops whose payload is a string (names, paths, channels, modes): ExprGraph::text.
bool hasTextPayload(Op op);

/// One expression node.
struct Expr {
  Op op = Op::Constant;
  Type type = Type::Float;
  uint32_t firstArg = 0;  ///< index into ExprGraph::args
  uint16_t argCount = 0;
  uint32_t payload = 0;   ///< Constant: constant index; Extract: component; string ops: string index
};

/// A pool of hash-consed expressions (one per material).
class ExprGraph {
 public:
  ExprGraph() = default;

  /// Room for `count` expressions without rehashing (a pass rebuilding a graph of that size).
  void reserve(size_t count);

  ExprId constant(doc::Value value);
  ExprId constantFloat(float value);
  ExprId constantVector(Type type, const std::vector<float>& components);
  ExprId constantBool(bool value);
  ExprId constantInt(int32_t value);
  /// Leaves with a name (Parameter, GeomProp, Texture).
  ExprId named(Op op, Type type, std::string_view name);
  ExprId op(Op op, Type type, std::initializer_list<ExprId> args, uint32_t payload = 0);
  ExprId op(Op op, Type type, const std::vector<ExprId>& args, uint32_t payload = 0);
  /// An op with a string payload (Swizzle channels, ImageSample addressing, transform spaces).
  ExprId opWithString(Op op, Type type, const std::vector<ExprId>& args, std::string_view text);

  const Expr& operator[](ExprId id) const { return exprs_[id]; }
  size_t size() const { return exprs_.size(); }
  ExprId arg(ExprId id, size_t i) const { return args_[exprs_[id].firstArg + i]; }
  std::vector<ExprId> argsOf(ExprId id) const;
  /// The constant of a Constant expression.
  const doc::Value& constantValue(ExprId id) const { return constants_[exprs_[id].payload]; }
  /// The name or text payload of Parameter, GeomProp, Texture, Swizzle and the string ops.
  const std::string& text(ExprId id) const { return strings_[exprs_[id].payload]; }

  bool isConstant(ExprId id) const { return id != kNoExpr && exprs_[id].op == Op::Constant; }
  /// Float components of a constant (a Bool or Int gives 0 or 1 or its value).
  std::vector<float> constantComponents(ExprId id) const;
  /// True when the expression is a constant whose every component equals `value`.
  bool isConstantEqual(ExprId id, float value) const;

 private:
  ExprId intern(Expr expr, const std::vector<ExprId>& args);
  void growSlots(size_t minimum);
  uint32_t internString(std::string_view text);
  uint32_t internConstant(const doc::Value& value);

  std::vector<Expr> exprs_;
  std::vector<ExprId> args_;
  std::vector<doc::Value> constants_;
  std::vector<std::string> strings_;
  /// Open-addressing hash set of expression ids (linear probing, kNoExpr marks an empty slot),
  /// with each expression's structural hash beside it: one flat array, so interning stays a
  /// few cache lines per expression however large the graph grows.
  std::vector<ExprId> slots_;
  std::vector<uint64_t> hashes_;  // parallel to exprs_
  std::unordered_map<std::string, uint32_t> stringIndex_;
  std::unordered_map<std::string, uint32_t> constantIndex_;
};

}  // namespace mxc::ir
