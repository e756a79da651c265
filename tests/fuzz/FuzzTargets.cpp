#include "FuzzTargets.h"

#include <string>

#include "compiler/driver/Compiler.h"
#include "compiler/xml/XmlParser.h"

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

void compileDocument(const uint8_t* data, size_t size) {
  // The built-in library, loaded once for all inputs; each input gets a workspace of its own.
  static Workspace library;
  static const bool loaded = library.loadLibraries();
  (void)loaded;
  Workspace workspace;
  CompileRequest request;
  request.document = "fuzz.mtlx";
  request.text = std::string(reinterpret_cast<const char*>(data), size);
  request.libraries = &library.libraries;
  Compiler compiler(workspace, std::move(request));
  for (const ir::Material& m : compiler.materials()) {
    for (glsl::ShaderKind kind : {glsl::ShaderKind::Raster, glsl::ShaderKind::Eval, glsl::ShaderKind::Furnace}) {
      glsl::MaterialShader shader = compiler.shader(m, kind);
      (void)shader;
    }
  }
}

}  // namespace mxc::fuzz
