#pragma once
/// \file
/// What a host renderer needs to run a material's shader without mxc: its interface as JSON
/// (schema mxc-shader-interface-1, docs/shader-interface.md), written beside the SPIR-V by
/// `mxc compile`. Every descriptor with its set, binding and type; each uniform and parameter
/// block member with its type, std140 offset and, for parameters, the document input it comes
/// from; each texture with its file, colour space, decoding, addressing and filtering; the
/// vertex inputs; the specialization constants; the tables the shader samples. Made from the
/// same tables the GLSL is generated from (compiler/glsl/Contract.h, MaterialInterface), so the
/// description and the shader cannot disagree.

#include <string>

#include <nlohmann/json.hpp>

#include "compiler/glsl/ShaderBuilder.h"
#include "compiler/ir/Material.h"

namespace mxc::glsl {

/// The files written beside the interface, named as the JSON refers to them (relative to it).
struct InterfaceFiles {
  std::string shader;  ///< the material's SPIR-V ("default.spv")
  std::string vertex;  ///< the vertex stage's SPIR-V, raster shaders only ("default.vert.spv")
  std::string tables;  ///< the albedo tables file (--tables), empty when not written
  std::string documentFolder;  ///< absolute: texture files are named relative to it, as the document names them
};

/// The interface of `shader` (built for `kind` from `material`).
nlohmann::json shaderInterfaceJson(const ir::Material& material, const MaterialShader& shader, ShaderKind kind,
                                   const InterfaceFiles& files);

/// The albedo tables the shaders sample (binding kTablesBinding), as the file `--tables` writes:
/// the format of compiler/glsl/AlbedoTableFile.h.
std::string albedoTablesFile();
inline constexpr const char* kAlbedoTablesFileName = "mxc_albedo_tables.bin";

}  // namespace mxc::glsl
