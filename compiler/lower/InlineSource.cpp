#include "compiler/lower/InlineSource.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <unordered_map>

#include <fmt/format.h>

#include "compiler/ir/Fold.h"

namespace mxc::lower {

using ir::ExprId;
using ir::Op;
using ir::Type;

namespace {

/// A value in the expression: an IR expression, or a struct (its type and its leaves).
struct Operand {
  ExprId e = ir::kNoExpr;
  const lib::StructType* structType = nullptr;
  std::vector<ExprId> leaves;

  bool isStruct() const { return structType != nullptr; }
};

/// Thrown to abandon the expression; the message says why, `at` is the character offset.
struct ParseError {
  size_t at;
  std::string message;
};

bool isVector(Type t) { return t == Type::Vec2 || t == Type::Vec3 || t == Type::Vec4; }
bool isMatrix(Type t) { return t == Type::Mat3 || t == Type::Mat4; }
bool isNumeric(Type t) { return t == Type::Float || isVector(t) || isMatrix(t); }

class Parser {
 public:
  Parser(Context& c, const NodeRef& n, std::string_view text) : c_(c), n_(n), b_(c.b), g_(c.material.exprs), s_(text) {}

  Operand parse() {
    Operand result = ternary();
    skipSpace();
    if (pos_ != s_.size()) fail(fmt::format("unexpected '{}' after the expression", s_.substr(pos_, 1)));
    return result;
  }

 private:
  [[noreturn]] void fail(std::string message) const { throw ParseError{pos_, std::move(message)}; }
  [[noreturn]] void failAt(size_t at, std::string message) const { throw ParseError{at, std::move(message)}; }

  void skipSpace() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  /// Consumes `token` when it comes next (an operator that is a prefix of a longer one, such
  /// as '<' of "<=", is not taken for it).
  bool accept(std::string_view token) {
    skipSpace();
    if (s_.substr(pos_, token.size()) != token) return false;
    const char after = pos_ + token.size() < s_.size() ? s_[pos_ + token.size()] : '\0';
    if ((token == "<" || token == ">" || token == "=" || token == "!") && after == '=') return false;
    if ((token == "&" && after == '&') || (token == "|" && after == '|')) return false;
    pos_ += token.size();
    return true;
  }
  void expect(std::string_view token) {
    if (!accept(token)) fail(fmt::format("expected '{}'", token));
  }

  ExprId value(const Operand& o, size_t at) const {
    if (o.isStruct()) failAt(at, fmt::format("a {} struct cannot be used as a value here", o.structType->name));
    return o.e;
  }
  Type typeOf(ExprId e) const { return b_.type(e); }
  std::string_view name(ExprId e) const { return ir::typeName(typeOf(e)); }
  /// GLSL converts integers and booleans to float where a float is expected.
  ExprId toFloat(ExprId e) { return typeOf(e) == Type::Int || typeOf(e) == Type::Bool ? b_.convert(e, Type::Float) : e; }
  static Operand of(ExprId e) { return Operand{e, nullptr, {}}; }

  /// Counts the grammar's recursion (a parenthesis, an operand of ?:, a unary operator, an
  /// index, a call's argument), so that nesting deeper than kMaxDepth is an error at its
  /// position rather than a stack overflow.
  class Nesting {
   public:
    explicit Nesting(Parser& p) : p_(p) {
      if (++p_.depth_ > kMaxDepth) p_.fail(fmt::format("the expression nests more than {} levels (parentheses, operands, prefix operators)", kMaxDepth));
    }
    ~Nesting() { --p_.depth_; }
    Nesting(const Nesting&) = delete;
    Nesting& operator=(const Nesting&) = delete;

   private:
    Parser& p_;
  };
  /// Far beyond any expression written by hand (a level is a parenthesis, an operand or a
  /// prefix operator inside another), and well below what the stack holds: a level is about
  /// ten frames, a few hundred bytes each in a release build but up to 5 KB each under
  /// AddressSanitizer (1000 levels overflowed its 8 MB stack), so 200 levels stay under 8 MB
  /// even there.
  static constexpr int kMaxDepth = 200;

