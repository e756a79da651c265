#include "compiler/glsl/ExprEmitter.h"

#include <sstream>

#include <fmt/format.h>

#include "compiler/glsl/Contract.h"
#include "compiler/ir/Walk.h"

namespace mxc::glsl {

using ir::ExprId;
using ir::Op;
using ir::Type;

std::string glslType(Type type) {
  switch (type) {
    case Type::Bool: return "bool";
    case Type::Int: return "int";
    case Type::Float: return "float";
    case Type::Vec2: return "vec2";
    case Type::Vec3: return "vec3";
    case Type::Vec4: return "vec4";
    case Type::Mat3: return "mat3";
    case Type::Mat4: return "mat4";
    case Type::String: return "int";  // strings are not GLSL values; the emitter never declares one
  }
  return "float";
}

std::string glslFloat(float value) {
  std::string s = doc::formatFloat(value);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) parts.push_back(part);
  return parts;
}

/// A MaterialX address mode (compiler/glsl/Contract.h, MXC_ADDRESS_*).
AddressMode addressMode(const std::string& mode) {
  if (mode == "constant") return AddressMode::Constant;
  if (mode == "clamp") return AddressMode::Clamp;
  if (mode == "mirror") return AddressMode::Mirror;
  return AddressMode::Periodic;  // periodic (and hex, sampled periodically)
}

/// The GLSL of a geometric property, by geompropdef name.
std::string geomprop(const std::string& name, Type type, const std::string& fallback) {
  std::string v;
  if (name == "Pworld") v = "g.P";
  else if (name == "Pobject" || name == "Pmodel") v = "g.Pobj";
  else if (name == "Nworld") v = "g.N";
  else if (name == "Nobject" || name == "Nmodel") v = "g.Nobj";
  else if (name == "Tworld") v = "g.T";
  else if (name == "Tobject" || name == "Tmodel") v = "g.Tobj";
  else if (name == "Bworld") v = "g.B";
  else if (name == "Bobject" || name == "Bmodel") v = "g.Bobj";
  else if (name.rfind("UV", 0) == 0) v = "g.uv";
  else if (name.rfind("color", 0) == 0) v = "g.color";
  // The view direction, from the eye to the shaded point (MaterialX nprlib "viewdirection",
  // geompropdef Vworld): -wo, wo being the unit direction towards the viewer every stage passes
  // to mxc_material_closure. In object space through the inverse of the object's transform,
  // which a singular transform (a zero scale) does not have: then the world direction.
  else if (name == "Vworld") v = "(-wo)";
  else if (name == "Vobject" || name == "Vmodel") {
    v = "(abs(determinant(mat3(g.objectToWorld))) > 1e-30 ? mxc_safe_normalize((inverse(g.objectToWorld) * "
        "vec4(-wo, 0.0)).xyz, -wo) : -wo)";
  }
  if (v.empty()) return fallback;  // a named primvar the harness does not provide: its default
  const int n = ir::componentCount(type);
  if (v == "g.uv" && n == 3) return "vec3(g.uv, 0.0)";
  if (v == "g.color") return n == 4 ? v : n == 3 ? "g.color.rgb" : "g.color.r";
  if (n == 4) return fmt::format("vec4({}, 1.0)", v);
  if (n == 2 && v != "g.uv") return v + ".xy";
  return v;
}

}  // namespace

ImageSampling imageSampling(const std::string& payload) {
  std::vector<std::string> modes = split(payload, ',');
  while (modes.size() < 4) modes.emplace_back();
  // MaterialX filter types: cubic is sampled as linear (compiler/glsl/Contract.h, MXC_FILTER_*).
  return {addressMode(modes[0]), addressMode(modes[1]), modes[2] == "closest" ? FilterMode::Closest : FilterMode::Linear,
          modes[3]};
}

std::string_view addressModeName(AddressMode mode) {
  switch (mode) {
    case AddressMode::Constant: return "constant";
    case AddressMode::Clamp: return "clamp";
    case AddressMode::Periodic: return "periodic";
    case AddressMode::Mirror: return "mirror";
  }
  return "periodic";
}

