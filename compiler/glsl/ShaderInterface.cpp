#include "compiler/glsl/ShaderInterface.h"

#include <fmt/format.h>

#include "compiler/common/ColorSpace.h"
#include "compiler/glsl/AlbedoTableFile.h"
#include "compiler/glsl/Contract.h"
#include "compiler/glsl/ExprEmitter.h"

namespace mxc::glsl {

namespace {

using nlohmann::json;

/// A std140 block of the contract (MxcView, MxcBatch): each member with its offset.
json blockMembers(std::span<const Member> members) {
  const Std140Layout layout = std140Layout(members);
  json out = json::array();
  for (size_t i = 0; i < members.size(); ++i) {
    const Member& m = members[i];
    json member{{"name", m.name}, {"type", m.type}, {"offset", layout.offsets[i]}};
    if (m.count > 0) member["count"] = m.count;
    if (!m.comment.empty()) member["meaning"] = m.comment;
    out.push_back(std::move(member));
  }
  return out;
}

uint32_t blockSize(std::span<const Member> members) { return std140Layout(members).size; }

/// How the shader addresses and filters a texture: from the image samples of the IR that read
/// it (the shader applies them itself; several samples may read one file differently).
json textureSampling(const ir::Material& material, const TextureBinding& binding) {
  json uses = json::array();
  for (ir::ExprId id = 0; id < material.exprs.size(); ++id) {
    if (material.exprs[id].op != ir::Op::ImageSample) continue;
    if (material.exprs.text(material.exprs.arg(id, 0)) != binding.path) continue;
    const ImageSampling sampling = imageSampling(material.exprs.text(id));
    if (sampling.colorspace != binding.colorspace) continue;
    json use{{"uaddress", addressModeName(sampling.uaddress)},
             {"vaddress", addressModeName(sampling.vaddress)},
             {"filter", sampling.filter == FilterMode::Closest ? "closest" : "linear"}};
    if (std::find(uses.begin(), uses.end(), use) == uses.end()) uses.push_back(std::move(use));
  }
  return uses;
}

}  // namespace

std::string albedoTablesFile() { return encodeAlbedoTables(committedAlbedoTables()); }

json shaderInterfaceJson(const ir::Material& material, const MaterialShader& shader, ShaderKind kind,
                         const InterfaceFiles& files) {
  const MaterialInterface& iface = shader.interface;
  const bool raster = kind == ShaderKind::Raster;
  json out{{"schema", "mxc-shader-interface-1"},
           {"material", material.name},
           {"shadingModel", material.shader},
           {"kind", std::string(shaderKindName(kind))},
           {"documentFolder", files.documentFolder},
           {"stages", json::object()}};
  out["stages"][raster ? "fragment" : "compute"] = {{"file", files.shader}, {"spirv", files.shader}, {"entryPoint", "main"}};
  if (raster) out["stages"]["vertex"] = {{"file", files.vertex}, {"spirv", files.vertex}, {"entryPoint", "main"}};

  if (raster) {
    out["vertexInputs"] = json::array({
        {{"location", uint32_t(kAttributePosition)}, {"name", "inPosition"}, {"type", "vec3"}, {"format", "R32G32B32_SFLOAT"},
         {"meaning", "object-space position"}},
        {{"location", uint32_t(kAttributeNormal)}, {"name", "inNormal"}, {"type", "vec3"}, {"format", "R32G32B32_SFLOAT"},
         {"meaning", "object-space normal"}},
        {{"location", uint32_t(kAttributeTangent)}, {"name", "inTangent"}, {"type", "vec4"},
         {"format", "R32G32B32A32_SFLOAT"},
         {"meaning", "xyz: object-space tangent (along +u); w: the bitangent's handedness, +1 or -1 (B = w cross(N, T))"}},
        {{"location", uint32_t(kAttributeUv)}, {"name", "inUv"}, {"type", "vec2"}, {"format", "R32G32_SFLOAT"},
         {"meaning", "texture coordinates (UV0)"}},
    });
    out["fragmentOutputs"] = json::array({{{"location", 0},
                                           {"name", "outColor"},
                                           {"type", "vec4"},
                                           {"format", "R32G32B32A32_SFLOAT"},
                                           {"meaning",
                                            "rgb: this frame's estimate of the radiance towards the camera (lights exact, "
                                            "the environment one Monte Carlo sample per pixel); a: coverage. Frames "
                                            "accumulate by additive blending (ONE, ONE); the image is the sum divided by "
                                            "the number of frames"}}});
  }

  json descriptors = json::array();
  descriptors.push_back({{"set", 0},
                         {"binding", uint32_t(kTablesBinding)},
                         {"type", "combined_image_sampler"},
                         {"name", "mxc_tables"},
                         {"meaning", "the albedo tables (directional albedo of the GGX lobes, split-sum and sheen), "
                                     "read by the energy compensation of the balanced and reference tiers"},
                         {"image", {{"width", kTableSize}, {"height", kTableHeight}, {"format", "R32G32B32A32_SFLOAT"},
                                    {"file", files.tables}}},
                         {"sampler", {{"filter", "linear"}, {"mipmap", "none"}, {"address", "clamp_to_edge"}}}});
  const std::span<const Member> stageMembers = raster ? viewMembers() : batchMembers();
  descriptors.push_back({{"set", 0},
                         {"binding", uint32_t(kStageBinding)},
                         {"type", "uniform_buffer"},
                         {"name", raster ? "MxcView" : "MxcBatch"},
                         {"layout", "std140"},
                         {"size", blockSize(stageMembers)},
                         {"members", blockMembers(stageMembers)}});
  // The material's parameters: the built-in three, then each input kept variable (--param,
  // --param-all, --no-specialize) with the document input it comes from.
  json parameters = json::array();
  for (const UniformField& f : iface.parameters) {
    json member{{"name", f.name},
                {"type", parameterType(f)},
                {"offset", f.offset},
                {"default", f.value}};
    if (isMissingTexturesMember(f.name)) {
      // missing_textures_32 holds textures 32 + k: its first texture is its name's suffix.
      const std::string first = f.name == "missing_textures" ? "" : f.name.substr(f.name.rfind('_') + 1) + " + ";
      member["meaning"] = "bit k set: texture " + first + "k could not be read, the image node's default is used";
    }
    if (f.name == "frame") member["meaning"] = "the frame index, from 1 (MaterialX's frame geometric property)";
    if (f.name == "time") member["meaning"] = "seconds (MaterialX's time geometric property)";
    for (const ir::Parameter& p : material.parameters) {
      if (p.name != f.name) continue;
      member["input"] = std::string(p.origin.input);
      if (!p.graph.empty()) member["graph"] = p.graph;
      if (p.origin.location.valid()) member["source"] = p.origin.location.str();
    }
    parameters.push_back(std::move(member));
  }
  descriptors.push_back({{"set", 0},
                         {"binding", uint32_t(kParameterBinding)},
                         {"type", "storage_buffer"},
                         {"name", "MxcParameters"},
                         {"layout", "std140"},
                         {"readonly", true},
                         {"size", iface.parameterBytes},
                         {"members", std::move(parameters)}});
  if (!raster) {
    descriptors.push_back({{"set", 0}, {"binding", uint32_t(kInputBinding)}, {"type", "storage_buffer"},
                           {"name", "MxcInput"}, {"layout", "std430"}, {"readonly", true}, {"meaning", "vec4 per item, read"},
                           {"members", json::array({{{"name", "mxc_in"}, {"type", "vec4"}, {"offset", 0}, {"count", "runtime"}}})}});
    descriptors.push_back({{"set", 0}, {"binding", uint32_t(kOutputBinding)}, {"type", "storage_buffer"},
                           {"name", "MxcOutput"}, {"layout", "std430"}, {"readonly", false}, {"meaning", "vec4 per item, written"},
                           {"members", json::array({{{"name", "mxc_out"}, {"type", "vec4"}, {"offset", 0}, {"count", "runtime"}}})}});
  }
  for (size_t k = 0; k < iface.textures.size(); ++k) {
    const TextureBinding& t = iface.textures[k];
    const bool decode = deviceDecodes(t.colorspace);
    json texture{{"set", 0},
                 {"binding", t.binding},
                 {"type", "combined_image_sampler"},
                 {"name", t.name},
                 {"file", t.path},
                 {"missingMember", missingTexturesMember(k)},
                 {"missingBit", k % 32},
                 {"colorspace", t.colorspace},
                 {"decode", decode ? "srgb" : "none"},
                 {"image",
                  {{"format", decode ? "R8G8B8A8_SRGB (8-bit files) or R32G32B32A32_SFLOAT decoded on the host"
                                     : "R8G8B8A8_UNORM (8-bit files) or R32G32B32A32_SFLOAT"},
                   {"mipmaps", "full chain"}}},
                 {"sampler", {{"filter", "linear"}, {"mipmap", "linear"}, {"address", "clamp_to_edge"}}},
                 {"sampling", textureSampling(material, t)}};
    if (t.origin.valid()) texture["source"] = t.origin.str();
    descriptors.push_back(std::move(texture));
  }
  if (raster) {
    descriptors.push_back({{"set", kEnvironmentSet},
                           {"binding", kEnvironmentRadianceBinding},
                           {"type", "combined_image_sampler"},
                           {"name", "mxc_env_radiance"},
                           {"meaning", "the environment image, equirectangular radiance (bound when MXC_ENVIRONMENT is "
                                       "3, or when it is read from MxcView.counts.y)"},
                           {"image", {{"format", "R32G32B32A32_SFLOAT"}}},
                           {"sampler", {{"filter", "linear"}, {"uaddress", "repeat"}, {"vaddress", "clamp_to_edge"}}}});
    descriptors.push_back({{"set", kEnvironmentSet},
                           {"binding", kEnvironmentDistributionBinding},
                           {"type", "storage_buffer"},
                           {"name", "MxcEnvDistribution"},
                           {"layout", "std430"},
                           {"readonly", true},
                           {"members", json::array({{{"name", "mxc_env_size"}, {"type", "uvec4"}, {"offset", 0}},
                                                    {{"name", "mxc_env_cells"}, {"type", "vec4"}, {"offset", 16},
                                                     {"count", "runtime"}}})},
                           {"meaning", "uvec4 size (cells across and down), then per cell vec4 (keep probability, alias "
                                       "as uint bits, pdf per steradian): the image's sampling distribution "
                                       "(runtime/EnvironmentDistribution.h)"}});
  }
  out["descriptors"] = std::move(descriptors);
  out["pushConstants"] = json::array();
  if (raster) {
    out["specializationConstants"] = json::array({
        {{"id", kEnvironmentConstantId}, {"name", "MXC_ENVIRONMENT"}, {"type", "int"}, {"default", kFromView},
         {"values", {{"-1", "read MxcView.counts.y"}, {"0", "none"}, {"1", "white"}, {"2", "sky"}, {"3", "image"}}}},
        {{"id", kLightCountConstantId}, {"name", "MXC_LIGHT_COUNT"}, {"type", "int"}, {"default", kFromView},
         {"values", {{"-1", "read MxcView.counts.x"}, {"0 to 8", "the number of lights"}}}},
        {{"id", kLightKindsConstantId}, {"name", "MXC_LIGHT_KINDS"}, {"type", "int"}, {"default", kFromView},
         {"values", {{"-1", "every kind"}, {"bits", "1 << 0 directional, 1 << 1 point, 1 << 2 spot"}}}},
    });
  } else {
    out["specializationConstants"] = json::array();
    out["workGroupSize"] = {kWorkGroupSize, 1, 1};
  }
  out["tables"] = json::array({{{"name", "albedo"},
                                {"binding", uint32_t(kTablesBinding)},
                                {"file", files.tables},
                                {"format", "MXCTAB01: 8 bytes 'MXCTAB01', uint32 width, height, channels (4), uint64 "
                                           "hash, then width x height RGBA float32 texels, row by row, little-endian"},
                                {"width", kTableSize},
                                {"height", kTableHeight}}});
  // Parameters are read through subgroupBroadcastFirst (MXC_PARAMETER, mxc_codes.glsl) in the
  // SPIR-V target's shaders.
  out["requires"] = json::array();
  if (iface.subgroups) {
    out["requires"].push_back("Vulkan 1.1 subgroups with the ballot operations (VK_SUBGROUP_FEATURE_BALLOT_BIT) in "
                              "the shader's stage");
  }
  out["lobes"] = iface.lobes;
  return out;
}

}  // namespace mxc::glsl
