// The interface JSON a host renderer reads (compiler/glsl/ShaderInterface.cpp) describes the
// shader glslang compiled: every block, member offset, sampler and vertex input it states is the
// one the SPIR-V has, by glslang's own reflection of the module.

#include <gtest/gtest.h>

#include <string>

#include "compiler/glsl/ShaderInterface.h"
#include "support/MaterialSupport.h"

namespace mxc::test {
namespace {

using nlohmann::json;

const json* named(const json& interface, const std::string& name) {
  for (const json& d : interface["descriptors"]) {
    if (d["name"] == name) return &d;
  }
  return nullptr;
}

const json* descriptor(const json& interface, int set, int binding) {
  for (const json& d : interface["descriptors"]) {
    if (d["set"] == set && d["binding"] == binding) return &d;
  }
  return nullptr;
}

/// The last part of a reflected member name ("MxcView.worldToClip" or "worldToClip", "lightVector[0]").
std::string memberName(std::string name) {
  if (const size_t dot = name.rfind('.'); dot != std::string::npos) name = name.substr(dot + 1);
  if (const size_t bracket = name.find('['); bracket != std::string::npos) name = name.substr(0, bracket);
  return name;
}

TEST(ShaderInterface, DescribesTheModuleGlslangCompiled) {
  // Parameters kept variable (a colour, a float), a texture, a procedural: a busy interface.
  lower::LoweringOptions options;
  options.parameters = {"base", "specular"};  // (the brick's colour and roughness come from its graph)
  Context context;
  std::vector<ir::Material> materials = lowerFile(
      context, sharedDir() / "corpus/materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx", options);
  ASSERT_EQ(materials.size(), 1u) << context.diagnostics.format();
  const glsl::MaterialShader shader = buildShader(materials[0], glsl::ShaderKind::Raster);
  spirv::Reflection reflection;
  Diagnostics diagnostics;
  auto words = spirv::compile(shader.glsl, {.optimize = false, .reflection = &reflection, .specialization = {}}, diagnostics);
  ASSERT_TRUE(words) << diagnostics.format();
  const json interface = glsl::shaderInterfaceJson(materials[0], shader, glsl::ShaderKind::Raster,
                                                   {"brick.spv", "brick.vert.spv", "tables/mxc_albedo_tables.bin", "/docs"});
  EXPECT_EQ(interface["schema"], "mxc-shader-interface-1");

  ASSERT_FALSE(reflection.blocks.empty());
  for (size_t b = 0; b < reflection.blocks.size(); ++b) {
    const spirv::Reflection::Block& block = reflection.blocks[b];
    const json* d = named(interface, block.name);
    ASSERT_NE(d, nullptr) << block.name << " is not described";
    EXPECT_EQ((*d)["binding"].get<int>(), block.binding) << block.name;
    // std140 sizes: reflection's ends at the last member, the described size (what the host
    // allocates) rounds that up to 16 bytes; a runtime array has no size.
    if (d->contains("size")) {
      EXPECT_GE((*d)["size"].get<int>(), block.size) << block.name;
      EXPECT_LT((*d)["size"].get<int>(), block.size + 16) << block.name;
    }
    for (const spirv::Reflection::Member& m : reflection.members) {
      if (m.block != static_cast<int>(b)) continue;
      const std::string name = memberName(m.name);
      bool found = false;
      for (const json& member : (*d)["members"]) {
        if (member["name"] != name) continue;
        found = true;
        // An array's reflected member is its first element: the member's own offset.
        EXPECT_EQ(member["offset"].get<int>(), m.offset) << block.name << "." << name;
      }
      EXPECT_TRUE(found) << block.name << "." << name << " is not described";
    }
  }
  // The kept inputs are members, with the document input they come from.
  const json* parameters = descriptor(interface, 0, glsl::kParameterBinding);
  ASSERT_NE(parameters, nullptr);
  int inputs = 0;
  for (const json& member : (*parameters)["members"]) {
    if (!member.contains("input")) continue;
    ++inputs;
    EXPECT_EQ(member["name"], "p_" + member["input"].get<std::string>());
  }
  EXPECT_EQ(inputs, 2);
  // Every sampler of the module is a described combined image sampler.
  ASSERT_FALSE(reflection.samplers.empty());
  for (const spirv::Reflection::Sampler& s : reflection.samplers) {
    const json* d = descriptor(interface, s.binding == glsl::kEnvironmentRadianceBinding && s.name == "mxc_env_radiance"
                                              ? int(glsl::kEnvironmentSet)
                                              : 0,
                               s.binding);
    ASSERT_NE(d, nullptr) << s.name;
    EXPECT_EQ((*d)["type"], "combined_image_sampler") << s.name;
    EXPECT_EQ((*d)["name"], s.name);
  }
  // Each texture names its file, as the document does, and how the shader addresses it.
  int textures = 0;
  for (const json& d : interface["descriptors"]) {
    if (!d.contains("file")) continue;
    ++textures;
    EXPECT_FALSE(d["sampling"].empty()) << d["file"];
    EXPECT_EQ(d["sampling"][0]["uaddress"], "periodic") << "the brick's tiledimage repeats";
  }
  EXPECT_EQ(textures, int(shader.interface.textures.size()));
  EXPECT_GT(textures, 0);

  // The vertex stage's inputs are the ones described.
  spirv::Reflection vertex;
  auto vertexWords = spirv::compile(glsl::buildVertexShader(), {.optimize = false, .reflection = &vertex, .specialization = {}},
                                    diagnostics);
  ASSERT_TRUE(vertexWords) << diagnostics.format();
  ASSERT_EQ(vertex.inputs.size(), interface["vertexInputs"].size());
  for (const spirv::Reflection::Input& in : vertex.inputs) {
    bool found = false;
    for (const json& described : interface["vertexInputs"]) {
      if (described["name"] != in.name) continue;
      found = true;
      EXPECT_EQ(described["location"].get<int>(), in.location) << in.name;
    }
    EXPECT_TRUE(found) << in.name;
  }
}

}  // namespace
}  // namespace mxc::test
