// Lowering rules for value nodes of the MaterialX standard library (MaterialX Specification
// 1.39, "Standard Nodes") and the value nodes of pbrlib (roughness_anisotropy, artistic_ior).
// Each rule turns a node's inputs into IR expressions; formulas cite their definition.

#include <cmath>
#include <unordered_map>
#include <utility>

#include <fmt/format.h>

#include "compiler/common/ColorSpace.h"
#include "compiler/lower/Context.h"
#include "compiler/lower/Microfacet.h"

namespace mxc::lower {

using ir::ExprId;
using ir::Op;
using ir::Type;

namespace {

/// An input as an IR value; unset inputs (which a nodedef default normally prevents) are zero.
ExprId in(Context& c, const NodeRef& n, std::string_view name) {
  ExprId v = c.input(n, name);
  return v != ir::kNoExpr ? v : c.b.vec(c.inputType(n, name), 0.0f);
}

bool hasInput(const NodeRef& n, std::string_view name) { return n.node->findInput(name) != nullptr; }

/// A uniform integer input's constant value, or `fallback` when it is not a constant.
int intInput(Context& c, const NodeRef& n, std::string_view name, int fallback) {
  ExprId v = c.input(n, name);
  if (v == ir::kNoExpr || !c.material.exprs.isConstant(v)) return fallback;
  std::vector<float> comps = c.material.exprs.constantComponents(v);
  return comps.empty() ? fallback : static_cast<int>(comps[0]);
}

bool isMatrix(Type t) { return t == Type::Mat3 || t == Type::Mat4; }

// --- Math (MaterialX "Math Nodes") ---

ExprId binaryRule(Context& c, const NodeRef& n, Op op) {
  ExprId a = in(c, n, "in1");
  ExprId b = in(c, n, "in2");
  return c.b.binary(op, a, b);
}

ExprId add(Context& c, const NodeRef& n, std::string_view, Type) { return binaryRule(c, n, Op::Add); }
ExprId subtract(Context& c, const NodeRef& n, std::string_view, Type) { return binaryRule(c, n, Op::Sub); }
ExprId multiply(Context& c, const NodeRef& n, std::string_view, Type type) {
  // Matrix multiply is the matrix product; everything else is component-wise.
  if (isMatrix(type)) return c.material.exprs.op(Op::MatMul, type, {in(c, n, "in1"), in(c, n, "in2")});
  return binaryRule(c, n, Op::Mul);
}
ExprId divide(Context& c, const NodeRef& n, std::string_view, Type type) {
  if (isMatrix(type)) {
    ExprId inverse = c.material.exprs.op(Op::Inverse, type, {in(c, n, "in2")});
    return c.material.exprs.op(Op::MatMul, type, {in(c, n, "in1"), inverse});
  }
  return binaryRule(c, n, Op::Div);  // as the document writes it: user arithmetic is not altered
}
ExprId modulo(Context& c, const NodeRef& n, std::string_view, Type) { return binaryRule(c, n, Op::Mod); }
ExprId power(Context& c, const NodeRef& n, std::string_view, Type) { return binaryRule(c, n, Op::Pow); }
ExprId minimum(Context& c, const NodeRef& n, std::string_view, Type) { return binaryRule(c, n, Op::Min); }
ExprId maximum(Context& c, const NodeRef& n, std::string_view, Type) { return binaryRule(c, n, Op::Max); }
ExprId safepower(Context& c, const NodeRef& n, std::string_view, Type) {
  // sign(a) * |a|^b: defined for negative bases (MaterialX "safepower").
  ExprId a = in(c, n, "in1");
  return c.b.mul(c.b.sign(a), c.b.pow(c.b.abs(a), in(c, n, "in2")));
}
ExprId atan2(Context& c, const NodeRef& n, std::string_view, Type) {
  return c.b.atan2(in(c, n, "iny"), in(c, n, "inx"));
}

template <Op op>
ExprId unaryRule(Context& c, const NodeRef& n, std::string_view, Type) {
  return c.b.unary(op, in(c, n, "in"));
}

ExprId fract(Context& c, const NodeRef& n, std::string_view, Type) {
  ExprId x = in(c, n, "in");
  return c.b.sub(x, c.b.unary(Op::Floor, x));
}
ExprId magnitude(Context& c, const NodeRef& n, std::string_view, Type) {
  return c.material.exprs.op(Op::Length, Type::Float, {in(c, n, "in")});
}
ExprId distance(Context& c, const NodeRef& n, std::string_view, Type) {
  return c.material.exprs.op(Op::Length, Type::Float, {c.b.sub(in(c, n, "in1"), in(c, n, "in2"))});
}
ExprId dotproduct(Context& c, const NodeRef& n, std::string_view, Type) {
  return c.b.dot(in(c, n, "in1"), in(c, n, "in2"));
}
ExprId crossproduct(Context& c, const NodeRef& n, std::string_view, Type) {
  return c.material.exprs.op(Op::Cross, Type::Vec3, {in(c, n, "in1"), in(c, n, "in2")});
}
ExprId reflect(Context& c, const NodeRef& n, std::string_view, Type) {
  // in - 2 dot(N, in) N (MaterialX "reflect"; GLSL reflect()): N is used as given, as there.
  const ExprId i = in(c, n, "in");
  const ExprId normal = in(c, n, "normal");
  return c.b.sub(i, c.b.mul(c.b.mul(c.b.f(2.0f), c.b.dot(normal, i)), normal));
}
ExprId invert(Context& c, const NodeRef& n, std::string_view, Type) {
  return c.b.sub(in(c, n, "amount"), in(c, n, "in"));  // amount - in
}
ExprId clamp(Context& c, const NodeRef& n, std::string_view, Type) {
  return c.b.clamp(in(c, n, "in"), in(c, n, "low"), in(c, n, "high"));
}
ExprId mix(Context& c, const NodeRef& n, std::string_view, Type) {
  // MaterialX mix: fg * mix + bg * (1 - mix).
  return c.b.lerp(in(c, n, "bg"), in(c, n, "fg"), in(c, n, "mix"));
}
ExprId remap(Context& c, const NodeRef& n, std::string_view, Type) {
  // outlow + (in - inlow) (outhigh - outlow) / (inhigh - inlow), as the document writes it.
  ExprId x = in(c, n, "in");
  ExprId inlow = in(c, n, "inlow");
  ExprId outlow = in(c, n, "outlow");
  ExprId t = c.b.div(c.b.sub(x, inlow), c.b.sub(in(c, n, "inhigh"), inlow));
  return c.b.add(outlow, c.b.mul(t, c.b.sub(in(c, n, "outhigh"), outlow)));
}
ExprId range(Context& c, const NodeRef& n, std::string_view, Type) {
  // MaterialX "range": remap to [0, 1], apply 1/gamma, remap to the output range, optional clamp.
  ExprId x = in(c, n, "in");
  ExprId inlow = in(c, n, "inlow");
  ExprId outlow = in(c, n, "outlow");
  ExprId t = c.b.div(c.b.sub(x, inlow), c.b.sub(in(c, n, "inhigh"), inlow));
  t = c.b.pow(t, c.b.div(c.b.vec(c.b.type(in(c, n, "gamma")), 1.0f), in(c, n, "gamma")));
  ExprId out = c.b.add(outlow, c.b.mul(t, c.b.sub(in(c, n, "outhigh"), outlow)));
  ExprId doClamp = in(c, n, "doclamp");
  ExprId clamped = c.b.clamp(out, outlow, in(c, n, "outhigh"));
  return c.b.select(doClamp, clamped, out);
}
ExprId smoothstep(Context& c, const NodeRef& n, std::string_view, Type type) {
  ExprId low = c.b.splat(in(c, n, "low"), type);
  ExprId high = c.b.splat(in(c, n, "high"), type);
  return c.material.exprs.op(Op::SmoothStep, type, {low, high, in(c, n, "in")});
}
ExprId normalize(Context& c, const NodeRef& n, std::string_view, Type) { return c.b.normalize(in(c, n, "in")); }
ExprId mincomponent(Context& c, const NodeRef& n, std::string_view, Type) { return c.b.minComponent(in(c, n, "in")); }
ExprId maxcomponent(Context& c, const NodeRef& n, std::string_view, Type) { return c.b.maxComponent(in(c, n, "in")); }

// --- Logic and selection (MaterialX "Conditional Nodes") ---

template <Op compare>
ExprId conditional(Context& c, const NodeRef& n, std::string_view, Type) {
  ExprId condition = c.material.exprs.op(compare, Type::Bool, {in(c, n, "value1"), in(c, n, "value2")});
  if (!hasInput(n, "in1")) return condition;  // the boolean-output variants
  return c.b.select(condition, in(c, n, "in1"), in(c, n, "in2"));
}
ExprId switchRule(Context& c, const NodeRef& n, std::string_view, Type type) {
  // in1 when which < 1, in2 when which < 2, ... (MaterialX "switch"), as a chain of selects.
  ExprId which = in(c, n, "which");
  if (c.b.type(which) != Type::Float) which = c.material.exprs.op(Op::Construct, Type::Float, {which});
  int count = 0;
  while (hasInput(n, fmt::format("in{}", count + 1))) ++count;
  ExprId result = in(c, n, fmt::format("in{}", count));
  for (int i = count - 1; i >= 1; --i) {
    ExprId below = c.material.exprs.op(Op::Greater, Type::Bool, {c.b.f(static_cast<float>(i)), which});
    result = c.b.select(below, in(c, n, fmt::format("in{}", i)), result);
  }
  (void)type;
  return result;
}
ExprId logicAnd(Context& c, const NodeRef& n, std::string_view, Type) {
  return c.material.exprs.op(Op::And, Type::Bool, {in(c, n, "in1"), in(c, n, "in2")});
}
ExprId logicOr(Context& c, const NodeRef& n, std::string_view, Type) {
  return c.material.exprs.op(Op::Or, Type::Bool, {in(c, n, "in1"), in(c, n, "in2")});
}
ExprId logicNot(Context& c, const NodeRef& n, std::string_view, Type) {
  return c.material.exprs.op(Op::Not, Type::Bool, {in(c, n, "in")});
}
ExprId logicXor(Context& c, const NodeRef& n, std::string_view, Type) {
  ExprId a = in(c, n, "in1");
  ExprId b = in(c, n, "in2");
  return c.material.exprs.op(Op::Not, Type::Bool, {c.material.exprs.op(Op::Equal, Type::Bool, {a, b})});
}

// --- Channels (MaterialX "Channel Nodes") ---

ExprId constant(Context& c, const NodeRef& n, std::string_view, Type) { return in(c, n, "value"); }
ExprId identity(Context& c, const NodeRef& n, std::string_view, Type) { return in(c, n, "in"); }
ExprId convert(Context& c, const NodeRef& n, std::string_view, Type type) { return c.b.convert(in(c, n, "in"), type); }
ExprId combine(Context& c, const NodeRef& n, std::string_view, Type type) {
  std::vector<ExprId> parts;
  for (int i = 1; hasInput(n, fmt::format("in{}", i)); ++i) parts.push_back(in(c, n, fmt::format("in{}", i)));
  return c.b.construct(type, parts);
}
ExprId separate(Context& c, const NodeRef& n, std::string_view output, Type) {
  // Outputs outr/outg/outb/outa or outx/outy/outz/outw select one component.
  const std::string_view names = "rgbaxyzw";
  const size_t at = output.empty() ? std::string_view::npos : names.find(output.back());
  const int component = at == std::string_view::npos ? 0 : static_cast<int>(at % 4);
  return c.b.extract(in(c, n, "in"), component);
}
ExprId extract(Context& c, const NodeRef& n, std::string_view, Type) {
  return c.b.extract(in(c, n, "in"), intInput(c, n, "index", 0));
}

// --- Geometry and application (MaterialX "Geometric Nodes", "Application Nodes") ---

/// Geometric property names follow the geompropdefs of the standard library: P, N, T, B
/// with "object" or "world" (a "model" space request reads the object space value).
std::string spaceName(Context& c, const NodeRef& n) {
  std::string space = c.stringInput(n, "space");
  return space == "world" ? "world" : "object";
}
ExprId position(Context& c, const NodeRef& n, std::string_view, Type type) {
  return c.material.exprs.named(Op::GeomProp, type, spaceName(c, n) == "world" ? "Pworld" : "Pobject");
}
ExprId normal(Context& c, const NodeRef& n, std::string_view, Type type) {
  return c.material.exprs.named(Op::GeomProp, type, spaceName(c, n) == "world" ? "Nworld" : "Nobject");
}
ExprId tangent(Context& c, const NodeRef& n, std::string_view, Type type) {
  return c.material.exprs.named(Op::GeomProp, type, spaceName(c, n) == "world" ? "Tworld" : "Tobject");
}
ExprId bitangent(Context& c, const NodeRef& n, std::string_view, Type type) {
  return c.material.exprs.named(Op::GeomProp, type, spaceName(c, n) == "world" ? "Bworld" : "Bobject");
}
ExprId viewdirection(Context& c, const NodeRef& n, std::string_view, Type type) {
  return c.material.exprs.named(Op::GeomProp, type, spaceName(c, n) == "world" ? "Vworld" : "Vobject");
}
// nprlib (MaterialX 1.39 "NPR Nodes").
ExprId facingratio(Context& c, const NodeRef& n, std::string_view, Type) {
  // The cosine between the view direction and the normal, as given: -dot(V, N) (V points from
  // the eye), or |dot(V, N)| when faceforward; inverted to 1 - cosine when asked.
  ir::ExprBuilder& b = c.b;
  const ExprId d = b.dot(in(c, n, "viewdirection"), in(c, n, "normal"));
  const ExprId facing = b.select(b.greater(b.convert(in(c, n, "faceforward"), Type::Float), b.f(0.5f)), b.abs(d), b.neg(d));
  return b.select(b.greater(b.convert(in(c, n, "invert"), Type::Float), b.f(0.5f)), b.oneMinus(facing), facing);
}
ExprId goochShade(Context& c, const NodeRef& n, std::string_view, Type) {
  // Gooch et al. 1998, "A Non-Photorealistic Lighting Model for Automatic Technical
  // Illustration", eq. 2: the tone runs from the warm colour (facing the light) to the cool one,
  // k = (1 + N.L) / 2 for the direction L the light travels (MaterialX's light_direction), plus
  // a Phong highlight max(-L . R, 0)^shininess of the view reflected about the normal. The
  // vectors are normalised; a zero light direction gives a zero vector (k = 1/2, no highlight).
  ir::ExprBuilder& b = c.b;
  const ExprId normal = b.normalize(c.material.exprs.named(Op::GeomProp, Type::Vec3, "Nworld"));
  const ExprId view = b.normalize(c.material.exprs.named(Op::GeomProp, Type::Vec3, "Vworld"));
  const ExprId light = b.normalize(in(c, n, "light_direction"));
  const ExprId k = b.mul(b.add(b.f(1.0f), b.dot(normal, light)), b.f(0.5f));
  const ExprId tone = b.lerp(in(c, n, "warm_color"), in(c, n, "cool_color"), k);
  const ExprId reflected = b.sub(view, b.mul(normal, b.mul(b.f(2.0f), b.dot(normal, view))));
  // pow of a base in [0, 1] (max(.., 0) and unit vectors).
  const ExprId highlight = b.pow(b.max(b.neg(b.dot(light, reflected)), b.f(0.0f)), in(c, n, "shininess"));
  return b.add(tone, b.splat(b.mul(highlight, in(c, n, "specular_intensity")), Type::Vec3));
}
ExprId texcoord(Context& c, const NodeRef& n, std::string_view, Type type) {
  return c.material.exprs.named(Op::GeomProp, type, fmt::format("UV{}", intInput(c, n, "index", 0)));
}
ExprId geomcolor(Context& c, const NodeRef& n, std::string_view, Type type) {
  return c.material.exprs.named(Op::GeomProp, type, fmt::format("color{}", intInput(c, n, "index", 0)));
}
ExprId geompropvalue(Context& c, const NodeRef& n, std::string_view, Type type) {
  // A named primvar, with the node's default when the geometry does not have it.
  return c.material.exprs.opWithString(Op::GeomProp, type, {in(c, n, "default")}, c.stringInput(n, "geomprop"));
}
ExprId frame(Context& c, const NodeRef&, std::string_view, Type type) {
  return c.material.exprs.named(Op::Parameter, type, "frame");
}
ExprId time(Context& c, const NodeRef&, std::string_view, Type type) {
  return c.material.exprs.named(Op::Parameter, type, "time");
}

// --- Textures (MaterialX "Texture Nodes") ---

/// The colour space a colour image's texels are in ("" for an image of another type: MaterialX
/// converts colour3 and colour4 images only; float and vector images are data).
std::string texelSpace(Context& c, const NodeRef& n, Type type) {
  return type == Type::Vec3 || type == Type::Vec4 ? c.colorspace(n, "file") : std::string();
}
/// A sampled colour in the working space. An sRGB-encoded texture is decoded by the device
/// (the renderer reads it through an sRGB format, runtime/MaterialResources.cpp), so only its
/// primaries are left to convert here.
ExprId texelsToWorkingSpace(Context& c, const NodeRef& n, ExprId sampled, const std::string& space) {
  return c.toWorkingSpace(sampled, space, c.origin(n, "file").location, deviceDecodes(space));
}
/// A UDIM tile set (Context::udimTiles): each tile sampled over its own unit square of texture
/// space (clamped there: tile edges are the set's seams), the one under `uv` chosen; outside
/// every tile, the node's default.
ExprId sampleTiles(Context& c, const NodeRef& n, ExprId uv, Type type, const std::vector<Context::UdimTile>& tiles,
                   const std::string& filter, const std::string& space, ExprId fallback) {
  ExprId tileU = c.b.unary(Op::Floor, c.b.extract(uv, 0));
  ExprId tileV = c.b.unary(Op::Floor, c.b.extract(uv, 1));
  ExprId local = c.b.sub(uv, c.b.construct(Type::Vec2, {tileU, tileV}));
  if (fallback == ir::kNoExpr) fallback = in(c, n, "default");
  ExprId result = fallback;
  for (const Context::UdimTile& tile : tiles) {
    c.material.addImage(tile.file, c.origin(n, "file"));
    ExprId texture = c.material.exprs.named(Op::Texture, Type::String, tile.file);
    ExprId sampled = c.material.exprs.opWithString(Op::ImageSample, type, {texture, local, fallback},
                                                   fmt::format("clamp,clamp,{},{}", filter, space));
    // 1001 + u + 10 v (MaterialX "Filename Substitutions"): u in 0..9, v from 0.
    const int u = (tile.number - 1001) % 10;
    const int v = (tile.number - 1001) / 10;
    ExprId here = c.material.exprs.op(Op::And, Type::Bool,
                                      {c.material.exprs.op(Op::Equal, Type::Bool, {tileU, c.b.f(float(u))}),
                                       c.material.exprs.op(Op::Equal, Type::Bool, {tileV, c.b.f(float(v))})});
    result = c.b.select(here, sampled, result);
  }
  return result;
}
/// The node's texture at `uv`, in the working space; `fallback` where the file cannot be read
/// (the node's `default` unless given). `missing`, when asked for, is set to the condition
/// "the file could not be read" (false for a UDIM set, whose tiles each fall back).
ExprId sample(Context& c, const NodeRef& n, ExprId uv, Type type, std::string_view uaddress, std::string_view vaddress,
              ExprId fallback = ir::kNoExpr, ExprId* missing = nullptr) {
  // The default is read where the sample needs it (the IR's expressions keep their order).
  std::string filter = c.stringInput(n, "filtertype");
  if (filter.empty()) filter = "linear";
  const std::string space = texelSpace(c, n, type);
  if (std::vector<Context::UdimTile> tiles = c.udimTiles(n); !tiles.empty()) {
    if (missing) *missing = c.material.exprs.constantBool(false);
    return texelsToWorkingSpace(c, n, sampleTiles(c, n, uv, type, tiles, filter, space, fallback), space);
  }
  const std::string file = c.imageFile(n);
  c.material.addImage(file, c.origin(n, "file"));
  ExprId texture = c.material.exprs.named(Op::Texture, Type::String, file);
  if (fallback == ir::kNoExpr) fallback = in(c, n, "default");
  ExprId sampled = c.material.exprs.opWithString(Op::ImageSample, type, {texture, uv, fallback},
                                                 fmt::format("{},{},{},{}", uaddress, vaddress, filter, space));
  if (missing) *missing = c.material.exprs.opWithString(Op::ImageMissing, Type::Bool, {texture}, space);
  return texelsToWorkingSpace(c, n, sampled, space);
}
ExprId image(Context& c, const NodeRef& n, std::string_view, Type type) {
  std::string u = c.stringInput(n, "uaddressmode");
  std::string v = c.stringInput(n, "vaddressmode");
  return sample(c, n, in(c, n, "texcoord"), type, u.empty() ? "periodic" : u, v.empty() ? "periodic" : v);
}
ExprId tiledimage(Context& c, const NodeRef& n, std::string_view, Type type) {
  // uv = (texcoord * uvtiling - uvoffset) / realworldimagesize * realworldtilesize, periodic.
  ExprId uv = c.b.sub(c.b.mul(in(c, n, "texcoord"), in(c, n, "uvtiling")), in(c, n, "uvoffset"));
  uv = c.b.mul(c.b.div(uv, in(c, n, "realworldimagesize")), in(c, n, "realworldtilesize"));
  return sample(c, n, uv, type, "periodic", "periodic");
}
ExprId hextiledimage(Context& c, const NodeRef& n, std::string_view, Type type) {
  // Hexagonal tiling (Mikkelsen 2022) is done by the shader library; the IR keeps its inputs.
  const std::string file = c.imageFile(n);
  c.material.addImage(file, c.origin(n, "file"));
  ExprId texture = c.material.exprs.named(Op::Texture, Type::String, file);
  ExprId uv = c.b.mul(in(c, n, "texcoord"), in(c, n, "tiling"));
  std::vector<ExprId> args{texture, uv, in(c, n, "default"), in(c, n, "rotation"), in(c, n, "rotationrange"),
                           in(c, n, "scale"), in(c, n, "scalerange"), in(c, n, "offset"), in(c, n, "offsetrange"),
                           in(c, n, "falloff"), in(c, n, "falloffcontrast"), in(c, n, "lumacoeffs")};
  const std::string space = texelSpace(c, n, type);
  ExprId sampled = c.material.exprs.opWithString(Op::ImageSample, type, args, fmt::format("hex,hex,linear,{}", space));
  return texelsToWorkingSpace(c, n, sampled, space);
}
ExprId place2d(Context& c, const NodeRef& n, std::string_view, Type) {
  // operationorder 0 (SRT): rotate((uv - pivot) / scale) - offset + pivot;
  // operationorder 1 (TRS): rotate((uv - pivot) - offset) / scale + pivot.
  ExprId uv = c.b.sub(in(c, n, "texcoord"), in(c, n, "pivot"));
  ExprId scale = in(c, n, "scale");
  ExprId rotate = in(c, n, "rotate");
  ExprId offset = in(c, n, "offset");
  ExprId pivot = in(c, n, "pivot");
  auto rotated = [&](ExprId v) { return c.material.exprs.op(Op::Rotate2D, Type::Vec2, {v, rotate}); };
  ExprId srt = c.b.add(c.b.sub(rotated(c.b.div(uv, scale)), offset), pivot);
  ExprId trs = c.b.add(c.b.div(rotated(c.b.sub(uv, offset)), scale), pivot);
  ExprId order = in(c, n, "operationorder");
  ExprId isTrs = c.material.exprs.op(Op::Greater, Type::Bool, {order, c.material.exprs.constantInt(0)});
  return c.b.select(isTrs, trs, srt);
}
// glTF's texture lookups (MaterialX's gltf_image, gltf_colorimage, gltf_normalmap): the texture
// coordinate placed by KHR_texture_transform, uv' = T(offset) R(rotation) S(scale) uv in glTF's
// frame (origin top left, v down; the extension's matrices are column-major, so R turns
// counter-clockwise), seen from MaterialX's frame (v up) through the pivot, (0, 1) by default:
// with d = uv - pivot and R- the rotation by -rotate degrees,
//   operationorder 0 (glTF's own): R-(d * scale) + offset * (1, -1) + pivot,
//   operationorder 1: R-(d + offset * (1, -1)) * scale + pivot,
// MaterialX's place2d of 1 / scale, -rotate and offset * (-1, 1) written without dividing by
// the scale (a scale of 0 collapses the image to a texel instead of dividing by 0).
ExprId gltfPlaced(Context& c, const NodeRef& n, bool glTFOrder = false) {
  ExprId d = c.b.sub(in(c, n, "texcoord"), in(c, n, "pivot"));
  ExprId scale = in(c, n, "scale");
  ExprId offset = c.b.mul(in(c, n, "offset"), c.material.exprs.constantVector(Type::Vec2, {1.0f, -1.0f}));
  ExprId minus = c.b.neg(in(c, n, "rotate"));
  auto rotated = [&](ExprId v) { return c.material.exprs.op(Op::Rotate2D, Type::Vec2, {v, minus}); };
  ExprId first = c.b.add(c.b.add(rotated(c.b.mul(d, scale)), offset), in(c, n, "pivot"));
  if (glTFOrder) return first;
  ExprId second = c.b.add(c.b.mul(rotated(c.b.add(d, offset)), scale), in(c, n, "pivot"));
  ExprId isSecond = c.material.exprs.op(Op::Greater, Type::Bool, {in(c, n, "operationorder"), c.material.exprs.constantInt(0)});
  return c.b.select(isSecond, second, first);
}
ExprId gltfTexture(Context& c, const NodeRef& n, Type type, bool glTFOrder) {
  std::string u = c.stringInput(n, "uaddressmode");
  std::string v = c.stringInput(n, "vaddressmode");
  return sample(c, n, gltfPlaced(c, n, glTFOrder), type, u.empty() ? "periodic" : u, v.empty() ? "periodic" : v);
}
ExprId gltfImage(Context& c, const NodeRef& n, std::string_view, Type type) {
  ExprId texel = gltfTexture(c, n, type, false);
  return hasInput(n, "factor") ? c.b.mul(texel, in(c, n, "factor")) : texel;  // the vector3 variant has no factor
}
ExprId gltfColorImage(Context& c, const NodeRef& n, std::string_view output, Type) {
  // glTF "baseColor": the texture (in glTF's own order of placement) times the colour factor
  // times the vertex colour; outcolor is its rgb, outa its alpha.
  ExprId rgba = c.b.mul(c.b.mul(gltfTexture(c, n, Type::Vec4, true), in(c, n, "color")), in(c, n, "geomcolor"));
  if (output == "outa") return c.b.extract(rgba, 3);
  return c.material.exprs.opWithString(Op::Swizzle, Type::Vec3, {rgba}, "xyz");
}
ExprId gltfNormalmap(Context& c, const NodeRef& n, std::string_view, Type) {
  // glTF "normalTexture": a tangent-space normal encoded in [0, 1], as normalmap decodes it.
  ExprId encoded = gltfTexture(c, n, Type::Vec3, false);
  return c.material.exprs.op(Op::NormalMap, Type::Vec3,
                             {encoded, c.b.vec(Type::Vec2, 1.0f), c.material.exprs.named(Op::GeomProp, Type::Vec3, "Nworld"),
                              c.material.exprs.named(Op::GeomProp, Type::Vec3, "Tworld"),
                              c.material.exprs.named(Op::GeomProp, Type::Vec3, "Bworld")});
}
ExprId gltfIridescenceThickness(Context& c, const NodeRef& n, std::string_view, Type) {
  // KHR_materials_iridescence: thickness = mix(minimum, maximum, texture.g), in glTF's order of
  // placement. (MaterialX 1.39's graph of this node mixes the other way round, giving the
  // maximum where g = 0; the extension is followed.)
  const ExprId g = c.b.extract(gltfTexture(c, n, Type::Vec3, true), 1);
  return c.b.lerp(in(c, n, "thicknessMin"), in(c, n, "thicknessMax"), g);
}
ExprId gltfAnisotropyImage(Context& c, const NodeRef& n, std::string_view output, Type) {
  // KHR_materials_anisotropy: the texture's red and green are a direction in [-1, 1]^2 of the
  // tangent frame, its blue a strength. Strength: anisotropy_strength times blue; rotation:
  // anisotropy_rotation plus the direction's angle atan2(y, x) (0 for a zero direction).
  const ExprId texel = gltfTexture(c, n, Type::Vec3, true);
  if (output == "anisotropy_strength_out") return c.b.mul(in(c, n, "anisotropy_strength"), c.b.extract(texel, 2));
  auto signedChannel = [&](int k) { return c.b.sub(c.b.mul(c.b.extract(texel, k), c.b.f(2.0f)), c.b.f(1.0f)); };
  const ExprId x = signedChannel(0), y = signedChannel(1);
  // atan2(0, 0) is undefined in GLSL: a zero direction keeps the rotation as given.
  const ExprId angle = c.b.select(c.b.greater(c.b.add(c.b.abs(x), c.b.abs(y)), c.b.f(0.0f)), c.b.atan2(y, x), c.b.f(0.0f));
  return c.b.add(in(c, n, "anisotropy_rotation"), angle);
}
ExprId normalmap(Context& c, const NodeRef& n, std::string_view, Type) {
  ExprId scale = in(c, n, "scale");
  if (c.b.type(scale) == Type::Float) scale = c.b.splat(scale, Type::Vec2);
  return c.material.exprs.op(Op::NormalMap, Type::Vec3,
                             {in(c, n, "in"), scale, in(c, n, "normal"), in(c, n, "tangent"), in(c, n, "bitangent")});
}

// --- The texture nodes of the UsdPreviewSurface specification (OpenUSD, "UsdPreviewSurface
// Specification", 2.6: "Texture Reader", "Primvar Reader", "Transform2d") ---

/// UsdUVTexture: the texture at st, each component times `scale` plus `bias`; where the file
/// cannot be read, `fallback` as it is (not scaled: it stands for the output). wrapS and wrapT
/// are black (transparent black outside [0, 1], then scaled and biased as a texel is), clamp,
/// repeat (MaterialX's enum writes periodic) or mirror; useMetadata, which mxc's images do not
/// carry, repeats. A one-channel texture gives (v, v, v, 1), a two-channel one (v, v, v, a), as
/// the specification asks (runtime/ImageIOPlugin.cpp widens them so).
ExprId usdUvTexture(Context& c, const NodeRef& n, std::string_view output, Type) {
  auto address = [&](std::string_view name) {
    const std::string mode = c.stringInput(n, name);
    return mode == "black" || mode == "clamp" ? std::string("clamp") : mode == "mirror" ? mode : std::string("periodic");
  };
  const ExprId st = in(c, n, "st");
  ExprId missing = ir::kNoExpr;
  ExprId texel = sample(c, n, st, Type::Vec4, address("wrapS"), address("wrapT"), in(c, n, "fallback"), &missing);
  const ExprId zero = c.b.f(0.0f), one = c.b.f(1.0f);
  for (auto [wrap, axis] : {std::pair{"wrapS", 0}, std::pair{"wrapT", 1}}) {
    if (c.stringInput(n, wrap) != "black") continue;
    const ExprId x = c.b.extract(st, axis);
    const ExprId inside = c.material.exprs.op(Op::And, Type::Bool, {c.material.exprs.op(Op::GreaterEq, Type::Bool, {x, zero}),
                                                                     c.material.exprs.op(Op::GreaterEq, Type::Bool, {one, x})});
    texel = c.b.select(inside, texel, c.b.vec(Type::Vec4, 0.0f));
  }
  const ExprId rgba = c.b.select(missing, in(c, n, "fallback"), c.b.add(c.b.mul(texel, in(c, n, "scale")), in(c, n, "bias")));
  if (output == "rgba") return rgba;
  if (output == "rgb") return c.material.exprs.opWithString(Op::Swizzle, Type::Vec3, {rgba}, "xyz");
  const size_t k = std::string_view("rgba").find(output.empty() ? 'r' : output[0]);
  return c.b.extract(rgba, k == std::string_view::npos ? 0 : static_cast<int>(k));
}
/// UsdPrimvarReader: the primvar `varname`, or `fallback` where the geometry has none. USD's
/// names for what mxc's geometry carries are read as those: `st` is the first texture coordinate
/// set, `displayColor` the vertex colour. A string or filename primvar cannot vary over a
/// surface in a shader: the fallback.
ExprId usdPrimvarReader(Context& c, const NodeRef& n, std::string_view, Type type) {
  const ExprId fallback = in(c, n, "fallback");
  if (type == Type::String) return fallback;
  const std::string name = c.stringInput(n, "varname");
  if (name == "st" && type == Type::Vec2) return c.material.exprs.named(Op::GeomProp, type, "UV0");
  if (name == "displayColor" && (type == Type::Vec3 || type == Type::Vec4)) {
    return c.material.exprs.named(Op::GeomProp, type, "color0");
  }
  return c.material.exprs.opWithString(Op::GeomProp, type, {fallback}, name);
}
/// UsdTransform2d: in scaled, then turned counter-clockwise by `rotation` degrees, then
/// translated (the specification's order: scale, rotate, translate).
ExprId usdTransform2d(Context& c, const NodeRef& n, std::string_view, Type) {
  const ExprId scaled = c.b.mul(in(c, n, "in"), in(c, n, "scale"));
  const ExprId turned = c.material.exprs.op(Op::Rotate2D, Type::Vec2, {scaled, in(c, n, "rotation")});
  return c.b.add(turned, in(c, n, "translation"));
}

// --- Procedural 2D shapes and waves (MaterialX 1.39 "Procedural Nodes"; each formula is that
// of MaterialX's own definition, libraries/stdlib/stdlib_ng.mtlx) ---

ExprId ramp4(Context& c, const NodeRef& n, std::string_view, Type) {
  // Bilinear in the texture coordinate clamped to [0, 1]^2: s from left to right, t from
  // bottom to top.
  ExprId st = c.b.clamp(in(c, n, "texcoord"), c.b.f(0.0f), c.b.f(1.0f));
  ExprId s = c.b.extract(st, 0);
  ExprId t = c.b.extract(st, 1);
  ExprId top = c.b.lerp(in(c, n, "valuetl"), in(c, n, "valuetr"), s);
  ExprId bottom = c.b.lerp(in(c, n, "valuebl"), in(c, n, "valuebr"), s);
  return c.b.lerp(bottom, top, t);
}
// 1 within `radius` of the segment a-b, else 0: the distance to the segment is |p - a - (b - a) h|,
// h the clamped projection. A zero-length segment has |b - a|^2 = 0: the division is guarded (h
// then 0, the distance to the point).
ExprId segmentMask(Context& c, ExprId p, ExprId a, ExprId b, ExprId radius) {
  ExprId pa = c.b.sub(p, a);
  ExprId ba = c.b.sub(b, a);
  ExprId h = c.b.clamp(c.b.safeDiv(c.b.dot(pa, ba), c.b.dot(ba, ba), 1e-12f), c.b.f(0.0f), c.b.f(1.0f));
  ExprId distance = c.material.exprs.op(Op::Length, Type::Float, {c.b.sub(pa, c.b.mul(ba, h))});
  return c.b.select(c.b.greater(distance, radius), c.b.f(0.0f), c.b.f(1.0f));
}
// 1 inside the disc of `radius` about the origin: |p|^2 <= radius^2.
ExprId discMask(Context& c, ExprId p, ExprId radius) {
  return c.b.select(c.b.greater(c.b.dot(p, p), c.b.mul(radius, radius)), c.b.f(0.0f), c.b.f(1.0f));
}
ExprId line(Context& c, const NodeRef& n, std::string_view, Type) {
  // The segment point1-point2 about `center`.
  ExprId p = c.b.sub(in(c, n, "texcoord"), in(c, n, "center"));
  return segmentMask(c, p, in(c, n, "point1"), in(c, n, "point2"), in(c, n, "radius"));
}
ExprId circle(Context& c, const NodeRef& n, std::string_view, Type) {
  return discMask(c, c.b.sub(in(c, n, "texcoord"), in(c, n, "center")), in(c, n, "radius"));
}
// The cells of checkerboard, grid, crosshatch and tiledcircles: texcoord * uvtiling - uvoffset.
ExprId tiledCoordinate(Context& c, const NodeRef& n) {
  return c.b.sub(c.b.mul(in(c, n, "texcoord"), in(c, n, "uvtiling")), in(c, n, "uvoffset"));
}
ExprId checkerboard(Context& c, const NodeRef& n, std::string_view, Type) {
  // color1 on the cells where floor(u') + floor(v') is odd, color2 on the others, for
  // (u', v') = texcoord * uvtiling - uvoffset.
  ExprId uv = tiledCoordinate(c, n);
  ExprId cells = c.b.unary(Op::Floor, uv);
  ExprId odd = c.b.mod(c.b.add(c.b.extract(cells, 0), c.b.extract(cells, 1)), c.b.f(2.0f));
  return c.b.lerp(in(c, n, "color2"), in(c, n, "color1"), odd);
}
// The tiled coordinate split into x and y, with the odd rows (mod(y, 2) > 1) shifted by half a
// cell along x when the node's `staggered` is on (grid and crosshatch).
std::pair<ExprId, ExprId> staggeredCoordinate(Context& c, const NodeRef& n) {
  ExprId uv = tiledCoordinate(c, n);
  ExprId x = c.b.extract(uv, 0);
  ExprId y = c.b.extract(uv, 1);
  ExprId shift = c.b.select(c.b.greater(c.b.mod(y, c.b.f(2.0f)), c.b.f(1.0f)), c.b.f(0.5f), c.b.f(0.0f));
  return {c.b.select(in(c, n, "staggered"), c.b.add(x, shift), x), y};
}
ExprId grid(Context& c, const NodeRef& n, std::string_view, Type) {
  // Lines of width `thickness` (in cell units) on the cell edges: a coordinate is on a line
  // where |2 mod(x, 1) - 1| > 1 - thickness.
  auto [x, y] = staggeredCoordinate(c, n);
  ExprId limit = c.b.sub(c.b.f(1.0f), in(c, n, "thickness"));
  auto onLine = [&](ExprId t) {
    ExprId edge = c.b.abs(c.b.sub(c.b.mul(c.b.mod(t, c.b.f(1.0f)), c.b.f(2.0f)), c.b.f(1.0f)));
    return c.b.select(c.b.greater(edge, limit), c.b.f(1.0f), c.b.f(0.0f));
  };
  return c.b.splat(c.b.max(onLine(x), onLine(y)), Type::Vec3);
}
ExprId crosshatch(Context& c, const NodeRef& n, std::string_view, Type) {
  // Both diagonals of each cell, `thickness` wide, in the cell mapped to [-1, 1]^2.
  auto [x, y] = staggeredCoordinate(c, n);
  auto centred = [&](ExprId t) { return c.b.sub(c.b.mul(c.b.mod(t, c.b.f(1.0f)), c.b.f(2.0f)), c.b.f(1.0f)); };
  ExprId p = c.b.construct(Type::Vec2, {centred(x), centred(y)});
  auto corner = [&](float u, float v) { return c.material.exprs.constantVector(Type::Vec2, {u, v}); };
  ExprId radius = in(c, n, "thickness");
  ExprId lines = c.b.max(segmentMask(c, p, corner(1, 1), corner(-1, -1), radius),
                         segmentMask(c, p, corner(-1, 1), corner(1, -1), radius));
  return c.b.splat(lines, Type::Vec3);
}
ExprId tiledcircles(Context& c, const NodeRef& n, std::string_view, Type) {
  // Regular: a disc of diameter 2 size (radius `size` in the cell mapped to [-1, 1]^2) in each
  // cell. Staggered: discs of radius size / 2 on a hexagonal lattice of rows sqrt(3) / 2 apart
  // (every other row shifted by half a cell), each cell of a row seeing the discs at its two
  // lower corners and at the middle of its top edge.
  ExprId uv = tiledCoordinate(c, n);
  ExprId regular = discMask(c, c.b.sub(c.b.mul(c.b.mod(uv, c.b.f(1.0f)), c.b.f(2.0f)), c.b.f(1.0f)), in(c, n, "size"));
  const float rowPair = 1.73205f, row = 0.866025f;  // sqrt(3), sqrt(3) / 2
  ExprId x = c.b.extract(uv, 0);
  ExprId y = c.b.extract(uv, 1);
  ExprId shift = c.b.select(c.b.greater(c.b.mod(y, c.b.f(rowPair)), c.b.f(row)), c.b.f(0.5f), c.b.f(0.0f));
  ExprId mx = c.b.mod(c.b.add(x, shift), c.b.f(1.0f));
  ExprId my = c.b.mod(y, c.b.f(row));
  ExprId radius = c.b.mul(in(c, n, "size"), c.b.f(0.5f));
  ExprId lowerLeft = discMask(c, c.b.construct(Type::Vec2, {mx, my}), radius);
  ExprId lowerRight = discMask(c, c.b.construct(Type::Vec2, {c.b.sub(c.b.f(1.0f), mx), my}), radius);
  ExprId top = discMask(c, c.b.construct(Type::Vec2, {c.b.sub(mx, c.b.f(0.5f)), c.b.sub(c.b.f(row), my)}), radius);
  ExprId staggered = c.b.max(c.b.max(lowerLeft, lowerRight), top);
  return c.b.splat(c.b.select(in(c, n, "staggered"), staggered, regular), Type::Vec3);
}
// 1 inside a cloverleaf of `radius` about the origin: four discs of radius radius / 2 centred
// radius / 2 away along +-x and +-y, tested as MaterialX's graph tests them, in doubled
// coordinates (d = 2 p; discs of radius r about (+-r, 0) and (0, +-r)).
ExprId cloverleafMask(Context& c, ExprId p, ExprId radius) {
  const ExprId d = c.b.mul(p, c.b.f(2.0f));
  const ExprId zero = c.b.f(0.0f);
  auto leaf = [&](ExprId dx, ExprId dy) { return discMask(c, c.b.add(d, c.b.construct(Type::Vec2, {dx, dy})), radius); };
  return c.b.max(c.b.max(leaf(radius, zero), leaf(c.b.neg(radius), zero)),
                 c.b.max(leaf(zero, c.b.neg(radius)), leaf(zero, radius)));
}
ExprId cloverleaf(Context& c, const NodeRef& n, std::string_view, Type) {
  return cloverleafMask(c, c.b.sub(in(c, n, "texcoord"), in(c, n, "center")), in(c, n, "radius"));
}
ExprId tiledcloverleafs(Context& c, const NodeRef& n, std::string_view, Type) {
  // Regular: a cloverleaf of radius `size` in each cell mapped to [-1, 1]^2. Staggered (as
  // MaterialX's graph lays it out): rows half a cell high, every other one shifted by half a
  // cell, each cell seeing cloverleafs of radius size / 2 at its lower corners and at the middle
  // of its top edge.
  ExprId uv = tiledCoordinate(c, n);
  ExprId regular = cloverleafMask(c, c.b.sub(c.b.mul(c.b.mod(uv, c.b.f(1.0f)), c.b.f(2.0f)), c.b.f(1.0f)), in(c, n, "size"));
  ExprId x = c.b.extract(uv, 0);
  ExprId y = c.b.extract(uv, 1);
  ExprId shift = c.b.select(c.b.greater(c.b.mod(y, c.b.f(1.0f)), c.b.f(0.5f)), c.b.f(0.5f), c.b.f(0.0f));
  ExprId mx = c.b.mod(c.b.add(x, shift), c.b.f(1.0f));
  ExprId my = c.b.mod(y, c.b.f(0.5f));
  ExprId radius = c.b.div(in(c, n, "size"), c.b.f(2.0f));
  ExprId lowerLeft = cloverleafMask(c, c.b.construct(Type::Vec2, {mx, my}), radius);
  ExprId lowerRight = cloverleafMask(c, c.b.construct(Type::Vec2, {c.b.sub(c.b.f(1.0f), mx), my}), radius);
  ExprId top = cloverleafMask(c, c.b.construct(Type::Vec2, {c.b.sub(mx, c.b.f(0.5f)), c.b.sub(c.b.f(0.5f), my)}), radius);
  ExprId staggered = c.b.max(c.b.max(lowerLeft, lowerRight), top);
  return c.b.splat(c.b.select(in(c, n, "staggered"), staggered, regular), Type::Vec3);
}
ExprId trianglewave(Context& c, const NodeRef& n, std::string_view, Type) {
  // Period 1, 0 at the integers and 0.5 half-way: 0.5 - |mod(|x|, 1) - 0.5|.
  ExprId x = c.b.mod(c.b.abs(in(c, n, "in")), c.b.f(1.0f));
  return c.b.sub(c.b.f(0.5f), c.b.abs(c.b.sub(x, c.b.f(0.5f))));
}

ExprId heighttonormal(Context& c, const NodeRef& n, std::string_view, Type) {
  return c.material.exprs.op(Op::HeightToNormal, Type::Vec3, {in(c, n, "in"), in(c, n, "scale"), in(c, n, "texcoord")});
}
ExprId bump(Context& c, const NodeRef& n, std::string_view, Type) {
  // MaterialX's definition (NG_bump_vector3): normalmap(heighttonormal(height), scale, N, T, B),
  // the height's own scale being 1 and its texture coordinate UV0.
  ExprId encoded = c.material.exprs.op(Op::HeightToNormal, Type::Vec3,
                                       {in(c, n, "height"), c.b.f(1.0f), c.material.exprs.named(Op::GeomProp, Type::Vec2, "UV0")});
  return c.material.exprs.op(Op::NormalMap, Type::Vec3,
                             {encoded, c.b.splat(in(c, n, "scale"), Type::Vec2), in(c, n, "normal"), in(c, n, "tangent"),
                              in(c, n, "bitangent")});
}

// --- Procedural (MaterialX "Procedural Nodes") ---

/// amplitude * noise + pivot, with the noise of the output's type.
ExprId noiseWith(Context& c, const NodeRef& n, Op op, ExprId coordinate, Type type) {
  ExprId noise = c.material.exprs.op(op, type, {coordinate});
  return c.b.add(c.b.mul(noise, in(c, n, "amplitude")), in(c, n, "pivot"));
}
ExprId noise2d(Context& c, const NodeRef& n, std::string_view, Type type) {
  return noiseWith(c, n, Op::Noise2D, in(c, n, "texcoord"), type);
}
ExprId noise3d(Context& c, const NodeRef& n, std::string_view, Type type) {
  return noiseWith(c, n, Op::Noise3D, in(c, n, "position"), type);
}
ExprId fractal3d(Context& c, const NodeRef& n, std::string_view, Type type) {
  ExprId noise = c.material.exprs.op(Op::Fractal3D, type,
                                     {in(c, n, "position"), in(c, n, "octaves"), in(c, n, "lacunarity"),
                                      in(c, n, "diminish")});
  return c.b.mul(noise, in(c, n, "amplitude"));
}
ExprId cellnoise2d(Context& c, const NodeRef& n, std::string_view, Type type) {
  return c.material.exprs.op(Op::CellNoise2D, type, {in(c, n, "texcoord")});
}
/// MaterialX's randomfloat hash (its stdlib graph of the node): the cell noise at
/// (in * 4096, seed) for a float input, at (in, seed) for an integer one, a value in [0, 1].
/// randomcolor converts an integer input to a float first (`scaleInteger`).
ExprId randomHash(Context& c, const NodeRef& n, ExprId seed, bool scaleInteger = false) {
  ExprId input = in(c, n, "in");
  const bool integer = c.inputType(n, "in") == Type::Int;
  if (integer) input = c.b.convert(input, Type::Float);
  if (!integer || scaleInteger) input = c.b.mul(input, c.b.f(4096.0f));
  const ExprId at = c.b.construct(Type::Vec2, {input, c.b.convert(seed, Type::Float)});
  return c.b.clamp01(c.material.exprs.op(Op::CellNoise2D, Type::Float, {at}));
}
ExprId randomfloat(Context& c, const NodeRef& n, std::string_view, Type) {
  return c.b.lerp(in(c, n, "min"), in(c, n, "max"), randomHash(c, n, in(c, n, "seed")));
}
ExprId randomcolor(Context& c, const NodeRef& n, std::string_view, Type) {
  // Hue, saturation and brightness each hashed with its own seed, ceil(seed + offset) with
  // MaterialX's offsets (413.3, 1522.4, 1813.8: the same colours as its graph), each taken into
  // its [low, high], then HSV to RGB.
  const ExprId seed = c.b.convert(in(c, n, "seed"), Type::Float);
  auto channel = [&](float offset, std::string_view low, std::string_view high) {
    const ExprId channelSeed = c.b.unary(Op::Ceil, c.b.add(seed, c.b.f(offset)));
    return c.b.lerp(in(c, n, low), in(c, n, high), randomHash(c, n, channelSeed, true));
  };
  const ExprId hue = channel(413.3f, "huelow", "huehigh");
  const ExprId saturation = channel(1522.4f, "saturationlow", "saturationhigh");
  const ExprId brightness = channel(1813.8f, "brightnesslow", "brightnesshigh");
  return c.material.exprs.op(Op::HsvToRgb, Type::Vec3, {c.b.construct(Type::Vec3, {hue, saturation, brightness})});
}
ExprId cellnoise3d(Context& c, const NodeRef& n, std::string_view, Type type) {
  return c.material.exprs.op(Op::CellNoise3D, type, {in(c, n, "position")});
}
ExprId worleynoise2d(Context& c, const NodeRef& n, std::string_view, Type type) {
  return c.material.exprs.op(Op::WorleyNoise2D, type, {in(c, n, "texcoord"), in(c, n, "jitter")});
}
ExprId worleynoise3d(Context& c, const NodeRef& n, std::string_view, Type type) {
  return c.material.exprs.op(Op::WorleyNoise3D, type, {in(c, n, "position"), in(c, n, "jitter")});
}

/// MaterialX "flake2d" / "flake3d": glitter flakes of side about `size` (the flake model is
/// mxc_flake in mxc_procedural.glsl), each with a normal drawn from GGX around `normal`.
///
/// Coverage to probability: in the Boolean model, a point is covered unless every cell whose
/// flake could cover it holds none. A flake covers V = (sqrt(3))^3 = 3 sqrt(3) cells' volume, so
/// on average V cells can cover a point, and taking that count as exactly V gives coverage
/// 1 - (1 - p)^V, hence p = 1 - (1 - coverage)^(1 / V). The count varies (2 to 9), so by
/// Jensen's inequality the true coverage is a little below the requested one; measured by Monte
/// Carlo over the model, by at most 0.02 (at coverage 0.8), and exactly 0 and 1 at the ends.
/// flake2d reads the plane z = 1/4 of the 3D model, where the mean number of cells that can
/// cover a point (5.22) is within 0.6% of the volume's mean: the plane z = 0, a cell face,
/// would have 7% more and cover more than asked.
///
/// The normal: the GGX distribution's inverse CDF in cos^2 theta (Walter et al. 2007, "Microfacet
/// Models for Refraction through Rough Surfaces", eq. 35), with alpha = roughness^2 as pbrlib's
/// roughness_anisotropy maps it, in the frame (tangent, bitangent, normal):
/// cos^2 theta = (1 - xi1) / ((1 - xi1) + alpha^2 xi1). The denominator is at least 1 - xi1 > 0
/// (xi1 < 1). Outputs where no flake is are the nodedef's defaults: id 0, rand 0, presence 0, the
/// normal unchanged. id is 1 + rand's 24-bit integer, so a flake's id is never 0.
ExprId flake(Context& c, const NodeRef& n, std::string_view output, Type, bool planar) {
  // A size is a length: below 1e-6 units the flakes are far below any pixel (and size 0 would divide by 0).
  const ExprId size = c.b.max(in(c, n, "size"), c.b.f(1e-6f));
  ExprId position;
  if (planar) {
    const ExprId uv = c.b.div(in(c, n, "texcoord"), size);
    position = c.b.construct(Type::Vec3, {c.b.extract(uv, 0), c.b.extract(uv, 1), c.b.f(0.25f)});
  } else {
    position = c.b.div(in(c, n, "position"), size);
  }
  const float volume = 3.0f * std::sqrt(3.0f);
  // pow of a base in [0, 1] to a positive exponent: defined everywhere, 0 at coverage 1.
  const ExprId uncovered = c.b.oneMinus(c.b.clamp01(in(c, n, "coverage")));
  const ExprId probability = c.b.oneMinus(c.b.pow(uncovered, c.b.f(1.0f / volume)));
  const ExprId seen = c.material.exprs.op(Op::Flake, Type::Vec4, {position, probability});
  const ExprId presence = c.b.extract(seen, 0);
  const ExprId present = c.b.greater(presence, c.b.f(0.0f));
  const ExprId rand = c.b.extract(seen, 1);
  if (output == "presence") return presence;
  if (output == "rand") return rand;
  if (output == "id") {
    const ExprId bits = c.b.construct(Type::Int, {c.b.mul(rand, c.b.f(16777216.0f))});
    return c.b.select(present, c.b.add(bits, c.material.exprs.constantInt(1)), c.material.exprs.constantInt(0));
  }
  const ExprId normal = in(c, n, "normal");
  const ExprId roughness = in(c, n, "roughness");
  const ExprId alpha = c.b.mul(roughness, roughness);
  const ExprId xi0 = c.b.extract(seen, 2);
  const ExprId xi1 = c.b.extract(seen, 3);
  const ExprId rest = c.b.oneMinus(xi1);
  const ExprId cos2 = c.b.div(rest, c.b.add(rest, c.b.mul(c.b.mul(alpha, alpha), xi1)));
  const ExprId cosTheta = c.b.sqrt(c.b.clamp01(cos2));
  const ExprId sinTheta = c.b.sqrt(c.b.clamp01(c.b.oneMinus(cos2)));  // clamped: rounding may leave cos2 above 1
  const ExprId phi = c.b.mul(xi0, c.b.f(6.28318531f));
  const ExprId along = c.b.add(c.b.mul(in(c, n, "tangent"), c.b.mul(c.b.unary(Op::Cos, phi), sinTheta)),
                               c.b.mul(in(c, n, "bitangent"), c.b.mul(c.b.unary(Op::Sin, phi), sinTheta)));
  // Normalised against a frame that is not orthonormal; a zero result falls back to the shading normal.
  const ExprId flakeNormal = c.b.normalize(c.b.add(along, c.b.mul(normal, cosTheta)));
  return c.b.select(present, flakeNormal, normal);
}
ExprId flake2d(Context& c, const NodeRef& n, std::string_view output, Type type) {
  return flake(c, n, output, type, true);
}
ExprId flake3d(Context& c, const NodeRef& n, std::string_view output, Type type) {
  return flake(c, n, output, type, false);
}

// --- Colour (MaterialX "Adjustment Nodes") ---

/// Applies a colour operation to the rgb of a color3 or color4 (alpha passes through).
template <typename F>
ExprId onRgb(Context& c, ExprId color, Type type, F f) {
  if (type != Type::Vec4) return f(color);
  ExprId rgb = c.b.convert(color, Type::Vec3);
  ExprId out = f(rgb);
  return c.b.construct(Type::Vec4, {out, c.b.extract(color, 3)});
}
ExprId luminance(Context& c, const NodeRef& n, std::string_view, Type type) {
  ExprId coefficients = in(c, n, "lumacoeffs");
  return onRgb(c, in(c, n, "in"), type, [&](ExprId rgb) {
    return c.b.splat(c.b.dot(rgb, coefficients), Type::Vec3);
  });
}
ExprId rgbtohsv(Context& c, const NodeRef& n, std::string_view, Type type) {
  return onRgb(c, in(c, n, "in"), type,
               [&](ExprId rgb) { return c.material.exprs.op(Op::RgbToHsv, Type::Vec3, {rgb}); });
}
ExprId hsvtorgb(Context& c, const NodeRef& n, std::string_view, Type type) {
  return onRgb(c, in(c, n, "in"), type,
               [&](ExprId hsv) { return c.material.exprs.op(Op::HsvToRgb, Type::Vec3, {hsv}); });
}
ExprId saturate(Context& c, const NodeRef& n, std::string_view, Type type) {
  // lerp(luminance, colour, amount): amount 0 is grey, 1 unchanged.
  ExprId coefficients = in(c, n, "lumacoeffs");
  ExprId amount = in(c, n, "amount");
  return onRgb(c, in(c, n, "in"), type, [&](ExprId rgb) {
    ExprId grey = c.b.splat(c.b.dot(rgb, coefficients), Type::Vec3);
    return c.b.lerp(grey, rgb, amount);
  });
}
ExprId hsvadjust(Context& c, const NodeRef& n, std::string_view, Type type) {
  // Hue shifts (wrapping), saturation and value scale: MaterialX "hsvadjust".
  ExprId amount = in(c, n, "amount");
  return onRgb(c, in(c, n, "in"), type, [&](ExprId rgb) {
    ExprId hsv = c.material.exprs.op(Op::RgbToHsv, Type::Vec3, {rgb});
    ExprId hue = c.b.add(c.b.extract(hsv, 0), c.b.extract(amount, 0));
    hue = c.b.sub(hue, c.b.unary(Op::Floor, hue));
    ExprId adjusted = c.b.construct(Type::Vec3, {hue, c.b.mul(c.b.extract(hsv, 1), c.b.extract(amount, 1)),
                                                c.b.mul(c.b.extract(hsv, 2), c.b.extract(amount, 2))});
    return c.material.exprs.op(Op::HsvToRgb, Type::Vec3, {adjusted});
  });
}
ExprId contrast(Context& c, const NodeRef& n, std::string_view, Type) {
  // (in - pivot) * amount + pivot
  ExprId pivot = in(c, n, "pivot");
  return c.b.add(c.b.mul(c.b.sub(in(c, n, "in"), pivot), in(c, n, "amount")), pivot);
}

// --- Transforms ---

ExprId rotate2d(Context& c, const NodeRef& n, std::string_view, Type) {
  return c.material.exprs.op(Op::Rotate2D, Type::Vec2, {in(c, n, "in"), in(c, n, "amount")});
}
ExprId rotate3d(Context& c, const NodeRef& n, std::string_view, Type) {
  return c.material.exprs.op(Op::Rotate3D, Type::Vec3, {in(c, n, "in"), in(c, n, "amount"), in(c, n, "axis")});
}
template <Op op>
ExprId transform(Context& c, const NodeRef& n, std::string_view, Type type) {
  return c.material.exprs.opWithString(op, type, {in(c, n, "in")},
                                       fmt::format("{},{}", c.stringInput(n, "fromspace"), c.stringInput(n, "tospace")));
}
ExprId transformmatrix(Context& c, const NodeRef& n, std::string_view, Type type) {
  // A vector (padded with w = 1 for the homogeneous 2D/3D forms) times the matrix.
  ExprId v = in(c, n, "in");
  ExprId m = in(c, n, "mat");
  const int vn = ir::componentCount(c.b.type(v));
  const int mn = c.b.type(m) == Type::Mat3 ? 3 : 4;
  ExprId padded = vn == mn ? v : c.b.construct(ir::vectorType(mn), {v, c.b.f(1.0f)});
  ExprId product = c.material.exprs.op(Op::MatMul, ir::vectorType(mn), {padded, m});
  return ir::componentCount(type) == mn ? product : c.b.convert(product, type);
}

// --- pbrlib value nodes ---

ExprId roughnessAnisotropy(Context& c, const NodeRef& n, std::string_view, Type) {
  return burleyAlpha(c.b, in(c, n, "roughness"), in(c, n, "anisotropy"));
}
ExprId roughnessDual(Context& c, const NodeRef& n, std::string_view, Type) {
  // Two roughnesses squared to alphas (MaterialX "roughness_dual"), clamped to [1e-7, 1] as above.
  ExprId r = in(c, n, "roughness");
  return c.b.clamp(c.b.mul(r, r), c.b.f(1e-7f), c.b.f(1.0f));
}
ExprId glossinessAnisotropy(Context& c, const NodeRef& n, std::string_view, Type) {
  // roughness = 1 - glossiness, then as roughness_anisotropy.
  return burleyAlpha(c.b, c.b.oneMinus(in(c, n, "glossiness")), in(c, n, "anisotropy"));
}
ExprId artisticIor(Context& c, const NodeRef& n, std::string_view output, Type) {
  auto [ior, extinction] = gulbrandsenIor(c.b, in(c, n, "reflectivity"), in(c, n, "edge_color"));
  return output == "extinction" ? extinction : ior;
}

ExprId blackbody(Context& c, const NodeRef& n, std::string_view, Type) {
  // The colour of a black body at T kelvin: the CIE 1931 chromaticity of the Planckian locus by
  // Kang et al. 2002 (cubic splines: x in 1/T, y in x; the paper's range 1667-25000 K, taken
  // down to 800 K, near the Draper point where visible emission starts), at luminance Y = 1,
  // then XYZ to linear Rec.709 (IEC 61966-2-1's matrix), negative components dropped; then to
  // the working space. T is clamped to [800, 25000], so 1000 / T is finite; over that range
  // y >= 0.3, and the divisions by y are guarded at 1e-3 all the same.
  ir::ExprBuilder& b = c.b;
  const ExprId kelvin = b.clamp(in(c, n, "temperature"), b.f(800.0f), b.f(25000.0f));
  const ExprId t = b.div(b.f(1000.0f), kelvin);
  auto cubic = [&](ExprId v, float c0, float c1, float c2, float c3) {
    return b.add(b.mul(b.add(b.mul(b.add(b.mul(b.f(c3), v), b.f(c2)), v), b.f(c1)), v), b.f(c0));  // Horner
  };
  const ExprId below4000 = b.greater(b.f(4000.0f), kelvin);
  const ExprId x = b.select(below4000, cubic(t, 0.179910f, 0.8776956f, -0.2343589f, -0.2661239f),
                            cubic(t, 0.240390f, 0.2226347f, 2.1070379f, -3.0258469f));
  const ExprId y = b.select(b.greater(b.f(2222.0f), kelvin), cubic(x, -0.20219683f, 2.18555832f, -1.34811020f, -1.1063814f),
                            b.select(below4000, cubic(x, -0.16748867f, 2.09137015f, -1.37418593f, -0.9549476f),
                                     cubic(x, -0.37001483f, 3.75112997f, -5.87338670f, 3.0817580f)));
  const ExprId safeY = b.max(y, b.f(1e-3f));
  const ExprId xyz = b.construct(Type::Vec3, {b.div(x, safeY), b.f(1.0f), b.div(b.sub(b.oneMinus(x), y), safeY)});
  auto row = [&](float r0, float r1, float r2) {
    return b.dot(xyz, c.material.exprs.constantVector(Type::Vec3, {r0, r1, r2}));
  };
  const ExprId rgb = b.nonNegative(b.construct(Type::Vec3, {row(3.2406f, -1.5372f, -0.4986f), row(-0.9689f, 1.8758f, 0.0415f),
                                                            row(0.0557f, -0.2040f, 1.0570f)}));
  return c.toWorkingSpace(rgb, "lin_rec709", c.nodeOrigin(n).location);
}

// pbrlib's hair helpers, for chiang_hair_bsdf.
ExprId deonHairAbsorption(Context& c, const NodeRef& n, std::string_view, Type) {
  // d'Eon et al. 2011 s. 6.1: melanin = -ln(1 - concentration) (1e-4: all melanin is a finite
  // 9.2), split into eumelanin and pheomelanin by the redness; each absorbs -ln(colour) per
  // unit, the colours being exp(-sigma) of the paper's coefficients. Colours >= 1e-4 keep the
  // logarithms finite (a black pigment absorbs 9.2 per unit).
  ir::ExprBuilder& b = c.b;
  const ExprId melanin = b.neg(b.ln(b.max(b.oneMinus(in(c, n, "melanin_concentration")), b.f(1e-4f))));
  const ExprId redness = in(c, n, "melanin_redness");
  const ExprId eu = b.mul(melanin, b.oneMinus(redness));
  const ExprId pheo = b.mul(melanin, redness);
  auto perUnit = [&](std::string_view input) { return b.neg(b.ln(b.max(in(c, n, input), b.vec(Type::Vec3, 1e-4f)))); };
  return b.nonNegative(b.add(b.mul(perUnit("eumelanin_color"), eu), b.mul(perUnit("pheomelanin_color"), pheo)));
}
ExprId chiangHairAbsorption(Context& c, const NodeRef& n, std::string_view, Type) {
  // Chiang et al. 2016 eq. 9: sigma_a = (ln(colour) / (5.969 - 0.215 b + 2.532 b^2 - 10.73 b^3 +
  // 5.574 b^4 + 0.245 b^5))^2 for the azimuthal roughness b, clamped to [0, 1] where the
  // polynomial stays >= 3.3; the colour in [1e-3, 1] keeps the logarithm finite and <= 0.
  ir::ExprBuilder& b = c.b;
  const ExprId beta = b.clamp01(in(c, n, "azimuthal_roughness"));
  const float k[] = {5.969f, -0.215f, 2.532f, -10.73f, 5.574f, 0.245f};
  ExprId poly = b.f(k[5]);
  for (int i = 4; i >= 0; --i) poly = b.add(b.mul(poly, beta), b.f(k[i]));  // Horner
  const ExprId sigma = b.div(b.ln(b.clamp(in(c, n, "color"), b.f(1e-3f), b.f(1.0f))), poly);
  return b.mul(sigma, sigma);
}
ExprId chiangHairRoughness(Context& c, const NodeRef& n, std::string_view output, Type) {
  // Chiang et al. 2016 eqs. 7-8: the longitudinal variance v = (0.726 b_m + 0.812 b_m^2 +
  // 3.7 b_m^20)^2 and the azimuthal scale s = 0.265 b_n + 1.194 b_n^2 + 5.372 b_n^22 (its
  // sqrt(pi/8) is applied by the BSDF, as MaterialX splits it), both roughnesses clamped to
  // [1e-3, 1]. TT and TRT scale the longitudinal width (Marschner et al. 2003: 1/2 and 2).
  ir::ExprBuilder& b = c.b;
  const ExprId lr = b.clamp(in(c, n, "longitudinal"), b.f(1e-3f), b.f(1.0f));
  const ExprId ar = b.clamp(in(c, n, "azimuthal"), b.f(1e-3f), b.f(1.0f));
  ExprId v = b.add(b.add(b.mul(b.f(0.726f), lr), b.mul(b.f(0.812f), b.mul(lr, lr))), b.mul(b.f(3.7f), b.pow(lr, b.f(20.0f))));
  v = b.mul(v, v);
  const ExprId s = b.add(b.add(b.mul(b.f(0.265f), ar), b.mul(b.f(1.194f), b.mul(ar, ar))), b.mul(b.f(5.372f), b.pow(ar, b.f(22.0f))));
  ExprId scale = b.f(1.0f);
  if (output == "roughness_TT") scale = in(c, n, "scale_TT");
  if (output == "roughness_TRT") scale = in(c, n, "scale_TRT");
  return b.construct(Type::Vec2, {b.mul(v, b.mul(scale, scale)), s});
}

using RuleTable = std::unordered_map<std::string_view, ValueRule>;

const RuleTable& rules() {
  static const RuleTable table = {
      {"add", add},
      {"subtract", subtract},
      {"multiply", multiply},
      {"divide", divide},
      {"modulo", modulo},
      {"power", power},
      {"safepower", safepower},
      {"min", minimum},
      {"max", maximum},
      {"atan2", atan2},
      {"absval", unaryRule<Op::Abs>},
      {"floor", unaryRule<Op::Floor>},
      {"ceil", unaryRule<Op::Ceil>},
      {"round", unaryRule<Op::Round>},
      {"sign", unaryRule<Op::Sign>},
      {"sqrt", unaryRule<Op::Sqrt>},
      {"exp", unaryRule<Op::Exp>},
      {"ln", unaryRule<Op::Ln>},
      {"sin", unaryRule<Op::Sin>},
      {"cos", unaryRule<Op::Cos>},
      {"tan", unaryRule<Op::Tan>},
      {"asin", unaryRule<Op::Asin>},
      {"acos", unaryRule<Op::Acos>},
      {"fract", fract},
      {"magnitude", magnitude},
      {"distance", distance},
      {"dotproduct", dotproduct},
      {"crossproduct", crossproduct},
      {"reflect", reflect},
      {"invert", invert},
      {"clamp", clamp},
      {"mix", mix},
      {"remap", remap},
      {"range", range},
      {"smoothstep", smoothstep},
      {"normalize", normalize},
      {"mincomponent", mincomponent},
      {"maxcomponent", maxcomponent},
      {"ifgreater", conditional<Op::Greater>},
      {"ifgreatereq", conditional<Op::GreaterEq>},
      {"ifequal", conditional<Op::Equal>},
      {"switch", switchRule},
      {"and", logicAnd},
      {"or", logicOr},
      {"not", logicNot},
      {"xor", logicXor},
      {"constant", constant},
      {"dot", identity},
      {"convert", convert},
      {"combine2", combine},
      {"combine3", combine},
      {"combine4", combine},
      {"separate2", separate},
      {"separate3", separate},
      {"separate4", separate},
      {"extract", extract},
      {"position", position},
      {"viewdirection", viewdirection},
      {"facingratio", facingratio},
      {"gooch_shade", goochShade},
      {"normal", normal},
      {"tangent", tangent},
      {"bitangent", bitangent},
      {"texcoord", texcoord},
      {"geomcolor", geomcolor},
      {"geompropvalue", geompropvalue},
      {"geompropvalueuniform", geompropvalue},
      {"frame", frame},
      {"time", time},
      {"image", image},
      {"tiledimage", tiledimage},
      {"hextiledimage", hextiledimage},
      {"place2d", place2d},
      {"normalmap", normalmap},
      {"UsdUVTexture", usdUvTexture},
      {"UsdPrimvarReader", usdPrimvarReader},
      {"UsdTransform2d", usdTransform2d},
      {"gltf_image", gltfImage},
      {"gltf_colorimage", gltfColorImage},
      {"gltf_normalmap", gltfNormalmap},
      {"gltf_iridescence_thickness", gltfIridescenceThickness},
      {"gltf_anisotropy_image", gltfAnisotropyImage},
      {"heighttonormal", heighttonormal},
      {"ramp4", ramp4},
      {"line", line},
      {"trianglewave", trianglewave},
      {"circle", circle},
      {"cloverleaf", cloverleaf},
      {"tiledcloverleafs", tiledcloverleafs},
      {"checkerboard", checkerboard},
      {"grid", grid},
      {"crosshatch", crosshatch},
      {"tiledcircles", tiledcircles},
      {"bump", bump},
      {"noise2d", noise2d},
      {"noise3d", noise3d},
      {"fractal3d", fractal3d},
      {"cellnoise2d", cellnoise2d},
      {"cellnoise3d", cellnoise3d},
      {"randomfloat", randomfloat},
      {"randomcolor", randomcolor},
      {"worleynoise2d", worleynoise2d},
      {"worleynoise3d", worleynoise3d},
      {"flake2d", flake2d},
      {"flake3d", flake3d},
      {"luminance", luminance},
      {"rgbtohsv", rgbtohsv},
      {"hsvtorgb", hsvtorgb},
      {"saturate", saturate},
      {"hsvadjust", hsvadjust},
      {"contrast", contrast},
      {"rotate2d", rotate2d},
      {"rotate3d", rotate3d},
      {"transformpoint", transform<Op::TransformPoint>},
      {"transformvector", transform<Op::TransformVector>},
      {"transformnormal", transform<Op::TransformNormal>},
      {"transformmatrix", transformmatrix},
      {"roughness_anisotropy", roughnessAnisotropy},
      {"roughness_dual", roughnessDual},
      {"glossiness_anisotropy", glossinessAnisotropy},
      {"artistic_ior", artisticIor},
      {"blackbody", blackbody},
      {"deon_hair_absorption_from_melanin", deonHairAbsorption},
      {"chiang_hair_absorption_from_color", chiangHairAbsorption},
      {"chiang_hair_roughness", chiangHairRoughness},
  };
  return table;
}

}  // namespace

ValueRule findValueRule(std::string_view category) {
  auto it = rules().find(category);
  return it == rules().end() ? nullptr : it->second;
}

}  // namespace mxc::lower
