#include "compiler/ir/Evaluate.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace mxc::ir {

namespace {

/// Component i of a constant, broadcasting scalars.
float at(const Constant& c, size_t i) { return c.v.size() == 1 ? c.v[0] : c.v[i]; }

size_t widthOf(Type type) { return static_cast<size_t>(std::max(1, componentCount(type))); }

template <typename F>
std::optional<Constant> componentwise(Type type, const std::vector<Constant>& args, F f) {
  Constant out{type, {}};
  const size_t n = widthOf(type);
  for (size_t i = 0; i < n; ++i) {
    std::vector<float> xs;
    for (const Constant& a : args) xs.push_back(at(a, i));
    out.v.push_back(f(xs));
  }
  return out;
}

bool finite(const Constant& c) {
  return std::all_of(c.v.begin(), c.v.end(), [](float x) { return std::isfinite(x); });
}

/// HSV <-> RGB (Smith 1978, "Color Gamut Transform Pairs"), hue in [0, 1).
glm::vec3 rgbToHsv(glm::vec3 c) {
  float maxc = std::max({c.r, c.g, c.b});
  float minc = std::min({c.r, c.g, c.b});
  float delta = maxc - minc;
  float h = 0.0f;
  // delta > 0 guards the divisions; maxc > 0 then too.
  if (delta > 0.0f) {
    if (maxc == c.r) h = (c.g - c.b) / delta;
    else if (maxc == c.g) h = 2.0f + (c.b - c.r) / delta;
    else h = 4.0f + (c.r - c.g) / delta;
    h /= 6.0f;
    if (h < 0.0f) h += 1.0f;
  }
  float s = maxc > 0.0f ? delta / maxc : 0.0f;
  return {h, s, maxc};
}

glm::vec3 hsvToRgb(glm::vec3 hsv) {
  float h = (hsv.x - std::floor(hsv.x)) * 6.0f;
  float s = hsv.y;
  float v = hsv.z;
  int sector = static_cast<int>(h) % 6;
  float f = h - std::floor(h);
  float p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  switch (sector) {
    case 0: return {v, t, p};
    case 1: return {q, v, p};
    case 2: return {p, v, t};
    case 3: return {p, q, v};
    case 4: return {t, p, v};
    default: return {v, p, q};
  }
}

glm::vec3 vec3Of(const Constant& c) { return {at(c, 0), at(c, 1), at(c, 2)}; }

std::optional<Constant> evaluateUnchecked(Op op, Type type, const std::vector<Constant>& a, uint32_t payload,
                                          const std::string& text) {
  auto unary = [&](auto f) { return componentwise(type, a, [&](const std::vector<float>& x) { return f(x[0]); }); };
  auto binary = [&](auto f) {
    return componentwise(type, a, [&](const std::vector<float>& x) { return f(x[0], x[1]); });
  };
  switch (op) {
    case Op::Add: return binary([](float x, float y) { return x + y; });
    case Op::Sub: return binary([](float x, float y) { return x - y; });
    case Op::Mul: return binary([](float x, float y) { return x * y; });
    case Op::Div: return binary([](float x, float y) { return x / y; });  // a zero divisor gives inf: not folded
    case Op::Mod: return binary([](float x, float y) { return x - y * std::floor(x / y); });
    case Op::Neg: return unary([](float x) { return -x; });
    case Op::Abs: return unary([](float x) { return std::abs(x); });
    case Op::Sign: return unary([](float x) { return x > 0 ? 1.0f : x < 0 ? -1.0f : 0.0f; });
    case Op::Floor: return unary([](float x) { return std::floor(x); });
    case Op::Ceil: return unary([](float x) { return std::ceil(x); });
    case Op::Round: return unary([](float x) { return std::round(x); });
    case Op::Fract: return unary([](float x) { return x - std::floor(x); });
    case Op::Min: return binary([](float x, float y) { return std::min(x, y); });
    case Op::Max: return binary([](float x, float y) { return std::max(x, y); });
    case Op::Clamp:
      return componentwise(type, a, [](const std::vector<float>& x) { return std::min(std::max(x[0], x[1]), x[2]); });
    case Op::Mix:
      return componentwise(type, a, [](const std::vector<float>& x) { return x[0] + (x[1] - x[0]) * x[2]; });
    case Op::Pow: return binary([](float x, float y) { return std::pow(x, y); });
    case Op::Sqrt: return unary([](float x) { return std::sqrt(x); });
    case Op::Exp: return unary([](float x) { return std::exp(x); });
    case Op::Ln: return unary([](float x) { return std::log(x); });
    case Op::Sin: return unary([](float x) { return std::sin(x); });
    case Op::Cos: return unary([](float x) { return std::cos(x); });
    case Op::Tan: return unary([](float x) { return std::tan(x); });
    case Op::Asin: return unary([](float x) { return std::asin(x); });
    case Op::Acos: return unary([](float x) { return std::acos(x); });
    case Op::Atan2: return binary([](float y, float x) { return std::atan2(y, x); });
    case Op::Step: return binary([](float edge, float x) { return x < edge ? 0.0f : 1.0f; });
    case Op::SmoothStep:
      return componentwise(type, a, [](const std::vector<float>& x) {
        if (x[0] >= x[1]) return x[2] < x[0] ? 0.0f : 1.0f;  // degenerate edges: a step
        float t = std::clamp((x[2] - x[0]) / (x[1] - x[0]), 0.0f, 1.0f);
        return t * t * (3 - 2 * t);
      });
    case Op::Dot: {
      float s = 0;
      for (size_t i = 0; i < a[0].v.size(); ++i) s += a[0].v[i] * at(a[1], i);
      return Constant{Type::Float, {s}};
    }
    case Op::Cross: {
      glm::vec3 r = glm::cross(vec3Of(a[0]), vec3Of(a[1]));
      return Constant{Type::Vec3, {r.x, r.y, r.z}};
    }
    case Op::Length: {
      float s = 0;
      for (float x : a[0].v) s += x * x;
      return Constant{Type::Float, {std::sqrt(s)}};
    }
    case Op::Normalize: {
      float s = 0;
      for (float x : a[0].v) s += x * x;
      if (s <= 1e-16f) return std::nullopt;  // the shader's guarded normalize decides
      Constant out = a[0];
      for (float& x : out.v) x /= std::sqrt(s);
      return out;
    }
    case Op::Splat: return Constant{type, std::vector<float>(widthOf(type), a[0].v[0])};
    case Op::Construct: {
      Constant out{type, {}};
      for (const Constant& part : a) out.v.insert(out.v.end(), part.v.begin(), part.v.end());
      out.v.resize(widthOf(type), 0.0f);
      return out;
    }
    case Op::Extract:
      if (payload >= a[0].v.size()) return std::nullopt;
      return Constant{Type::Float, {a[0].v[payload]}};
    case Op::Swizzle: {
      Constant out{type, {}};
      for (char c : text) {
        if (c == '0' || c == '1') {
          out.v.push_back(c == '1' ? 1.0f : 0.0f);
          continue;
        }
        const size_t index = std::string_view("rgbaxyzw").find(c) % 4;
        out.v.push_back(at(a[0], index));
      }
      return out;
    }
    case Op::Greater: return Constant{Type::Bool, {at(a[0], 0) > at(a[1], 0) ? 1.0f : 0.0f}};
    case Op::GreaterEq: return Constant{Type::Bool, {at(a[0], 0) >= at(a[1], 0) ? 1.0f : 0.0f}};
    case Op::Equal: return Constant{Type::Bool, {a[0].v == a[1].v ? 1.0f : 0.0f}};
    case Op::And: return Constant{Type::Bool, {(a[0].v[0] != 0 && a[1].v[0] != 0) ? 1.0f : 0.0f}};
    case Op::Or: return Constant{Type::Bool, {(a[0].v[0] != 0 || a[1].v[0] != 0) ? 1.0f : 0.0f}};
    case Op::Not: return Constant{Type::Bool, {a[0].v[0] != 0 ? 0.0f : 1.0f}};
    case Op::Select: return a[0].v[0] != 0 ? a[1] : a[2];
    case Op::Luminance: {
      float l = at(a[0], 0) * at(a[1], 0) + at(a[0], 1) * at(a[1], 1) + at(a[0], 2) * at(a[1], 2);
      return Constant{type, std::vector<float>(widthOf(type), l)};
    }
    case Op::RgbToHsv: {
      glm::vec3 r = rgbToHsv(vec3Of(a[0]));
      return Constant{Type::Vec3, {r.x, r.y, r.z}};
    }
    case Op::HsvToRgb: {
      glm::vec3 r = hsvToRgb(vec3Of(a[0]));
      return Constant{Type::Vec3, {r.x, r.y, r.z}};
    }
    case Op::Rotate2D: {
      // Counter-clockwise by `amount` degrees.
      float radians = at(a[1], 0) * 3.14159265358979f / 180.0f;
      float s = std::sin(radians), c = std::cos(radians);
      float x = at(a[0], 0), y = at(a[0], 1);
      return Constant{Type::Vec2, {c * x - s * y, s * x + c * y}};
    }
    case Op::HeightToNormal:
      // A constant height has no gradient: the flat normal, (0, 0, 1) encoded.
      return Constant{Type::Vec3, {0.5f, 0.5f, 1.0f}};
    case Op::Rotate3D: {
      glm::vec3 axis = vec3Of(a[2]);
      if (glm::length(axis) <= 1e-8f) return std::nullopt;
      glm::mat4 r = glm::rotate(glm::mat4(1.0f), glm::radians(at(a[1], 0)), glm::normalize(axis));
      glm::vec3 v = glm::vec3(r * glm::vec4(vec3Of(a[0]), 0.0f));
      return Constant{Type::Vec3, {v.x, v.y, v.z}};
    }
    default:
      return std::nullopt;  // leaves, matrices, textures, noise, geometry: not folded on the host
  }
}

}  // namespace

std::optional<Constant> evaluate(Op op, Type type, const std::vector<Constant>& args, uint32_t payload,
                                 const std::string& text) {
  std::optional<Constant> result = evaluateUnchecked(op, type, args, payload, text);
  if (result && !finite(*result)) return std::nullopt;  // inf or NaN stays an expression (the shader guards)
  return result;
}

std::optional<Constant> evaluateExpr(const ExprGraph& graph, ExprId id) {
  const Expr& e = graph[id];
  if (e.op == Op::Constant) {
    if (e.type == Type::String) return std::nullopt;
    return Constant{e.type, graph.constantComponents(id)};
  }
  std::vector<Constant> args;
  for (ExprId a : graph.argsOf(id)) {
    std::optional<Constant> c = evaluateExpr(graph, a);
    if (!c) return std::nullopt;
    args.push_back(std::move(*c));
  }
  static const std::string empty;
  return evaluate(e.op, e.type, args, e.payload, hasTextPayload(e.op) ? graph.text(id) : empty);
}

}  // namespace mxc::ir