  // --- Grammar (GLSL precedence, lowest first) ---
  Operand ternary() {
    const Nesting nesting(*this);
    const size_t at = (skipSpace(), pos_);
    Operand condition = logicalOr();
    if (!accept("?")) return condition;
    ExprId test = value(condition, at);
    if (typeOf(test) != Type::Bool) failAt(at, fmt::format("the condition of ?: is a {}, not a bool", name(test)));
    const size_t thenAt = (skipSpace(), pos_);
    Operand ifTrue = ternary();
    expect(":");
    const size_t elseAt = (skipSpace(), pos_);
    Operand ifFalse = ternary();
    if (ifTrue.isStruct() || ifFalse.isStruct()) {
      if (ifTrue.structType != ifFalse.structType) failAt(thenAt, "the two branches of ?: have different types");
      Operand result{ir::kNoExpr, ifTrue.structType, {}};
      for (size_t i = 0; i < ifTrue.leaves.size(); ++i) {
        result.leaves.push_back(b_.select(test, ifTrue.leaves[i], ifFalse.leaves[i]));
      }
      return result;
    }
    ExprId t = toFloat(value(ifTrue, thenAt));
    ExprId f = toFloat(value(ifFalse, elseAt));
    if (typeOf(t) != typeOf(f) && typeOf(t) != Type::Float && typeOf(f) != Type::Float) {
      failAt(thenAt, fmt::format("the branches of ?: are {} and {}", name(t), name(f)));
    }
    return of(b_.select(test, t, f));
  }

  Operand logicalOr() {
    const size_t at = (skipSpace(), pos_);
    Operand left = logicalAnd();
    while (accept("||")) {
      Operand right = logicalAnd();
      left = of(g_.op(Op::Or, Type::Bool, {boolean(left, at), boolean(right, at)}));
    }
    return left;
  }
  Operand logicalAnd() {
    const size_t at = (skipSpace(), pos_);
    Operand left = equality();
    while (accept("&&")) {
      Operand right = equality();
      left = of(g_.op(Op::And, Type::Bool, {boolean(left, at), boolean(right, at)}));
    }
    return left;
  }
  ExprId boolean(const Operand& o, size_t at) {
    ExprId e = value(o, at);
    if (typeOf(e) != Type::Bool) failAt(at, fmt::format("&& and || take bools, not a {}", name(e)));
    return e;
  }

  Operand equality() {
    const size_t at = (skipSpace(), pos_);
    Operand left = relational();
    for (;;) {
      const bool equal = accept("==");
      if (!equal && !accept("!=")) return left;
      Operand right = relational();
      ExprId a = toFloat(value(left, at));
      ExprId bb = toFloat(value(right, at));
      if (typeOf(a) != typeOf(bb)) failAt(at, fmt::format("cannot compare a {} with a {}", name(a), name(bb)));
      ExprId eq = g_.op(Op::Equal, Type::Bool, {a, bb});
      left = of(equal ? eq : g_.op(Op::Not, Type::Bool, {eq}));
    }
  }

  Operand relational() {
    const size_t at = (skipSpace(), pos_);
    Operand left = additive();
    for (;;) {
      int kind = -1;  // 0 <, 1 >, 2 <=, 3 >=
      if (accept("<=")) kind = 2;
      else if (accept(">=")) kind = 3;
      else if (accept("<")) kind = 0;
      else if (accept(">")) kind = 1;
      if (kind < 0) return left;
      Operand right = additive();
      ExprId a = toFloat(value(left, at));
      ExprId bb = toFloat(value(right, at));
      if (typeOf(a) != Type::Float || typeOf(bb) != Type::Float) {
        failAt(at, fmt::format("<, >, <= and >= compare scalars (GLSL), not a {} and a {}", name(a), name(bb)));
      }
      // a < b is b > a; a <= b is b >= a.
      const Op op = (kind == 0 || kind == 1) ? Op::Greater : Op::GreaterEq;
      const bool swap = kind == 0 || kind == 2;
      left = of(g_.op(op, Type::Bool, {swap ? bb : a, swap ? a : bb}));
    }
  }

