#include "compiler/glsl/ShaderBuilder.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <map>
#include <mutex>
#include <span>
#include <stdexcept>
#include <tuple>

#include <fmt/format.h>

#include "compiler/common/EmbeddedFile.h"
#include "compiler/common/Quote.h"
#include "compiler/glsl/AlbedoTableFile.h"
#include "compiler/glsl/Contract.h"

namespace mxc {
std::span<const EmbeddedFile> glslLibraryFiles();  // cmake/EmbedFiles.cmake: compiler/glsl/{library,stages}
}

namespace mxc::glsl {

/// The GLSL versions of the generated shaders, chosen for glslang's start-up, which builds the
/// built-in symbol tables of every stage the version has before it parses anything (callgrind,
/// glslangValidator on an empty fragment shader: 4.00 142 M, 4.20 172 M, 4.40 180 M, 4.50 351 M
/// instructions; 4.50 adds the mesh and task stages, 4.20 the compute stage).
///
/// The raster stages (fragment and vertex) are GLSL 4.00 with the ARB extensions that bring the
/// later versions' features they use: storage buffers (4.30), block member offsets (4.40),
/// binding layouts (4.20), memory qualifiers (4.20) and input locations (4.10). The SPIR-V is the
/// same as from 4.40 but for its OpSource and an OpSourceExtension per extension, and a single
/// `mxc compile` takes 38 M instructions (about a tenth) less. glslang refuses compute shaders
/// below 4.20 (and has no compute built-ins there); they are 4.40. A process that compiles
/// both kinds builds both versions' tables: the test programs do; of mxc's commands, none
/// (render and compile build raster stages, eval and furnace compute ones; the environment
/// sampling kernel, 4.40, runs only in tests).
constexpr int kGlslRasterVersion = 400;
constexpr std::string_view kGlslRasterExtensions[] = {
    "GL_ARB_separate_shader_objects",      // layout(location) on stage inputs (4.10)
    "GL_ARB_shading_language_420pack",     // layout(binding) (4.20)
    "GL_ARB_shader_image_load_store",      // readonly on buffers (4.20)
    "GL_ARB_shader_storage_buffer_object", // buffer blocks (4.30)
    "GL_ARB_enhanced_layouts",             // layout(offset) on block members (4.40)
};
constexpr int kGlslComputeVersion = 440;

namespace {

/// A shader library file: a real one (embedded), or one generated from the contract.
std::string libraryFile(std::string_view path) {
  if (std::optional<std::string> generated = generatedLibraryFile(path)) return *generated;
  for (const EmbeddedFile& f : glslLibraryFiles()) {
    if (f.path == path) return std::string(f.contents);
  }
  if (path == kAlbedoFitsPath) return std::string(committedTableFile(kAlbedoFitsPath));
  throw std::logic_error(fmt::format("shader library file {} is not embedded", path));  // a build error
}

/// The tier's macro: MXC_ACCURACY_FAST, MXC_ACCURACY_BALANCED.
std::string accuracyMacro(Accuracy accuracy) {
  std::string name(accuracyName(accuracy));
  for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return name;
}

/// A library file as a shader holds it: its lines, with each `#include "path"` of the file (the
/// contract's generated declarations) replaced by that file's marker line and lines.
struct ExpandedFile {
  std::string text;  ///< every line ends with '\n'
  size_t lines = 0;
};

void expandInto(std::string_view path, ExpandedFile& out) {
  const std::string text = libraryFile(path);
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view l = std::string_view(text).substr(start, end - start);
    constexpr std::string_view kInclude = "#include \"";
    if (l.rfind(kInclude, 0) == 0 && l.size() > kInclude.size() + 1 && l.back() == '"') {
      const std::string_view included = l.substr(kInclude.size(), l.size() - kInclude.size() - 1);
      out.text += fmt::format("// ---- {} ----\n", included);
      ++out.lines;
      expandInto(included, out);
    } else {
      out.text.append(l);
      out.text += '\n';
      ++out.lines;
    }
    start = end + 1;
  }
}

/// The file expanded once per process: its text is fixed in the executable (the generated
/// files by the contract), and every material's shader holds it.
const ExpandedFile& expandedFile(std::string_view path) {
  static std::mutex mutex;
  static std::map<std::string, ExpandedFile, std::less<>> files;  // nodes never move
  std::lock_guard<std::mutex> lock(mutex);
  auto found = files.find(path);
  if (found == files.end()) {
    ExpandedFile f;
    expandInto(path, f);
    found = files.emplace(std::string(path), std::move(f)).first;
  }
  return found->second;
}

/// Accumulates GLSL lines with their origins: lines of its own, and library files whole.
class Writer {
 public:
  explicit Writer(bool expand = true) : expand_(expand) {}
  void line(std::string text, SourceLocation origin = {}) { addLine(std::move(text), origin, true); }
  /// A comment line that names the material: part of the text, not of its code key.
  void namingLine(std::string text, SourceLocation origin = {}) { addLine(std::move(text), origin, false); }
  void lines(const Lines& more) {
    for (size_t i = 0; i < more.text.size(); ++i) line(more.text[i], more.origins[i]);
  }
  /// The lines from here to endClosure() define the material's function: out of the library key.
  void beginClosure() { closure_.first = lineCount_; closurePieces_.first = pieces_.size(); }
  void endClosure() { closure_.second = lineCount_; closurePieces_.second = pieces_.size(); }
  /// The lines from here to endTextures() declare the textures: out of the library key.
  void beginTextures() { textures_.first = lineCount_; texturePieces_.first = pieces_.size(); }
  void endTextures() { textures_.second = lineCount_; texturePieces_.second = pieces_.size(); }
  /// A library file, whole, with a marker naming it.
  void file(std::string_view path) {
    if (!expand_) {
      line(fmt::format("#include \"{}\"", path));
      return;
    }
    line(fmt::format("// ---- {} ----", path));
    // A library file's text is fixed in the executable, so its path stands for it in the key.
    const ExpandedFile& f = expandedFile(path);
    Piece& p = pieces_.emplace_back();
    p.file = &f;
    p.keyed = false;
    lineCount_ += f.lines;
  }
  /// The code key of the text finish() returned: its lines but for the naming ones, library
  /// files by their paths.
  const std::string& key() const { return key_; }
  /// The key but for the material's function.
  const std::string& libraryKey() const { return libraryKey_; }
  std::pair<size_t, size_t> closure() const { return closure_; }
  std::pair<size_t, size_t> textures() const { return textures_; }
  spirv::GlslSource finish(spirv::Stage stage, std::string name) {
    spirv::GlslSource out;
    out.stage = stage;
    out.name = std::move(name);
    size_t bytes = 0;
    for (const Piece& p : pieces_) bytes += p.file ? p.file->text.size() : p.text.size() + 1;
    out.text.reserve(bytes);
    out.origins.reserve(lineCount_);
    std::string key, libraryKey;
    for (size_t i = 0; i < pieces_.size(); ++i) {
      const Piece& p = pieces_[i];
      if (p.file) {
        out.text += p.file->text;
        out.origins.resize(out.origins.size() + p.file->lines);
        continue;
      }
      out.text += p.text;
      out.text += '\n';
      out.origins.push_back(p.origin);
      if (!p.keyed) continue;
      key += p.text;
      key += '\n';
      const bool inClosure = i >= closurePieces_.first && i < closurePieces_.second;
      const bool inTextures = i >= texturePieces_.first && i < texturePieces_.second;
      if (!inClosure && !inTextures) {
        // Without its comment, which changes no code (GLSL has no strings: `//` always starts
        // a comment).
        libraryKey.append(p.text, 0, p.text.find("//"));
        libraryKey += '\n';
      }
    }
    key_ = std::move(key);
    libraryKey_ = std::move(libraryKey);
    return out;
  }