ExprEmitter::ExprEmitter(const ir::Material& material, uint32_t firstTexture) : m_(material), nextTexture_(firstTexture) {
  // Origins: each expression gets the location of the first parameter reaching it.
  origins_.assign(m_.exprs.size(), SourceLocation{});
  std::vector<ExprId> order;
  ir::Material& mutableMaterial = const_cast<ir::Material&>(m_);  // the walk only reads
  std::vector<bool> seen(m_.exprs.size());
  ir::forEachReachableParam(mutableMaterial, [&](ir::Param& p) {
    if (!p.present()) return;
    std::vector<ExprId> stack{p.value};
    while (!stack.empty()) {
      ExprId id = stack.back();
      stack.pop_back();
      if (seen[id]) continue;
      seen[id] = true;
      origins_[id] = p.origin.location;
      for (ExprId a : m_.exprs.argsOf(id)) stack.push_back(a);
    }
  });
  // Ids are a topological order: emitting in id order defines arguments before use.
  for (ExprId id = 0; id < m_.exprs.size(); ++id) {
    if (seen[id] && !m_.exprs.isConstant(id) && m_.exprs[id].op != Op::Texture) names_[id] = emit(id);
  }
}

std::string ExprEmitter::literal(ExprId id) const {
  const ir::Expr& e = m_.exprs[id];
  const std::vector<float> c = m_.exprs.constantComponents(id);
  switch (e.type) {
    case Type::Bool: return c.at(0) != 0.0f ? "true" : "false";
    case Type::Int: return std::to_string(static_cast<int>(c.at(0)));
    case Type::Float: return glslFloat(c.at(0));
    case Type::String: return "0";
    default: {
      std::string out = glslType(e.type) + "(";
      bool same = true;
      for (float x : c) same = same && x == c[0];
      if (same && e.type != Type::Mat3 && e.type != Type::Mat4) return out + glslFloat(c[0]) + ")";
      // Matrices: constantComponents is row by row; GLSL constructors take columns.
      const int n = e.type == Type::Mat3 ? 3 : e.type == Type::Mat4 ? 4 : 0;
      for (size_t i = 0; i < c.size(); ++i) {
        size_t k = n ? (i % n) * n + i / n : i;
        out += (i ? ", " : "") + glslFloat(c[k]);
      }
      return out + ")";
    }
  }
}

std::string ExprEmitter::ref(ExprId id) const {
  if (id == ir::kNoExpr) return "0.0";
  if (m_.exprs.isConstant(id)) return literal(id);
  auto it = names_.find(id);
  return it != names_.end() ? it->second : "0.0";
}

std::string ExprEmitter::param(const ir::Param& p, const std::string& fallback) const {
  return p.present() ? ref(p.value) : fallback;
}

std::string ExprEmitter::texture(const std::string& path, const std::string& colorspace) {
  for (const TextureBinding& t : textures_) {
    if (t.path == path && t.colorspace == colorspace) return t.name;
  }
  SourceLocation origin;
  for (const ir::ImageFile& image : m_.images) {
    if (image.path == path) origin = image.origin.location;
  }
  TextureBinding t{path, colorspace, nextTexture_++, fmt::format("mxc_texture_{}", textures_.size()), origin};
  textures_.push_back(t);
  return t.name;
}

std::string ExprEmitter::missing(const std::string& sampler) const {
  size_t k = textures_.size() - 1;
  for (size_t t = 0; t < textures_.size(); ++t) k = textures_[t].name == sampler ? t : k;
  return fmt::format("(MXC_PARAMETER(mxc_params.{}) & {}u) != 0u", missingTexturesMember(k), 1u << (k % 32));
}

