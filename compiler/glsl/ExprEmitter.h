#pragma once
/// \file
/// IR expressions to GLSL statements: one SSA temporary per non-constant expression, constants
/// written in place, textures and parameters collected as bindings.

#include <map>
#include <string>
#include <vector>

#include "compiler/glsl/Contract.h"
#include "compiler/ir/Material.h"
#include "compiler/spirv/SpirvCompiler.h"

namespace mxc::glsl {

/// An image file the shader samples, with its binding.
struct TextureBinding {
  std::string path;        ///< as the document resolves it (fileprefix applied)
  std::string colorspace;  ///< the file input's colour space ("srgb_texture" is decoded to linear)
  uint32_t binding = 0;
  std::string name;  ///< GLSL sampler name
  SourceLocation origin;  ///< the image node's `file` input, for errors about the file
};

/// GLSL lines with the document position each came from (for error mapping).
struct Lines {
  std::vector<std::string> text;
  std::vector<SourceLocation> origins;
  void add(std::string line, SourceLocation origin = {}) {
    text.push_back(std::move(line));
    origins.push_back(origin);
  }
  void append(const Lines& other) {
    text.insert(text.end(), other.text.begin(), other.text.end());
    origins.insert(origins.end(), other.origins.begin(), other.origins.end());
  }
};

std::string glslType(ir::Type type);

/// How an image sample reads its texture: Op::ImageSample's payload
/// "uaddress,vaddress,filtertype,colorspace" as MaterialX writes the modes.
struct ImageSampling {
  AddressMode uaddress = AddressMode::Periodic;
  AddressMode vaddress = AddressMode::Periodic;
  FilterMode filter = FilterMode::Linear;
  std::string colorspace;  ///< the file input's colour space
};
ImageSampling imageSampling(const std::string& payload);
/// MaterialX's name of an address mode ("constant", "clamp", "periodic", "mirror").
std::string_view addressModeName(AddressMode mode);
/// A float as a GLSL literal that always reads as a float ("1.0", "0.5", "1e-07").
std::string glslFloat(float value);

class ExprEmitter {
 public:
  /// `firstTexture` is the binding of the first sampler.
  ExprEmitter(const ir::Material& material, uint32_t firstTexture);

  /// Statements computing every non-constant expression the material uses (in dependency
  /// order), indented for a function body.
  const Lines& statements() const { return statements_; }
  /// A GLSL expression for an IR expression: a literal or a temporary's name.
  std::string ref(ir::ExprId id) const;
  /// ref() of a parameter, or `fallback` when it is absent.
  std::string param(const ir::Param& p, const std::string& fallback) const;
  const std::vector<TextureBinding>& textures() const { return textures_; }
  /// Names of geometric properties the material reads (for reports).
  const std::vector<std::string>& geomprops() const { return geomprops_; }
  bool usesProcedural() const { return procedural_; }
  /// Op::Parameter names the statements read, with their types.
  const std::map<std::string, ir::Type>& parameters() const { return parameters_; }

 private:
  std::string emit(ir::ExprId id);
  std::string literal(ir::ExprId id) const;
  std::string texture(const std::string& path, const std::string& colorspace);
  /// The GLSL condition "the file of `sampler` could not be read": its bit of its missing_textures mask.
  std::string missing(const std::string& sampler) const;

  const ir::Material& m_;
  uint32_t nextTexture_;
  Lines statements_;
  std::map<ir::ExprId, std::string> names_;
  std::vector<TextureBinding> textures_;
  std::vector<std::string> geomprops_;
  std::map<std::string, ir::Type> parameters_;
  std::vector<SourceLocation> origins_;  // per expression: the first parameter that uses it
  bool procedural_ = false;
};

}  // namespace mxc::glsl