  Operand additive() {
    const size_t at = (skipSpace(), pos_);
    Operand left = multiplicative();
    for (;;) {
      Op op;
      if (accept("+")) op = Op::Add;
      else if (accept("-")) op = Op::Sub;
      else return left;
      Operand right = multiplicative();
      left = of(arithmetic(op, value(left, at), value(right, at), at));
    }
  }

  Operand multiplicative() {
    const size_t at = (skipSpace(), pos_);
    Operand left = unary();
    for (;;) {
      Op op;
      if (accept("*")) op = Op::Mul;
      else if (accept("/")) op = Op::Div;
      else return left;
      Operand right = unary();
      left = of(arithmetic(op, value(left, at), value(right, at), at));
    }
  }

  /// a op b with GLSL's rules: a scalar broadcasts over a vector or matrix; matrix * vector,
  /// vector * matrix and matrix * matrix are products. Division by zero is the source's own
  /// business, as in the GLSL it stands for.
  ExprId arithmetic(Op op, ExprId a, ExprId bb, size_t at) {
    a = toFloat(a);
    bb = toFloat(bb);
    const Type ta = typeOf(a), tb = typeOf(bb);
    if (!isNumeric(ta) || !isNumeric(tb)) failAt(at, fmt::format("cannot do arithmetic on a {} and a {}", name(a), name(bb)));
    if (op == Op::Mul && (isMatrix(ta) || isMatrix(tb)) && ta != Type::Float && tb != Type::Float) {
      const int na = isMatrix(ta) ? (ta == Type::Mat3 ? 3 : 4) : ir::componentCount(ta);
      const int nb = isMatrix(tb) ? (tb == Type::Mat3 ? 3 : 4) : ir::componentCount(tb);
      if (na != nb) failAt(at, fmt::format("cannot multiply a {} by a {}", name(a), name(bb)));
      const Type result = isMatrix(ta) && isMatrix(tb) ? ta : (isMatrix(ta) ? tb : ta);
      return g_.op(Op::MatMul, result, {a, bb});
    }
    if (ta != tb && ta != Type::Float && tb != Type::Float) {
      failAt(at, fmt::format("cannot combine a {} with a {} (GLSL needs equal types or a scalar)", name(a), name(bb)));
    }
    return b_.binary(op, a, bb);
  }

  Operand unary() {
    const size_t at = (skipSpace(), pos_);
    if (accept("-")) {
      const Nesting nesting(*this);
      ExprId e = toFloat(value(unary(), at));
      if (!isNumeric(typeOf(e))) failAt(at, fmt::format("cannot negate a {}", name(e)));
      return of(b_.neg(e));
    }
    if (accept("+")) {
      const Nesting nesting(*this);
      return unary();
    }
    if (accept("!")) {
      const Nesting nesting(*this);
      ExprId e = value(unary(), at);
      if (typeOf(e) != Type::Bool) failAt(at, fmt::format("! takes a bool, not a {}", name(e)));
      return of(g_.op(Op::Not, Type::Bool, {e}));
    }
    return postfix();
  }

  Operand postfix() {
    Operand o = primary();
    for (;;) {
      const size_t at = (skipSpace(), pos_);
      if (accept(".")) {
        o = member(o, identifier(), at);
      } else if (accept("[")) {
        const size_t indexAt = (skipSpace(), pos_);
        ExprId index = folded(value(ternary(), indexAt));
        expect("]");
        o = of(element(value(o, at), index, at));
      } else {
        return o;
      }
    }
  }

