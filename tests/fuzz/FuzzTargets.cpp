#include "FuzzTargets.h"

#include <string>

#include "compiler/document/DocumentLoader.h"
#include "compiler/glsl/ShaderBuilder.h"
#include "compiler/ir/Effects.h"
#include "compiler/ir/passes/Pass.h"
#include "compiler/library/LibraryStack.h"
#include "compiler/lower/Lowering.h"
#include "compiler/resolve/Resolver.h"
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

namespace {

/// The built-in library, loaded once for all inputs.
struct Library {
  SourceManager sources;
  Diagnostics diagnostics;
  lib::LibraryStack stack{sources, diagnostics};
  Library() { stack.addBuiltin(); }
};

}  // namespace

void compileDocument(const uint8_t* data, size_t size) {
  static Library library;
  Diagnostics diagnostics;
  SourceManager sources;
  doc::DocumentLoader loader(sources, diagnostics);
  const doc::Document* document = loader.loadText("fuzz.mtlx", std::string(reinterpret_cast<const char*>(data), size));
  if (!document) return;
  resolve::ResolvedDocument resolved = resolve::resolveDocument(*document, library.stack.top(), diagnostics);
  if (diagnostics.hasErrors()) return;
  std::vector<ir::Material> materials = lower::lowerDocument(resolved, {}, diagnostics);
  for (ir::Material& m : materials) {
    ir::runPasses(m);
    ir::summarizeEffects(m);
    for (glsl::ShaderKind kind : {glsl::ShaderKind::Raster, glsl::ShaderKind::Eval, glsl::ShaderKind::Furnace}) {
      glsl::MaterialShader shader = glsl::buildMaterialShader(m, kind);
      (void)shader;
    }
  }
}

}  // namespace mxc::fuzz