 private:
  /// A line of the writer's own, or a library file.
  struct Piece {
    std::string text;
    const ExpandedFile* file = nullptr;
    SourceLocation origin;
    bool keyed = true;
  };
  void addLine(std::string&& text, SourceLocation origin, bool keyed) {
    Piece& p = pieces_.emplace_back();
    p.text = std::move(text);
    p.origin = origin;
    p.keyed = keyed;
    ++lineCount_;
  }

  std::vector<Piece> pieces_;
  size_t lineCount_ = 0;
  bool expand_ = true;
  std::string key_;
  std::string libraryKey_;
  std::pair<size_t, size_t> closure_{0, 0};        ///< the lines of mxc_material_closure, [first, end)
  std::pair<size_t, size_t> closurePieces_{0, 0};  ///< the same as pieces
  std::pair<size_t, size_t> textures_{0, 0};       ///< the texture declarations' lines, [first, end)
  std::pair<size_t, size_t> texturePieces_{0, 0};  ///< the same as pieces
};

std::vector<UniformField> parameterLayout(const ir::Material& material, const ExprEmitter& exprs, uint32_t& bytes) {
  std::vector<UniformField> fields;
  fields.push_back({"missing_textures", ir::Type::Int, 0, {0.0f}});
  fields.push_back({"frame", ir::Type::Float, 0, {1.0f}});
  fields.push_back({"time", ir::Type::Float, 0, {0.0f}});
  for (size_t k = 32; k < exprs.textures().size(); k += 32) fields.push_back({missingTexturesMember(k), ir::Type::Int, 0, {0.0f}});
  for (const auto& [name, type] : exprs.parameters()) {
    if (name == "frame" || name == "time") continue;
    UniformField f{name, type, 0, std::vector<float>(std::max(ir::componentCount(type), 1), 0.0f)};
    for (const ir::Parameter& p : material.parameters) {
      if (p.name == name && p.value.size() == f.value.size()) f.value = p.value;
    }
    fields.push_back(std::move(f));
  }
  uint32_t offset = 0;
  for (UniformField& f : fields) {
    uint32_t align = 4, size = 4;
    std140Type(glslType(f.type), align, size);
    offset = (offset + align - 1) / align * align;
    f.offset = offset;
    offset += size;
  }
  bytes = std::max<uint32_t>((offset + 15) / 16 * 16, 16);
  return fields;
}


/// `#version` and, for the raster stages, the extensions that stand in for later versions.
void versionLines(Writer& w, bool raster) {
  w.line(fmt::format("#version {}", raster ? kGlslRasterVersion : kGlslComputeVersion));
  if (!raster) return;
  for (std::string_view extension : kGlslRasterExtensions) w.line(fmt::format("#extension {} : require", extension));
}

void header(Writer& w, const ir::Material& material, std::string_view purpose, bool raster, bool subgroups) {
  versionLines(w, raster);
  if (subgroups) w.line("#extension GL_KHR_shader_subgroup_ballot : require");  // parameters read by subgroupBroadcastFirst
  // Every text from the document reaches the code through quotedValue() (compiler/common/Quote.h):
  // raw, a newline in it would end the comment and make the rest shader code.
  w.namingLine(fmt::format("// Generated by mxc from material {} ({}): {}.", quotedValue(material.name), quotedValue(material.shader), purpose));
  w.line("// Do not edit: produced by `mxc compile`; goldens are rewritten by scripts/update-goldens.");
}

}  // namespace