  /// .name: a struct member, or a swizzle of a vector (xyzw, rgba or stpq).
  Operand member(const Operand& o, std::string_view field, size_t at) {
    if (o.isStruct()) {
      const lib::StructType::Member* m = o.structType->findMember(field);
      if (!m) failAt(at, fmt::format("struct {} has no member '{}'", o.structType->name, field));
      std::vector<ExprId> leaves(o.leaves.begin() + static_cast<std::ptrdiff_t>(m->firstLeaf),
                                 o.leaves.begin() + static_cast<std::ptrdiff_t>(m->firstLeaf + m->leafCount));
      if (const lib::StructType* inner = c_.library.structType(m->type)) return Operand{ir::kNoExpr, inner, leaves};
      return of(leaves.front());
    }
    ExprId v = o.e;
    const int n = ir::componentCount(typeOf(v));
    if (!(isVector(typeOf(v)) || typeOf(v) == Type::Float) || field.empty() || field.size() > 4) {
      failAt(at, fmt::format("'.{}' on a {}: only vectors have swizzles, and only structs have members", field, name(v)));
    }
    std::string channels;
    for (char ch : field) {
      size_t index = std::string_view("xyzw").find(ch);
      if (index == std::string_view::npos) index = std::string_view("rgba").find(ch);
      if (index == std::string_view::npos) index = std::string_view("stpq").find(ch);
      if (index == std::string_view::npos || static_cast<int>(index) >= std::max(n, 1)) {
        failAt(at, fmt::format("'.{}' is not a swizzle of a {}", field, name(v)));
      }
      channels += "xyzw"[index];
    }
    if (channels.size() == 1) return of(n <= 1 ? v : b_.extract(v, static_cast<int>(std::string_view("xyzw").find(channels[0]))));
    return of(g_.opWithString(Op::Swizzle, ir::vectorType(static_cast<int>(channels.size())), {v}, channels));
  }

  /// v[index]: a component of a vector. A constant index picks it; any other is a chain of
  /// selections (GLSL indexes vectors dynamically; an index outside the vector gives the last
  /// component here, where GLSL leaves it undefined).
  ExprId element(ExprId v, ExprId index, size_t at) {
    const int n = ir::componentCount(typeOf(v));
    if (!isVector(typeOf(v))) failAt(at, fmt::format("[] indexes vectors here, not a {}", name(v)));
    if (g_.isConstant(index)) {
      const float i = g_.constantComponents(index).at(0);
      if (i < 0.0f || i >= static_cast<float>(n) || i != static_cast<float>(static_cast<int>(i))) {
        failAt(at, fmt::format("index {} is outside a {}", i, name(v)));
      }
      return b_.extract(v, static_cast<int>(i));
    }
    ExprId indexF = toFloat(index);
    if (typeOf(indexF) != Type::Float) failAt(at, fmt::format("an index is a number, not a {}", name(index)));
    ExprId result = b_.extract(v, n - 1);
    for (int i = n - 2; i >= 0; --i) {
      result = b_.select(g_.op(Op::Equal, Type::Bool, {indexF, b_.f(static_cast<float>(i))}), b_.extract(v, i), result);
    }
    return result;
  }

  /// `e` with its constant subexpressions folded (so that an index such as -1 or 3 - 1 is
  /// known to be a constant and checked against the vector's size). An index may read an
  /// input, whose upstream graph can be deep and shares nodes: each node is folded once
  /// (`done`), and below kMaxDepth levels the rest is left as it is (the index is then
  /// dynamic, as any index that is not a constant).
  ExprId folded(ExprId e) {
    std::unordered_map<ExprId, ExprId> done;
    return folded(e, 0, done);
  }
  ExprId folded(ExprId e, int depth, std::unordered_map<ExprId, ExprId>& done) {
    if (g_.isConstant(e) || g_[e].argCount == 0 || depth > kMaxDepth) return e;
    if (auto known = done.find(e); known != done.end()) return known->second;
    std::vector<ExprId> args = g_.argsOf(e);
    for (ExprId& a : args) a = folded(a, depth + 1, done);
    const ir::Expr expr = g_[e];  // a copy: folding may grow the graph
    const std::string text = ir::hasTextPayload(expr.op) ? g_.text(e) : std::string();
    const ExprId result = ir::foldExpression(g_, expr, args, text).value_or(e);
    done.emplace(e, result);
    return result;
  }

