#pragma once
/// \file
/// GLSL to SPIR-V with glslang (used as a library), SPIR-V validation and optimisation with
/// SPIRV-Tools. Errors in generated GLSL are mapped back to the document element that produced
/// the failing line.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "compiler/common/Diagnostic.h"

namespace mxc::spirv {

enum class Stage : uint8_t { Vertex, Fragment, Compute };

std::string_view stageName(Stage stage);

/// GLSL source with, for error mapping, the document location each generated line came from.
struct GlslSource {
  std::string text;
  Stage stage = Stage::Fragment;
  std::string name;  ///< for messages: "material Glass (fragment)"
  /// origins[i] is where line i + 1 of `text` came from (invalid for library code).
  std::vector<SourceLocation> origins;
};

/// The resource interface of a module, from glslang's reflection: what a harness must bind
/// and fill to run GLSL that another generator wrote (MaterialX's, for the comparison).
struct Reflection {
  enum class Scalar : uint8_t { Float, Int, UInt, Bool, Sampler, Other };
  struct Block {
    std::string name;
    int binding = -1;
    int size = 0;  ///< bytes (std140)
  };
  struct Member {
    std::string name;  ///< as reflection spells it: "u_viewPosition", "u_lightData[0].direction"
    int block = -1;    ///< index into blocks
    int offset = 0;
    Scalar scalar = Scalar::Float;
    int components = 1;  ///< vector size, or rows x columns of a matrix
    int columns = 1;     ///< > 1 for a matrix (columns are 16-byte aligned in std140)
    int arraySize = 1;
    int arrayStride = 0;
  };
  struct Sampler {
    std::string name;
    int binding = -1;
  };
  struct Input {
    std::string name;
    int location = -1;
    int components = 1;
  };
  std::vector<Block> blocks;
  std::vector<Member> members;
  std::vector<Sampler> samplers;
  std::vector<Input> inputs;
};

struct CompileOptions {
  bool optimize = false;  ///< run SPIRV-Tools' performance passes
  /// When set, filled with the module's live blocks (every member of each, used or not),
  /// samplers and, for a vertex stage, its inputs.
  Reflection* reflection = nullptr;
  /// With `optimize`: specialization constants (SpecId, value) fixed before the passes, so that
  /// they fold what the values decide, as a pipeline created with those values can.
  std::vector<std::pair<uint32_t, int32_t>> specialization;
  /// glslang reads the text trimmed (spirv/SourceTrim.h): the same module, parsed faster. Off
  /// only to check that claim.
  bool trimSource = true;
};

/// Compiles GLSL (as mxc writes it: 4.00 with ARB extensions, compute 4.40) for Vulkan 1.1 / SPIR-V 1.3 and validates the module. On failure the
/// errors go to `diagnostics` (at the document element behind the failing line when known)
/// and nullopt is returned.
std::optional<std::vector<uint32_t>> compile(const GlslSource& source, const CompileOptions& options,
                                             Diagnostics& diagnostics);

/// The module with every specialization constant fixed at its default and the expressions of
/// them folded (SPIRV-Tools' freeze and fold passes): for a translator that reads no
/// specialization (naga). nullopt (and `error`) when the passes fail.
std::optional<std::vector<uint32_t>> freezeSpecialization(const std::vector<uint32_t>& words, std::string& error);

/// The shading languages whose text glslang's front ends can check.
enum class Language : uint8_t { OpenGl, OpenGlEs, Hlsl };
/// Checks a stage written in `language` (by a translator) with glslang's front end: GLSL and
/// ESSL are parsed and linked as an OpenGL (ES) driver's compiler would; HLSL is compiled to
/// SPIR-V for Vulkan 1.1 from `entryPoint` and the module validated. Returns glslang's log when
/// the text is rejected, "" when it is accepted.
std::string checkSource(const std::string& text, Language language, Stage stage, const std::string& entryPoint);

/// Validates a SPIR-V module for Vulkan 1.1; returns the validator's message, or "" when valid.
std::string validate(const std::vector<uint32_t>& words);

/// Number of instructions of a module (every word count/opcode header after the 5-word header).
size_t instructionCount(const std::vector<uint32_t>& words);

/// Disassembles a module (for --spirv-asm output and for tests).
std::string disassemble(const std::vector<uint32_t>& words);

}  // namespace mxc::spirv