std::string_view shaderKindName(ShaderKind kind) {
  switch (kind) {
    case ShaderKind::Raster: return "raster";
    case ShaderKind::Eval: return "eval";
    case ShaderKind::Furnace: return "furnace";
    case ShaderKind::Sample: return "sample";
  }
  return "raster";
}

MaterialShader buildMaterialShader(const ir::Material& material, ShaderKind kind, const BuildOptions& options) {
  ExprEmitter exprs(material, kFirstTextureBinding);
  const Closure closure = buildClosure(material, exprs, options.accuracy);
  MaterialShader out;
  MaterialInterface& iface = out.interface;
  iface.textures = exprs.textures();
  iface.lobes = closure.lobes;
  if (options.accuracy == Accuracy::Reference) iface.samplesPerDispatch = 1;
  // The library's closure code refers to a lobe type, so at least one kind is compiled in.
  iface.lobeKinds = material.features.lobes.empty() ? FlagSet<ir::LobeKind>().insert(ir::LobeKind::EON)
                                                    : material.features.lobes;
  iface.geomprops = exprs.geomprops();
  // The reference tier's walk refracts through every interface and crosses every medium.
  const bool everything = !options.specialize || options.accuracy == Accuracy::Reference;
  iface.transmission = everything || (closure.modes & kModeTransmit) != 0;
  iface.absorption = everything || closure.absorbs;
  iface.parameters = parameterLayout(material, exprs, iface.parameterBytes);

  Writer w(options.expandLibrary);
  const std::string_view purpose = kind == ShaderKind::Raster  ? "fragment shader of the sphere renderer"
                                   : kind == ShaderKind::Eval    ? "compute shader evaluating f cos for direction pairs"
                                   : kind == ShaderKind::Furnace ? "compute shader estimating the directional albedo"
                                                                 : "compute shader drawing sample directions";
  header(w, material, purpose, kind == ShaderKind::Raster, options.subgroups);
  iface.subgroups = options.subgroups;
  w.line(fmt::format("#define MXC_MAX_LOBES {}", std::max(iface.lobes, 1)));
  w.line(fmt::format("#define MXC_ACCURACY_{}", accuracyMacro(options.accuracy)));
  if (options.accuracy == Accuracy::Reference) {
    w.line(fmt::format("#define MXC_MAX_STACKS {}", std::max(closure.stacks, 1)));
    w.line(fmt::format("#define MXC_REFERENCE_SAMPLES {}", std::max(options.referenceSamples, 1)));
    // The emission walk only where emission reaches the surface: each walk is a large inlined
    // loop, and lavapipe's compile time grows with them.
    if (material.features.emission) w.line("#define MXC_WALK_EMITS");
  }
  // The guards of the lobe kinds in use, in the order of their names.
  std::vector<std::string_view> kinds;
  iface.lobeKinds.forEach([&](ir::LobeKind k) { kinds.push_back(ir::lobeKindName(k)); });
  std::sort(kinds.begin(), kinds.end());
  for (std::string_view k : kinds) w.line(fmt::format("#define MXC_HAS_{}", k));
  if (material.features.thinFilm) w.line("#define MXC_THIN_FILM");
  if (iface.transmission) w.line("#define MXC_TRANSMISSION");
  if (iface.absorption) w.line("#define MXC_ABSORPTION");
  w.line(fmt::format("#define MXC_TABLE_BINDING {}", static_cast<uint32_t>(kTablesBinding)));
  w.line(fmt::format("#define MXC_TABLE_SIZE {}", kTableSize));
  w.line(fmt::format("#define MXC_TABLE_SLICES {}", kTableSlices));
  w.line(fmt::format("#define MXC_TABLE_HEIGHT {}", kTableHeight));
  if (options.accuracy != Accuracy::Fast) {
    // The walk's tables (Bindings.h, WalkTables.h): their grids and first rows.
    w.line(fmt::format("#define MXC_WALK_ETA_STEPS {}", kWalkEtaSteps));
    w.line(fmt::format("#define MXC_WALK_ANISOTROPY_STEPS {}", kWalkAnisotropySteps));
    w.line(fmt::format("#define MXC_WALK_ROUGHNESS_STEPS {}", kWalkRoughnessSteps));
    w.line(fmt::format("#define MXC_WALK_GLOSS_ROW {}", kWalkGlossRow));
    w.line(fmt::format("#define MXC_WALK_MEDIUM_ROW {}", kWalkMediumRow));
    w.line(fmt::format("#define MXC_WALK_REFLECTANCE_ROW {}", kWalkReflectanceRow));
  }
  if (kind == ShaderKind::Raster) w.line("#define MXC_STAGE_RASTER");
  if (options.subgroups) w.line("#define MXC_SUBGROUPS");
  if (options.separateSamplers) w.line("#define MXC_SEPARATE_SAMPLERS");
  w.line("");
  w.file("library/mxc_common.glsl");
  w.file("library/mxc_microfacet.glsl");
  w.file("library/mxc_fresnel.glsl");
  if (iface.lobeKinds.has(ir::LobeKind::Sheen)) w.file("library/mxc_sheen.glsl");
  if (iface.lobeKinds.has(ir::LobeKind::Fuzz)) w.file("library/mxc_fuzz.glsl");
  if (iface.lobeKinds.has(ir::LobeKind::Hair)) w.file("library/mxc_hair.glsl");
  w.file("library/mxc_geometry.glsl");
  if (exprs.usesProcedural()) w.file("library/mxc_procedural.glsl");
  w.file("library/mxc_lobes.glsl");
  w.file("library/mxc_subsurface.glsl");
  w.file(options.accuracy == Accuracy::Reference ? "library/mxc_walk.glsl" : "library/mxc_closure.glsl");
  w.file("library/mxc_closure_sample.glsl");

  w.line("// ---- the material's parameters ----");
  w.line(fmt::format("layout(set = 0, binding = {}, std140) readonly buffer MxcParameters {{", static_cast<uint32_t>(kParameterBinding)));
  for (const UniformField& f : iface.parameters) {
    w.line(fmt::format("  layout(offset = {}) {} {};", f.offset, parameterType(f), f.name));
  }
  w.line("} mxc_params;");
  w.beginTextures();
  for (const TextureBinding& t : iface.textures) {
    w.line(fmt::format("MXC_DECLARE_SAMPLER2D(0, {}, {});  // {}{}", t.binding, t.name, quotedValue(t.path),
                       t.colorspace.empty() ? "" : " (" + quotedValue(t.colorspace) + ")"));
  }
  w.endTextures();
  w.line("");
  w.namingLine(fmt::format("// ---- material {} ----", quotedValue(material.name)), material.origin.location);
  w.beginClosure();
  w.line(fmt::format("void {}({}) {{", kClosureFunction, kClosureParameters), material.origin.location);
  w.lines(exprs.statements());
  w.lines(closure.lines);
  w.line("}");
  w.endClosure();
  w.line("");
  switch (kind) {
    case ShaderKind::Raster:
      w.file("stages/mxc_view.glsl");
      w.line(fmt::format("#define MXC_ENV_SET {}", kEnvironmentSet));
      w.file("stages/mxc_environment.glsl");
      w.file("stages/mxc_raster.frag");
      out.glsl = w.finish(spirv::Stage::Fragment, fmt::format("material {} (fragment)", material.name));
      break;
    case ShaderKind::Eval:
      w.file("stages/mxc_batch.glsl");
      w.file("stages/mxc_eval.comp");
      out.glsl = w.finish(spirv::Stage::Compute, fmt::format("material {} (eval compute)", material.name));
      break;
    case ShaderKind::Furnace:
      w.file("stages/mxc_batch.glsl");
      w.file("stages/mxc_furnace.comp");
      out.glsl = w.finish(spirv::Stage::Compute, fmt::format("material {} (furnace compute)", material.name));
      break;
    case ShaderKind::Sample:
      w.file("stages/mxc_batch.glsl");
      w.file("stages/mxc_sample.comp");
      out.glsl = w.finish(spirv::Stage::Compute, fmt::format("material {} (sample compute)", material.name));
      break;
  }
  out.codeKey = w.key();
  out.libraryKey = w.libraryKey();
  std::tie(out.closureFirst, out.closureEnd) = w.closure();
  std::tie(out.texturesFirst, out.texturesEnd) = w.textures();
  return out;
}