  std::string_view identifier() {
    skipSpace();
    const size_t start = pos_;
    while (pos_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_')) ++pos_;
    if (start == pos_ || std::isdigit(static_cast<unsigned char>(s_[start]))) failAt(start, "expected a name");
    return s_.substr(start, pos_ - start);
  }

  Operand primary() {
    skipSpace();
    const size_t at = pos_;
    if (pos_ >= s_.size()) fail("the expression ends early");
    if (accept("(")) {
      Operand inner = ternary();
      expect(")");
      return inner;
    }
    if (s_.substr(pos_, 2) == "{{") {
      const size_t close = s_.find("}}", pos_ + 2);
      if (close == std::string_view::npos) fail("'{{' without '}}'");
      std::string_view inputName = s_.substr(pos_ + 2, close - pos_ - 2);
      while (!inputName.empty() && inputName.front() == ' ') inputName.remove_prefix(1);
      while (!inputName.empty() && inputName.back() == ' ') inputName.remove_suffix(1);
      pos_ = close + 2;
      return input(inputName, at);
    }
    const char ch = s_[pos_];
    if (std::isdigit(static_cast<unsigned char>(ch)) || (ch == '.' && pos_ + 1 < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_ + 1])))) {
      return of(number());
    }
    const std::string_view id = identifier();
    if (id == "true" || id == "false") return of(g_.constantBool(id == "true"));
    if (!accept("(")) failAt(at, fmt::format("'{}' is not an input: inputs are written {{{{name}}}}", id));
    std::vector<ExprId> args;
    std::vector<size_t> argAt;
    skipSpace();
    if (!accept(")")) {
      do {
        argAt.push_back((skipSpace(), pos_));
        args.push_back(value(ternary(), argAt.back()));
      } while (accept(","));
      expect(")");
    }
    return of(call(id, args, at));
  }

  ExprId number() {
    const char* begin = s_.data() + pos_;
    char* end = nullptr;
    const std::string text(begin, std::min<size_t>(64, s_.size() - pos_));
    const double v = std::strtod(text.c_str(), &end);
    const size_t length = static_cast<size_t>(end - text.c_str());
    if (length == 0) fail("expected a number");
    // A literal beyond a 32-bit float's range would reach the shader as inf (GLSL has no such
    // literal); one below its smallest normal rounds towards 0, as GLSL's own literals do.
    if (!std::isfinite(static_cast<float>(v))) {
      fail(fmt::format("the number {} is outside the range of a 32-bit float", std::string_view(begin, length)));
    }
    pos_ += length;
    if (pos_ < s_.size() && (s_[pos_] == 'f' || s_[pos_] == 'F' || s_[pos_] == 'u' || s_[pos_] == 'U')) ++pos_;
    // GLSL literals are ints or floats; arithmetic converts, so a float serves both.
    return b_.f(static_cast<float>(v));
  }

  Operand input(std::string_view inputName, size_t at) {
    const resolve::ResolvedInput* in = n_.node->findInput(inputName);
    if (!in) {
      std::vector<std::string_view> names;
      for (const resolve::ResolvedInput& i : n_.node->inputs) names.push_back(i.name);
      failAt(at, fmt::format("{{{{{}}}}} names no input of <{}> (its inputs: {})", inputName, n_.node->category(),
                             fmt::join(names, ", ")));
    }
    if (const lib::StructType* st = c_.library.structType(in->type)) {
      return Operand{ir::kNoExpr, st, c_.structValue(*in, *n_.env)};
    }
    ir::Type t;
    if (!ir::irTypeOf(in->type, t)) failAt(at, fmt::format("input '{}' is a {}, which has no value here", inputName, in->type));
    return of(c_.input(n_, inputName));
  }

