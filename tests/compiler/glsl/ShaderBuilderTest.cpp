// The GLSL backend (compiler/glsl): only what the IR keeps is emitted, --param inputs become
// uniforms, textures become bindings, and generated lines map back to the document.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "support/MaterialSupport.h"

namespace mxc::test {
namespace {

std::string openPbr(const std::string& inputs = "") {
  return mtlx("  <open_pbr_surface name=\"s\" type=\"surfaceshader\">\n" + inputs +
              "  </open_pbr_surface>\n  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" "
              "type=\"surfaceshader\" nodename=\"s\" /></surfacematerial>\n");
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

glsl::MaterialShader shaderOf(const std::string& text, const lower::LoweringOptions& options = {}) {
  Context context;
  std::vector<ir::Material> materials = lowerText(context, text, options);
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  if (materials.size() != 1) {
    ADD_FAILURE() << "expected one material";
    return {};
  }
  return buildShader(materials[0], glsl::ShaderKind::Raster);
}

TEST(ShaderBuilder, CoatCodeOnlyWhenTheMaterialHasACoat) {
  glsl::MaterialShader plain = shaderOf(openPbr());
  glsl::MaterialShader coated = shaderOf(openPbr("    <input name=\"coat_weight\" type=\"float\" value=\"1\" />\n"));
  EXPECT_EQ(plain.interface.lobes, 2);  // specular and diffuse
  EXPECT_EQ(coated.interface.lobes, 3);
  EXPECT_EQ(count(plain.glsl.text, "= MXC_LOBE_DIELECTRIC;"), 1u);
  EXPECT_EQ(count(coated.glsl.text, "= MXC_LOBE_DIELECTRIC;"), 2u);
  // coat_weight = 0 given explicitly folds away the same way.
  glsl::MaterialShader zero = shaderOf(openPbr("    <input name=\"coat_weight\" type=\"float\" value=\"0\" />\n"));
  EXPECT_EQ(zero.glsl.text, plain.glsl.text);
}

TEST(ShaderBuilder, ThinFilmAndLobeKindsCompiledOnlyWhenUsed) {
  glsl::MaterialShader plain = shaderOf(openPbr());
  EXPECT_EQ(count(plain.glsl.text, "#define MXC_THIN_FILM"), 0u);
  EXPECT_EQ(count(plain.glsl.text, "#define MXC_HAS_SHEEN"), 0u);
  EXPECT_EQ(count(plain.glsl.text, "#define MXC_HAS_EON"), 1u);
  glsl::MaterialShader film = shaderOf(openPbr("    <input name=\"thin_film_weight\" type=\"float\" value=\"1\" />\n"
                                               "    <input name=\"thin_film_thickness\" type=\"float\" value=\"0.5\" />\n"
                                               "    <input name=\"fuzz_weight\" type=\"float\" value=\"1\" />\n"));
  EXPECT_EQ(count(film.glsl.text, "#define MXC_THIN_FILM"), 1u);
  // OpenPBR fuzz is Zeltner's LTC lobe, not the Estevez-Kulla sheen; its library file comes only
  // with it.
  EXPECT_EQ(count(film.glsl.text, "#define MXC_HAS_SHEEN"), 0u);
  EXPECT_EQ(count(film.glsl.text, "#define MXC_HAS_FUZZ"), 1u);
  EXPECT_EQ(count(film.glsl.text, "float mxc_fuzz_albedo("), 1u);
  EXPECT_EQ(count(plain.glsl.text, "float mxc_fuzz_albedo("), 0u);
  // Procedural library code only for procedural nodes.
  EXPECT_EQ(count(plain.glsl.text, "mxc_noise_float("), 0u);
}

TEST(ShaderBuilder, ParamInputsBecomeUniformsWithTheirDefault) {
  lower::LoweringOptions options;
  options.parameters = {"base_color", "coat_weight"};
  glsl::MaterialShader shader = shaderOf(openPbr("    <input name=\"base_color\" type=\"color3\" value=\"0.3, 0.5, 0.7\" />\n"),
                                         options);
  EXPECT_EQ(count(shader.glsl.text, "vec3 p_base_color;"), 1u);
  EXPECT_GE(count(shader.glsl.text, "mxc_params.p_base_color"), 1u);
  EXPECT_EQ(count(shader.glsl.text, "0.3, 0.5, 0.7"), 0u) << "the value must not be folded into the code";
  // A coat weight that may change keeps the coat's code.
  EXPECT_EQ(shader.interface.lobes, 3);
  const glsl::UniformField* color = nullptr;
  for (const glsl::UniformField& f : shader.interface.parameters) color = f.name == "p_base_color" ? &f : color;
  ASSERT_NE(color, nullptr);
  EXPECT_EQ(color->offset % 16, 0u);  // std140: a vec3 is 16-byte aligned
  std::vector<uint8_t> bytes = glsl::packParameters(shader.interface.parameters, shader.interface.parameterBytes);
  float packed[3];
  std::memcpy(packed, bytes.data() + color->offset, sizeof(packed));
  EXPECT_FLOAT_EQ(packed[0], 0.3f);
  EXPECT_FLOAT_EQ(packed[2], 0.7f);
}

TEST(ShaderBuilder, SetOverridesAnInputAndReportsBadOnes) {
  glsl::MaterialShader coated = shaderOf(openPbr(), withInputs({{"coat_weight", "1"}}));
  EXPECT_EQ(coated.interface.lobes, 3);
  {
    Context context;
    lowerText(context, openPbr(), withInputs({{"no_such_input", "1"}}));
    ASSERT_TRUE(context.diagnostics.hasErrors());
    EXPECT_NE(context.firstError().message.find("has no input named 'no_such_input'"), std::string::npos)
        << context.firstError().message;
    EXPECT_EQ(context.firstError().location.line(), 3u);  // the open_pbr_surface element
  }
  {
    Context context;
    lowerText(context, openPbr(), withInputs({{"base_color", "red"}}));
    ASSERT_TRUE(context.diagnostics.hasErrors());
    EXPECT_NE(context.firstError().message.find("--set base_color=red: 'red' is not a color3"), std::string::npos)
        << context.firstError().message;
  }
}

TEST(ShaderBuilder, Std140LayoutOfParameters) {
  std::vector<glsl::UniformField> fields{{"a", ir::Type::Float, 0, {1.0f}},
                                         {"m", ir::Type::Mat3, 16, {1, 2, 3, 4, 5, 6, 7, 8, 9}}};
  std::vector<uint8_t> bytes = glsl::packParameters(fields, 64);
  float column1[3];
  std::memcpy(column1, bytes.data() + 16 + 16, sizeof(column1));  // the second column, padded to 16 bytes
  EXPECT_EQ(column1[0], 2.0f);  // row-major input: m[0][1] = 2 is column 1, row 0
  EXPECT_EQ(column1[1], 5.0f);
  EXPECT_EQ(column1[2], 8.0f);
}

TEST(ShaderBuilder, TexturesBecomeBindingsWithTheirColourSpace) {
  Context context;
  std::vector<ir::Material> materials =
      lowerFile(context, sharedDir() / "corpus/materialx/examples/StandardSurface/standard_surface_wood_tiled.mtlx");
  ASSERT_EQ(materials.size(), 1u);
  glsl::MaterialShader shader = buildShader(materials[0], glsl::ShaderKind::Raster);
  ASSERT_EQ(shader.interface.textures.size(), 2u);
  std::vector<std::string> spaces;
  for (const glsl::TextureBinding& t : shader.interface.textures) {
    EXPECT_GE(t.binding, glsl::kFirstTextureBinding);
    EXPECT_NE(t.path.find("../../../Images/wood_"), std::string::npos) << t.path;
    spaces.push_back(t.path.find("color") != std::string::npos ? t.colorspace : "(roughness) " + t.colorspace);
  }
  EXPECT_NE(std::find(spaces.begin(), spaces.end(), "srgb_texture"), spaces.end());
}

// A newline (&#10;) in an image's file or colour space was copied raw into a `//` comment, so
// the rest of the value became shader code (here a #define that made every surface
// transparent), and a trailing backslash joined the next line to the comment.
TEST(ShaderBuilder, TextFromTheDocumentCannotBecomeShaderCode) {
  const std::string injected = "x.png&#10;#define mxc_luminance(x) 1.0&#10;//";
  const std::string text = mtlx(
      "  <image name=\"img\" type=\"color3\">\n"
      "    <input name=\"file\" type=\"filename\" value=\"" + injected + "\" colorspace=\"srgb_texture&#10;#define MXC_INJECTED 1&#13;\\\"/>\n"
      "  </image>\n"
      "  <image name=\"img2\" type=\"color3\"><input name=\"file\" type=\"filename\" value=\"c:\\dir\\\"/></image>\n"
      "  <multiply name=\"both\" type=\"color3\"><input name=\"in1\" type=\"color3\" nodename=\"img\"/>"
      "<input name=\"in2\" type=\"color3\" nodename=\"img2\"/></multiply>\n"
      "  <open_pbr_surface name=\"s\" type=\"surfaceshader\">\n"
      "    <input name=\"base_color\" type=\"color3\" nodename=\"both\"/>\n"
      "  </open_pbr_surface>\n  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" "
      "type=\"surfaceshader\" nodename=\"s\" /></surfacematerial>\n");
  Context context;
  std::vector<ir::Material> materials = lowerText(context, text);
  ASSERT_EQ(materials.size(), 1u) << context.diagnostics.format();
  glsl::MaterialShader shader = buildShader(materials[0], glsl::ShaderKind::Raster);
  ASSERT_EQ(shader.interface.textures.size(), 2u);
  const std::string& glsl = shader.glsl.text;
  EXPECT_EQ(glsl.find("\n#define mxc_luminance"), std::string::npos);
  EXPECT_EQ(glsl.find("\n#define MXC_INJECTED"), std::string::npos);
  // Each declaration stays one line, its comment quoted, escaped and ended by the quote.
  EXPECT_NE(glsl.find("// \"x.png\\n#define mxc_luminance(x) 1.0\\n//\" (\"srgb_texture\\n#define MXC_INJECTED 1\\r\\\\\")\n"),
            std::string::npos);
  EXPECT_NE(glsl.find("// \"c:\\\\dir\\\\\"\n"), std::string::npos);
  for (char c : glsl) EXPECT_FALSE((static_cast<unsigned char>(c) < 0x20 && c != '\n') || c == 0x7F) << int(c);
  // And it compiles (glslang reads what the device would).
  EXPECT_FALSE(compiledWords(shader).empty());
}

TEST(ShaderBuilder, MaterialLinesMapToTheDocument) {
  Context context;
  std::vector<ir::Material> materials = lowerText(context, openPbr("    <input name=\"coat_weight\" type=\"float\" value=\"1\" />\n"));
  ASSERT_EQ(materials.size(), 1u);
  glsl::MaterialShader shader = buildShader(materials[0], glsl::ShaderKind::Eval);
  ASSERT_EQ(shader.glsl.origins.size(), size_t(std::count(shader.glsl.text.begin(), shader.glsl.text.end(), '\n')));
  size_t mapped = 0;
  for (const SourceLocation& at : shader.glsl.origins) mapped += at.valid() ? 1 : 0;
  EXPECT_GT(mapped, 20u);  // the lobes' lines come from the shading node
  EXPECT_LT(mapped, shader.glsl.origins.size() / 4);  // library lines have no document origin
}

// The code key (ShaderCache's): two materials whose shaders differ only in the comments naming
// them share it; any difference in the code does not; library files count by their paths.
TEST(ShaderBuilder, CodeKeyIgnoresTheNamesAndKeepsTheCode) {
  const std::string blue = openPbr("    <input name=\"base_color\" type=\"color3\" value=\"0.1, 0.2, 0.8\" />\n");
  std::string renamed = blue;
  const size_t at = renamed.find("name=\"M\"");
  ASSERT_NE(at, std::string::npos);
  renamed.replace(at, 8, "name=\"Blue_paint\"");
  glsl::MaterialShader a = shaderOf(blue);
  glsl::MaterialShader b = shaderOf(renamed);
  glsl::MaterialShader red = shaderOf(openPbr("    <input name=\"base_color\" type=\"color3\" value=\"0.8, 0.2, 0.1\" />\n"));
  EXPECT_NE(a.glsl.text, b.glsl.text);  // the comments name the material
  EXPECT_NE(b.glsl.text.find("Blue_paint"), std::string::npos);
  EXPECT_EQ(a.codeKey, b.codeKey);
  EXPECT_EQ(b.codeKey.find("Blue_paint"), std::string::npos);
  EXPECT_NE(a.codeKey, red.codeKey);  // a constant of the code differs
  // Library files by their paths, not their text: the key is the generated part.
  EXPECT_NE(a.codeKey.find("// ---- library/mxc_common.glsl ----"), std::string::npos);
  EXPECT_LT(a.codeKey.size() * 5, a.glsl.text.size());
  EXPECT_NE(a.codeKey.find("void mxc_material_closure("), std::string::npos);
}

// The library key (what a batch's group compile shares, ShaderGroup.h) leaves out the closure
// function's body and the comments: two materials whose textures differ only in their files
// are one library, while their codes differ.
TEST(ShaderBuilder, LibraryKeyLeavesOutTheClosureAndComments) {
  auto textured = [](const std::string& file, const std::string& roughness) {
    return mtlx("  <image name=\"img\" type=\"color3\"><input name=\"file\" type=\"filename\" value=\"" + file +
                "\" /></image>\n  <open_pbr_surface name=\"s\" type=\"surfaceshader\">\n"
                "    <input name=\"base_color\" type=\"color3\" nodename=\"img\" />\n"
                "    <input name=\"specular_roughness\" type=\"float\" value=\"" + roughness + "\" />\n"
                "  </open_pbr_surface>\n  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" "
                "type=\"surfaceshader\" nodename=\"s\" /></surfacematerial>\n");
  };
  const glsl::MaterialShader a = shaderOf(textured("a.png", "0.3"));
  const glsl::MaterialShader b = shaderOf(textured("b.png", "0.3"));
  const glsl::MaterialShader rougher = shaderOf(textured("a.png", "0.6"));
  ASSERT_EQ(a.interface.textures.size(), 1u);
  EXPECT_NE(a.codeKey, b.codeKey);  // the declaration's comment names the file
  EXPECT_EQ(a.libraryKey, b.libraryKey);
  EXPECT_NE(a.codeKey, rougher.codeKey);  // a constant of the closure
  EXPECT_EQ(a.libraryKey, rougher.libraryKey);
  EXPECT_EQ(a.libraryKey.find("a.png"), std::string::npos);
  // The closure's lines are the function, whole.
  const std::string& text = a.glsl.text;
  size_t line = 0, at = 0;
  for (; line < a.closureFirst; ++line) at = text.find('\n', at) + 1;
  EXPECT_EQ(text.compare(at, 26, "void mxc_material_closure("), 0) << text.substr(at, 80);
  EXPECT_EQ(a.libraryKey.find("void mxc_material_closure("), std::string::npos);
}

}  // namespace
}  // namespace mxc::test