spirv::GlslSource buildVertexShader() {
  Writer w;
  versionLines(w, true);
  w.line("// Generated by mxc: vertex shader of the sphere renderer (the same for every material).");
  w.file("stages/mxc_view.glsl");
  w.file("stages/mxc_raster.vert");
  return w.finish(spirv::Stage::Vertex, "renderer (vertex)");
}

const std::vector<uint32_t>& vertexStageSpirv() {
  static const std::vector<uint32_t> words = [] {
    Diagnostics diagnostics;
    auto compiled = spirv::compile(buildVertexShader(), {}, diagnostics);
    // The vertex stage is mxc's own fixed code, compiled by every test: a failure is a bug.
    if (!compiled) throw std::logic_error("the vertex stage does not compile: " + diagnostics.format());
    return std::move(*compiled);
  }();
  return words;
}

spirv::GlslSource buildTablesShader() {
  Writer w;
  versionLines(w, false);
  w.line("// Generated by mxc: compute shader filling the albedo tables the lobes read.");
  w.line(fmt::format("#define MXC_TABLE_SIZE {}", kTableSize));
  w.line(fmt::format("#define MXC_TABLE_SLICES {}", kTableSlices));
  w.file("library/mxc_common.glsl");
  w.file("library/mxc_microfacet.glsl");
  w.file("library/mxc_fresnel.glsl");
  w.file("library/mxc_sheen.glsl");
  w.file("stages/mxc_tables.comp");
  return w.finish(spirv::Stage::Compute, "albedo tables (compute)");
}