  /// GLSL built-ins and MaterialX's mx_ helpers, as IR ops.
  ExprId call(std::string_view fn, std::vector<ExprId> args, size_t at) {
    auto arity = [&](size_t count) {
      if (args.size() != count) {
        failAt(at, fmt::format("{}() takes {} argument{}, given {}", fn, count, count == 1 ? "" : "s", args.size()));
      }
    };
    // Every check of the arguments' count comes before the first read of args[i], in its own
    // statement: C++ evaluates a call's arguments in an unspecified order.
    if (fn.substr(0, 3) == "mx_") fn.remove_prefix(3);
    for (ExprId& a : args) a = toFloat(a);
    auto same = [&](size_t count) {
      arity(count);
      Type t = Type::Float;
      for (ExprId a : args) {
        if (!isNumeric(typeOf(a))) failAt(at, fmt::format("{}() takes numbers, not a {}", fn, name(a)));
        if (typeOf(a) != Type::Float) {
          if (t != Type::Float && t != typeOf(a)) failAt(at, fmt::format("{}() is given a {} and a {}", fn, ir::typeName(t), name(a)));
          t = typeOf(a);
        }
      }
      for (ExprId& a : args) a = b_.splat(a, t);
      return t;
    };
    struct Unary {
      std::string_view name;
      Op op;
    };
    static constexpr Unary kUnary[] = {
        {"abs", Op::Abs},   {"sign", Op::Sign}, {"floor", Op::Floor}, {"ceil", Op::Ceil},   {"round", Op::Round},
        {"fract", Op::Fract}, {"sqrt", Op::Sqrt}, {"exp", Op::Exp},   {"log", Op::Ln},      {"sin", Op::Sin},
        {"cos", Op::Cos},   {"tan", Op::Tan},   {"asin", Op::Asin},   {"acos", Op::Acos},   {"normalize", Op::Normalize},
        {"transpose", Op::Transpose}, {"inverse", Op::Inverse},
    };
    for (const Unary& u : kUnary) {
      if (fn == u.name) {
        const Type t = same(1);
        return g_.op(u.op, t, {args[0]});
      }
    }
    if (fn == "min" || fn == "max" || fn == "pow" || fn == "mod") {
      const Type t = same(2);
      const Op op = fn == "min" ? Op::Min : fn == "max" ? Op::Max : fn == "pow" ? Op::Pow : Op::Mod;
      return g_.op(op, t, {args[0], args[1]});
    }
    if (fn == "atan") {
      if (args.empty()) arity(1);
      if (args.size() == 1) args.push_back(b_.f(1.0f));  // atan(y) = atan(y, 1)
      const Type t = same(2);
      return g_.op(Op::Atan2, t, {args[0], args[1]});
    }
    if (fn == "clamp" || fn == "smoothstep") {
      const Type t = same(3);
      return g_.op(fn == "clamp" ? Op::Clamp : Op::SmoothStep, t, {args[0], args[1], args[2]});
    }
    if (fn == "step") {
      const Type t = same(2);
      return g_.op(Op::Step, t, {args[0], args[1]});
    }
    if (fn == "mix") {
      arity(3);
      // mix(x, y, a): a is a float or of x's type.
      const Type t = typeOf(args[0]) == Type::Float ? typeOf(args[1]) : typeOf(args[0]);
      if ((typeOf(args[0]) != t && typeOf(args[0]) != Type::Float) || (typeOf(args[1]) != t && typeOf(args[1]) != Type::Float) ||
          (typeOf(args[2]) != t && typeOf(args[2]) != Type::Float)) {
        failAt(at, "mix() takes values of one type and a weight of that type or a float");
      }
      return b_.lerp(args[0], args[1], args[2]);
    }
    if (fn == "dot" || fn == "length" || fn == "distance" || fn == "determinant") {
      if (fn == "length" || fn == "determinant") {
        arity(1);
        return g_.op(fn == "length" ? Op::Length : Op::Determinant, Type::Float, {args[0]});
      }
      same(2);
      if (fn == "dot") return b_.dot(args[0], args[1]);
      return g_.op(Op::Length, Type::Float, {b_.sub(args[0], args[1])});
    }
    if (fn == "cross") {
      if (same(2) != Type::Vec3) failAt(at, "cross() takes two vec3");  // same() checked the arity
      return g_.op(Op::Cross, Type::Vec3, {args[0], args[1]});
    }
    if (fn == "reflect") {
      const Type t = same(2);
      return g_.op(Op::Reflect, t, {args[0], args[1]});
    }
    if (fn == "matrix_mul") {
      arity(2);
      return arithmetic(Op::Mul, args[0], args[1], at);
    }
    if (fn == "float" || fn == "vec2" || fn == "vec3" || fn == "vec4") {
      const int size = fn == "float" ? 1 : fn[3] - '0';
      const Type t = ir::vectorType(size);
      if (args.empty()) failAt(at, fmt::format("{}() needs arguments", fn));
      for (ExprId a : args) {
        if (!isVector(typeOf(a)) && typeOf(a) != Type::Float) failAt(at, fmt::format("{}() cannot take a {}", fn, name(a)));
      }
      if (args.size() == 1 && typeOf(args[0]) == Type::Float) return b_.splat(args[0], t);
      if (args.size() == 1 && ir::componentCount(typeOf(args[0])) >= size) return b_.convert(args[0], t);  // drops the rest
      int total = 0;
      for (ExprId a : args) total += ir::componentCount(typeOf(a));
      if (total != size) failAt(at, fmt::format("{}() is given {} components", fn, total));
      return b_.construct(t, args);
    }
    failAt(at, fmt::format("'{}' is not a function mxc lowers from inline source code (it lowers GLSL's built-in "
                           "math, vector constructors and MaterialX's mx_ math helpers)",
                           fn));
  }