std::string ExprEmitter::emit(ExprId id) {
  const ir::Expr& e = m_.exprs[id];
  std::vector<ExprId> args = m_.exprs.argsOf(id);
  auto a = [&](size_t i) { return ref(args.at(i)); };
  const std::string type = glslType(e.type);
  std::string value;
  switch (e.op) {
    case Op::Constant:
    case Op::Texture: return ref(id);
    case Op::Local: return m_.exprs.text(id);  // the back end's own value, by its GLSL
    case Op::Parameter:
      // Read through MXC_PARAMETER (mxc_codes.glsl: subgroupBroadcastFirst for mxc's renderer,
      // whose lavapipe gives helper invocations 0 for a storage-buffer load). Matrices are read
      // as they are (the broadcast takes scalars and vectors).
      value = e.type == Type::Mat3 || e.type == Type::Mat4
                  ? fmt::format("mxc_params.{}", m_.exprs.text(id))
                  : fmt::format("MXC_PARAMETER(mxc_params.{})", m_.exprs.text(id));
      parameters_.emplace(m_.exprs.text(id), e.type);
      break;
    case Op::GeomProp: {
      std::string fallback = args.empty() ? fmt::format("{}(0.0)", type) : a(0);
      value = geomprop(m_.exprs.text(id), e.type, fallback);
      geomprops_.push_back(m_.exprs.text(id));
      break;
    }
    case Op::Add: value = fmt::format("{} + {}", a(0), a(1)); break;
    case Op::Sub: value = fmt::format("{} - {}", a(0), a(1)); break;
    case Op::Mul: value = fmt::format("{} * {}", a(0), a(1)); break;
    case Op::Div: value = fmt::format("{} / {}", a(0), a(1)); break;
    case Op::Mod: value = fmt::format("mod({}, {})", a(0), a(1)); break;
    case Op::Neg: value = fmt::format("-{}", a(0)); break;
    case Op::Abs: value = fmt::format("abs({})", a(0)); break;
    case Op::Sign: value = fmt::format("sign({})", a(0)); break;
    case Op::Floor: value = fmt::format("floor({})", a(0)); break;
    case Op::Ceil: value = fmt::format("ceil({})", a(0)); break;
    case Op::Round: value = fmt::format("round({})", a(0)); break;
    case Op::Fract: value = fmt::format("fract({})", a(0)); break;
    case Op::Min: value = fmt::format("min({}, {})", a(0), a(1)); break;
    case Op::Max: value = fmt::format("max({}, {})", a(0), a(1)); break;
    case Op::Clamp: value = fmt::format("clamp({}, {}, {})", a(0), a(1), a(2)); break;
    case Op::Mix: value = fmt::format("mix({}, {}, {})", a(0), a(1), a(2)); break;
    case Op::Pow: value = fmt::format("pow({}, {})", a(0), a(1)); break;
    case Op::Sqrt: value = fmt::format("sqrt({})", a(0)); break;
    case Op::Exp: value = fmt::format("exp({})", a(0)); break;
    case Op::Ln: value = fmt::format("log({})", a(0)); break;
    case Op::Sin: value = fmt::format("sin({})", a(0)); break;
    case Op::Cos: value = fmt::format("cos({})", a(0)); break;
    case Op::Tan: value = fmt::format("tan({})", a(0)); break;
    case Op::Asin: value = fmt::format("asin({})", a(0)); break;
    case Op::Acos: value = fmt::format("acos({})", a(0)); break;
    case Op::Atan2: value = fmt::format("atan({}, {})", a(0), a(1)); break;
    case Op::Step: value = fmt::format("step({}, {})", a(0), a(1)); break;
    case Op::SmoothStep: value = fmt::format("smoothstep({}, {}, {})", a(0), a(1), a(2)); break;
    case Op::Dot: value = fmt::format("dot({}, {})", a(0), a(1)); break;
    case Op::Cross: value = fmt::format("cross({}, {})", a(0), a(1)); break;
    case Op::Length: value = fmt::format("length({})", a(0)); break;
    case Op::Normalize:
      // Guarded: a zero vector keeps its direction undefined, so the shading normal is used.
      value = e.type == Type::Vec3 ? fmt::format("mxc_safe_normalize({}, g.N)", a(0))
                                   : fmt::format("({} == {}(0.0) ? {} : normalize({}))", a(0), type, a(0), a(0));
      break;
    case Op::Reflect: value = fmt::format("reflect({}, {})", a(0), a(1)); break;
    case Op::Refract: value = fmt::format("refract({}, {}, {})", a(0), a(1), a(2)); break;
    case Op::Splat: value = fmt::format("{}({})", type, a(0)); break;
    case Op::Construct: {
      std::vector<std::string> parts;
      for (size_t i = 0; i < args.size(); ++i) parts.push_back(a(i));
      value = fmt::format("{}({})", type, fmt::join(parts, ", "));
      break;
    }
    case Op::Extract: {
      const Type from = m_.exprs[args[0]].type;
      value = ir::componentCount(from) <= 1 ? a(0) : fmt::format("{}[{}]", a(0), e.payload);
      break;
    }
    case Op::Swizzle: {
      std::string channels = m_.exprs.text(id);
      std::vector<std::string> parts;
      for (char c : channels) {
        if (c == '0' || c == '1') parts.push_back(c == '1' ? "1.0" : "0.0");
        else if (ir::componentCount(m_.exprs[args[0]].type) <= 1) parts.push_back(a(0));
        else parts.push_back(fmt::format("{}[{}]", a(0), std::string_view("rgbaxyzw").find(c) % 4));
      }
      value = parts.size() == 1 ? parts[0] : fmt::format("{}({})", type, fmt::join(parts, ", "));
      break;
    }
    case Op::Greater: value = fmt::format("({} > {})", a(0), a(1)); break;
    case Op::GreaterEq: value = fmt::format("({} >= {})", a(0), a(1)); break;
    case Op::Equal: value = fmt::format("({} == {})", a(0), a(1)); break;
    case Op::And: value = fmt::format("({} && {})", a(0), a(1)); break;
    case Op::Or: value = fmt::format("({} || {})", a(0), a(1)); break;
    case Op::Not: value = fmt::format("(!{})", a(0)); break;
    case Op::Select: value = fmt::format("({} ? {} : {})", a(0), a(1), a(2)); break;
    case Op::MatMul: value = fmt::format("({} * {})", a(0), a(1)); break;
    case Op::Transpose: value = fmt::format("transpose({})", a(0)); break;
    case Op::Determinant: value = fmt::format("determinant({})", a(0)); break;
    case Op::Inverse: value = fmt::format("inverse({})", a(0)); break;
    case Op::Luminance: value = fmt::format("{}(dot({}.rgb, {}))", type, a(0), a(1)); break;
    case Op::RgbToHsv: value = fmt::format("mxc_rgb_to_hsv({})", a(0)); procedural_ = true; break;
    case Op::HsvToRgb: value = fmt::format("mxc_hsv_to_rgb({})", a(0)); procedural_ = true; break;
    case Op::Noise2D:
    case Op::Noise3D: {
      procedural_ = true;
      std::string p = e.op == Op::Noise2D ? fmt::format("vec3({}, 0.0)", a(0)) : a(0);
      value = e.type == Type::Float ? fmt::format("mxc_noise_float({})", p)
                                    : fmt::format("{}(mxc_noise_vec3({}){})", type, p,
                                                  e.type == Type::Vec4 ? ", mxc_noise_float(" + p + " + 19.1)" : "");
      if (e.type == Type::Vec2) value = fmt::format("mxc_noise_vec3({}).xy", p);
      break;
    }
    case Op::Fractal3D:
      procedural_ = true;
      value = e.type == Type::Float
                  ? fmt::format("mxc_fractal_float({}, {}, {}, {})", a(0), a(1), a(2), a(3))
                  : fmt::format("{}(mxc_fractal_vec3({}, {}, {}, {}){})", type, a(0), a(1), a(2), a(3),
                                e.type == Type::Vec4 ? ", 0.0" : "");
      if (e.type == Type::Vec2) value = fmt::format("mxc_fractal_vec3({}, {}, {}, {}).xy", a(0), a(1), a(2), a(3));
      break;
    case Op::CellNoise2D: procedural_ = true; value = fmt::format("{}(mxc_cellnoise(vec3({}, 0.0)))", type, a(0)); break;
    case Op::CellNoise3D: procedural_ = true; value = fmt::format("{}(mxc_cellnoise({}))", type, a(0)); break;
    case Op::WorleyNoise2D:
      procedural_ = true;
      value = fmt::format("{}(mxc_worley(vec3({}, 0.0), {}))", type, a(0), a(1));
      break;
    case Op::WorleyNoise3D: procedural_ = true; value = fmt::format("{}(mxc_worley({}, {}))", type, a(0), a(1)); break;
    case Op::Flake: procedural_ = true; value = fmt::format("mxc_flake({}, {})", a(0), a(1)); break;
    case Op::ImageSample: {
      procedural_ = true;
      const ImageSampling sampling = imageSampling(m_.exprs.text(id));
      std::string sampler = texture(m_.exprs.text(args[0]), sampling.colorspace);
      std::string fallback = a(2);
      const int n = ir::componentCount(e.type);
      std::string fallback4 = n == 1   ? fmt::format("vec4({})", fallback)
                              : n == 2 ? fmt::format("vec4({}, 0.0, 1.0)", fallback)
                              : n == 3 ? fmt::format("vec4({}, 1.0)", fallback)
                                       : fallback;
      // The harness sets bit k of missing_textures when texture k's file cannot be read: the
      // node's default is used instead (MaterialX "image": default "if the file cannot be read").
      std::string sample = fmt::format("mxc_sample_image(MXC_SAMPLER2D_ARGUMENT({}), {}, {}, {}, {}, {}, {})", sampler, a(1),
                                       fallback4, int(sampling.uaddress), int(sampling.vaddress), int(sampling.filter),
                                       missing(sampler));
      value = n == 1 ? sample + ".r" : n == 2 ? sample + ".rg" : n == 3 ? sample + ".rgb" : sample;
      break;
    }
    case Op::ImageMissing:
      value = missing(texture(m_.exprs.text(args[0]), m_.exprs.text(id)));
      break;
    case Op::HeightToNormal:
      procedural_ = true;
      value = fmt::format("mxc_heighttonormal({}, {}, {})", a(0), a(1), a(2));
      break;
    case Op::NormalMap:
      procedural_ = true;
      value = fmt::format("mxc_normalmap({}, {}, {}, {}, {})", a(0), a(1), a(2), a(3), a(4));
      break;
    case Op::Rotate3D: procedural_ = true; value = fmt::format("mxc_rotate3d({}, {}, {})", a(0), a(1), a(2)); break;
    case Op::Rotate2D: procedural_ = true; value = fmt::format("mxc_rotate2d({}, {})", a(0), a(1)); break;
    case Op::TransformPoint:
    case Op::TransformVector:
    case Op::TransformNormal: {
      std::vector<std::string> spaces = split(m_.exprs.text(id), ',');
      const bool toWorld = spaces.size() == 2 && spaces[1] == "world" && spaces[0] != "world";
      const bool same = spaces.size() != 2 || (spaces[0] == "world") == (spaces[1] == "world");
      const TransformKind kind = e.op == Op::TransformPoint    ? TransformKind::Point
                                 : e.op == Op::TransformVector ? TransformKind::Vector
                                                               : TransformKind::Normal;
      value = same ? a(0) : fmt::format("mxc_transform(g, {}, {}, {})", a(0), int(kind), toWorld ? "true" : "false");
      break;
    }
  }
  std::string name = fmt::format("v{}", id);
  statements_.add(fmt::format("  {} {} = {};", type, name, value), origins_[id]);
  return name;
}

}  // namespace mxc::glsl