spirv::GlslSource buildEnvironmentSampleShader() {
  Writer w;
  versionLines(w, false);
  w.line("// Generated by mxc: compute shader drawing directions from an environment image's distribution.");
  w.line("#define MXC_ENV_SET 0");
  w.line(fmt::format("#define MXC_ENV_SAMPLE_OUTPUT {}", kEnvironmentSampleOutputBinding));
  w.file("library/mxc_common.glsl");
  w.file("stages/mxc_environment.glsl");
  w.file("stages/mxc_environment_sample.comp");
  return w.finish(spirv::Stage::Compute, "environment sampling (compute)");
}

}  // namespace mxc::glsl

namespace mxc::glsl {

std::string parameterType(const UniformField& f) {
  if (isMissingTexturesMember(f.name)) return "uint";
  return glslType(f.type);
}

std::vector<uint8_t> packParameters(const std::vector<UniformField>& fields, uint32_t bytes) {
  std::vector<uint8_t> out(bytes, 0);
  auto put = [&](uint32_t offset, const void* data, size_t size) {
    if (offset + size <= out.size()) std::memcpy(out.data() + offset, data, size);
  };
  for (const UniformField& f : fields) {
    if (isMissingTexturesMember(f.name)) {
      put(f.offset, &f.bits, 4);
      continue;
    }
    if (f.value.empty()) continue;
    if (f.type == ir::Type::Int || f.type == ir::Type::Bool) {
      const int32_t v = f.type == ir::Type::Bool ? (f.value[0] != 0.0f ? 1 : 0) : static_cast<int32_t>(f.value[0]);
      put(f.offset, &v, 4);
    } else if (f.type == ir::Type::Mat3 || f.type == ir::Type::Mat4) {
      const uint32_t n = f.type == ir::Type::Mat3 ? 3 : 4;
      for (uint32_t col = 0; col < n; ++col) {
        for (uint32_t row = 0; row < n && row * n + col < f.value.size(); ++row) {
          put(f.offset + col * 16 + row * 4, &f.value[row * n + col], 4);
        }
      }
    } else {
      put(f.offset, f.value.data(), f.value.size() * sizeof(float));
    }
  }
  return out;
}

}  // namespace mxc::glsl
