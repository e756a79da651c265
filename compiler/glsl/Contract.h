#pragma once
/// \file
/// The contract between the generated shaders and the harness that runs them, kept in one
/// place: the lobe kinds and mode bits, the members of MxcLobe, the stage blocks (the raster
/// renderer's MxcView, the compute stages' MxcBatch) and their bindings, the limits and codes.
/// The GLSL declarations are generated from these tables (generatedLibraryFile: the files
/// under "generated/" that the shader library includes), and the C++ side writes blocks through
/// the same tables (BlockWriter), so a new member, lobe kind or code is one edit here.

#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/glsl/Bindings.h"

namespace mxc::glsl {

/// Bits of MxcLobe.mode (dielectric and Schlick lobes): which of reflection and transmission
/// the lobe carries, and whether transmission goes straight through (a thin sheet).
enum LobeMode : int { kModeReflect = 1, kModeTransmit = 2, kModeThinWall = 4 };

/// The GGX alpha below which a lobe is a perfect mirror or refraction (a delta): its f cos is 0
/// for every pair of directions but the specular ones, and sampling draws those exactly.
constexpr float kDeltaAlpha = 1e-4f;

/// Lights the raster renderer passes (MxcView.lightVector and lightRadiance).
constexpr uint32_t kMaxLights = 8;
/// local_size_x of the compute stages that run a material (eval, furnace, sample).
constexpr uint32_t kWorkGroupSize = 64;
/// local_size_x and _y of the albedo tables stage.
constexpr uint32_t kTablesGroupSize = 8;
/// The binding of the tables stage's output buffer (its own descriptor set).
constexpr uint32_t kTablesOutputBinding = 0;

/// The environment of the raster renderer, MxcView.counts.y.
enum class EnvironmentCode : int32_t { None = 0, White = 1, Sky = 2, Map = 3 };
/// The kinds of the raster renderer's lights, MxcView.lightVector[k].w.
enum class LightCode : int32_t { Directional = 0, Point = 1, Spot = 2 };

/// The specialization constants of the raster renderer's fragment stage: what a scene fixes for
/// a whole render, set when a pipeline is created (Vulkan 1.3, s. 10.9), so that the pipeline
/// drops the code of the environments, light kinds and light slots the scene does not have,
/// without compiling GLSL again (lavapipe runs both sides of every branch, masked, so that code
/// would otherwise run). Each one's default, kFromView, reads the choice from MxcView at run time
/// instead: the general shader (`--no-specialize`) is created without them.
///
/// Which choices are made where (docs/specialization.md): what the material fixes (lobe kinds,
/// transmission, absorbing media, thin film, procedural code) is compiled in by the back end;
/// what the scene fixes and a renderer may change between frames (the environment, the number of
/// lights and their kinds) is one of these constants.
constexpr uint32_t kEnvironmentConstantId = 0;  ///< MXC_ENVIRONMENT: an EnvironmentCode
constexpr uint32_t kLightCountConstantId = 1;   ///< MXC_LIGHT_COUNT: 0 to kMaxLights
constexpr uint32_t kLightKindsConstantId = 2;   ///< MXC_LIGHT_KINDS: bit LightCode set for each kind present
constexpr int32_t kFromView = -1;

/// The raster renderer's environment image (stages/mxc_environment.glsl) is its own descriptor
/// set, so that a material's set 0 does not change with the scene: the radiance (an RGBA32F
/// equirectangular image, repeating across, clamped down) and its sampling distribution (a
/// storage buffer: uvec4 size, then one vec4 per cell, runtime/EnvironmentDistribution.h).
constexpr uint32_t kEnvironmentSet = 1;
constexpr uint32_t kEnvironmentRadianceBinding = 0;
constexpr uint32_t kEnvironmentDistributionBinding = 1;
/// The output buffer of the environment sampling stage (stages/mxc_environment_sample.comp),
/// which reads the environment at set 0.
constexpr uint32_t kEnvironmentSampleOutputBinding = 2;

/// MaterialX texture address modes, as mxc_sample_image takes them (MXC_ADDRESS_*).
enum class AddressMode : int32_t { Constant = 0, Clamp = 1, Periodic = 2, Mirror = 3 };
/// MaterialX image `filtertype` as the shader library's codes (MXC_FILTER_*): linear (the
/// default, trilinear through the mip chain where the stage has derivatives), closest (the
/// nearest texel of the full-resolution level). "cubic" is sampled as linear, as MaterialX's
/// GLSL generator does.
enum class FilterMode : int32_t { Linear = 0, Closest = 1 };
/// What mxc_transform moves between object and world space (MXC_TRANSFORM_*).
enum class TransformKind : int32_t { Point = 0, Vector = 1, Normal = 2 };

/// The vertex attributes of the raster renderer: their locations in mxc_raster.vert
/// (generated) and in the pipeline's vertex input state (runtime/Renderer.cpp).
enum VertexAttribute : uint32_t { kAttributePosition = 0, kAttributeNormal = 1, kAttributeTangent = 2, kAttributeUv = 3 };

/// A member of a generated GLSL struct or uniform block.
struct Member {
  std::string_view type;  ///< GLSL: float, int, vec2, vec3, vec4, ivec4, uvec4, mat4
  std::string_view name;
  uint32_t count = 0;     ///< array length; 0 for a single value
  std::string_view comment;
  /// MxcLobe: the value a lobe has unless its kind or its layering sets another (GLSL).
  std::string_view initial = {};
  /// MxcLobe: the one lobe kind that reads the member ("HAIR": ir::lobeKindName), or empty for
  /// every kind. Such a member is declared only where MXC_HAS_<kind> is, and set only on lobes
  /// of that kind, so that the other materials' lobes do not carry it.
  std::string_view onlyFor = {};
};

/// MxcLobe, in declaration order.
std::span<const Member> lobeMembers();
/// MxcView: the camera, lights and environment of the raster renderer (binding kStageBinding).
std::span<const Member> viewMembers();
/// MxcBatch: the compute stages' sizes and seed (binding kStageBinding).
std::span<const Member> batchMembers();

/// Byte offsets of a block's members in the std140 layout (GLSL 4.50 s. 7.6.2.2), and its size.
struct Std140Layout {
  std::vector<uint32_t> offsets;
  uint32_t size = 0;
};
Std140Layout std140Layout(std::span<const Member> members);
/// std140 base alignment and size of a single value of a GLSL type.
void std140Type(std::string_view type, uint32_t& align, uint32_t& size);

/// Fills the bytes of a std140 block by member name, from the same table the GLSL is made of.
class BlockWriter {
 public:
  explicit BlockWriter(std::span<const Member> members);
  /// Writes `value` (a trivially copyable C++ value of the member's size: glm::vec4 for vec4,
  /// glm::mat4 for mat4, glm::ivec4 for ivec4, ...) into member `name`, element `index`.
  /// Throws std::logic_error for an unknown member or a wrong size (a mismatch of the tables).
  template <typename T>
  void set(std::string_view name, const T& value, uint32_t index = 0) {
    write(name, &value, sizeof(T), index);
  }
  const std::vector<uint8_t>& bytes() const { return bytes_; }

 private:
  void write(std::string_view name, const void* data, size_t size, uint32_t index);
  std::span<const Member> members_;
  Std140Layout layout_;
  std::vector<uint8_t> bytes_;
};

/// The GLSL of a generated library file ("generated/mxc_lobe.glsl", "generated/mxc_codes.glsl",
/// "generated/mxc_view_block.glsl", "generated/mxc_batch_block.glsl",
/// "generated/mxc_tables_stage.glsl", "generated/mxc_vertex_inputs.glsl",
/// "generated/mxc_environment_block.glsl"), or nullopt for any
/// other path.
std::optional<std::string> generatedLibraryFile(std::string_view path);

}  // namespace mxc::glsl
