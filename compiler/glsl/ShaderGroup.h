#pragma once
/// \file
/// One GLSL shader for materials whose shaders differ only in their `mxc_material_closure`
/// (MaterialShader::libraryKey): a batch compiles it once and cuts each material's module from
/// it (spirv/ModuleCut.h). A corpus batch cuts 59 of its 75 materials' modules from groups.

#include <string>
#include <vector>

#include "compiler/glsl/ShaderBuilder.h"

namespace mxc::glsl {

/// The name member `index` of a group gives its closure function.
std::string groupMemberFunction(size_t index);

/// The shader of the group: the first member's text with, in place of its closure function,
/// each member's (renamed groupMemberFunction(k)) and a forwarder under kClosureFunction that
/// calls them all (so that glslang, which drops functions nothing calls, compiles them all), and
/// in place of its texture declarations those of the member that reads the most textures (a
/// member's cut drops the ones it does not read). Every member must have the first's library key.
spirv::GlslSource groupSource(const std::vector<const MaterialShader*>& members);

}  // namespace mxc::glsl
