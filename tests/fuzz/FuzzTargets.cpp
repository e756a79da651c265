#include "FuzzTargets.h"

#include <string>

#include "cli/Scene.h"
#include "compiler/driver/Compiler.h"
#include "compiler/xml/XmlParser.h"
#include "runtime/MeshFile.h"

namespace mxc::fuzz {

void parseXml(const uint8_t* data, size_t size) {
  SourceFile source("fuzz.xml", std::string(reinterpret_cast<const char*>(data), size));
  try {
    xml::Document document = xml::parse(source);
    (void)document;
  } catch (const CompileError&) {
    // Malformed input is reported with a position: the expected outcome.
  }
}

namespace {

void compileText(std::string text) {
  // The built-in library, loaded once for all inputs; each input gets a workspace of its own.
  static Workspace library;
  static const bool loaded = library.loadLibraries();
  (void)loaded;
  Workspace workspace;
  CompileRequest request;
  request.document = "fuzz.mtlx";
  request.text = std::move(text);
  request.libraries = &library.libraries;
  Compiler compiler(workspace, std::move(request));
  for (const ir::Material& m : compiler.materials()) {
    for (glsl::ShaderKind kind : {glsl::ShaderKind::Raster, glsl::ShaderKind::Eval, glsl::ShaderKind::Furnace}) {
      glsl::MaterialShader shader = compiler.shader(m, kind);
      (void)shader;
    }
  }
}

}  // namespace

void compileDocument(const uint8_t* data, size_t size) {
  compileText(std::string(reinterpret_cast<const char*>(data), size));
}

void compileInlineSource(const uint8_t* data, size_t size) {
  // The bytes as an attribute value: markup characters as entities, and bytes XML cannot hold
  // at all (controls but tab and line breaks) as spaces, so that the parser under test is the
  // inline-source one, not the XML reader's refusal.
  std::string source;
  for (size_t i = 0; i < size; ++i) {
    const char c = static_cast<char>(data[i]);
    switch (c) {
      case '&': source += "&amp;"; break;
      case '<': source += "&lt;"; break;
      case '>': source += "&gt;"; break;
      case '"': source += "&quot;"; break;
      default: source += (data[i] < 0x20 && c != '\t' && c != '\n' && c != '\r') || data[i] == 0x7f ? ' ' : c;
    }
  }
  // One document per output type, so that an expression of either type reaches the back end.
  for (const char* type : {"float", "vector3"}) {
    std::string text = "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\">\n";
    text += std::string("  <nodedef name=\"ND_fuzz\" node=\"fuzz\">\n"
                        "    <input name=\"f\" type=\"float\" value=\"0.5\"/>\n"
                        "    <input name=\"v\" type=\"vector3\" value=\"0.1, 0.2, 0.3\"/>\n"
                        "    <input name=\"c\" type=\"color4\" value=\"0.1, 0.2, 0.3, 0.4\"/>\n"
                        "    <input name=\"i\" type=\"integer\" value=\"2\"/>\n"
                        "    <input name=\"b\" type=\"boolean\" value=\"true\"/>\n"
                        "    <input name=\"m\" type=\"matrix33\" value=\"1, 0, 0, 0, 1, 0, 0, 0, 1\"/>\n"
                        "    <output name=\"out\" type=\"") + type + "\"/>\n  </nodedef>\n"
            "  <implementation name=\"IM_fuzz\" nodedef=\"ND_fuzz\" target=\"genglsl\" sourcecode=\"" + source + "\"/>\n"
            "  <fuzz name=\"n\" type=\"" + type + "\"/>\n"
            "  <convert name=\"colour\" type=\"color3\"><input name=\"in\" type=\"" + type + "\" nodename=\"n\"/></convert>\n"
            "  <open_pbr_surface name=\"s\" type=\"surfaceshader\">\n"
            "    <input name=\"base_color\" type=\"color3\" nodename=\"colour\"/>\n  </open_pbr_surface>\n"
            "  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" "
            "nodename=\"s\"/></surfacematerial>\n</materialx>\n";
    compileText(std::move(text));
  }
}

void readSceneJson(const uint8_t* data, size_t size) {
  // A folder that does not exist: the scene's relative files are named, not read.
  auto scene = cli::readSceneText("/nonexistent-mxc-fuzz/scene.json", std::string(reinterpret_cast<const char*>(data), size));
  (void)scene;
}

void loadMeshFile(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const size_t first = bytes.find_first_not_of(" \t\r\n");
  const char* name = bytes.starts_with("glTF")                             ? "/nonexistent-mxc-fuzz/mesh.glb"
                     : first != std::string::npos && bytes[first] == '{' ? "/nonexistent-mxc-fuzz/mesh.gltf"
                                                                         : "/nonexistent-mxc-fuzz/mesh.obj";
  auto mesh = rt::loadMeshBytes(name, bytes);
  (void)mesh;
}

}  // namespace mxc::fuzz