  Context& c_;
  const NodeRef& n_;
  ir::ExprBuilder& b_;
  ir::ExprGraph& g_;
  std::string_view s_;
  size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

ir::ExprId lowerInlineSource(Context& c, const NodeRef& n, const doc::Implementation& implementation,
                             std::string_view output, ir::Type type) {
  // The source as the message quotes it: a long one is cut (at a character's start), so that
  // the message's reason still shows (Diagnostics cuts a message at 1000 bytes).
  std::string_view shown = implementation.sourcecode;
  std::string cut;
  if (shown.size() > 160) {
    size_t end = 120;
    while (end > 0 && (static_cast<unsigned char>(shown[end]) & 0xC0) == 0x80) --end;
    cut = fmt::format("{}... ({} characters)", shown.substr(0, end), shown.size());
    shown = cut;
  }
  auto report = [&](size_t at, const std::string& why) {
    c.error(n.node->node->location,
            fmt::format("<{}> '{}' is implemented by inline source code (implementation '{}', {}): \"{}\": at "
                        "character {}: {}",
                        n.node->category(), n.node->name(), implementation.name, implementation.location.str(),
                        shown, at + 1, why));
    return ir::kNoExpr;
  };
  if (n.node->signature && n.node->signature->outputs.size() > 1) {
    return report(0, fmt::format("inline source code computes one output; '{}' has several", output));
  }
  if (c.library.structType(n.node->signature ? n.node->signature->outputType() : std::string_view())) {
    return report(0, "struct-valued inline source code is not lowered by mxc (its members are read with .name)");
  }
  try {
    Parser parser(c, n, implementation.sourcecode);
    Operand result = parser.parse();
    if (result.isStruct()) return report(0, fmt::format("the expression is a {} struct, not a value", result.structType->name));
    ExprId e = result.e;
    if (c.b.type(e) != type && (c.b.type(e) == Type::Int || c.b.type(e) == Type::Bool) && type == Type::Float) {
      e = c.b.convert(e, Type::Float);
    }
    if (c.b.type(e) != type) {
      return report(0, fmt::format("the expression is a {}, and the node outputs a {}", ir::typeName(c.b.type(e)),
                                   ir::typeName(type)));
    }
    return e;
  } catch (const ParseError& error) {
    return report(error.at, error.message);
  }
}

}  // namespace mxc::lower
