#include "compiler/target/CrossCompiler.h"

#include <exception>
#include <memory>

#include <fmt/format.h>
#include <spirv_cross/spirv_glsl.hpp>
#include <spirv_cross/spirv_hlsl.hpp>
#include <spirv_cross/spirv_msl.hpp>

namespace mxc::target {

namespace {

using spirv_cross::Compiler;
using spirv_cross::Resource;

/// Every descriptor of the module, with its set and binding.
struct Bound {
  spirv_cross::ID id;
  uint32_t set, binding;
};

std::vector<Bound> descriptors(const Compiler& compiler) {
  const spirv_cross::ShaderResources resources = compiler.get_shader_resources();
  std::vector<Bound> out;
  for (const auto* list : {&resources.uniform_buffers, &resources.storage_buffers, &resources.sampled_images,
                           &resources.separate_images, &resources.separate_samplers}) {
    for (const Resource& r : *list) {
      out.push_back({r.id, compiler.get_decoration(r.id, spv::DecorationDescriptorSet),
                     compiler.get_decoration(r.id, spv::DecorationBinding)});
    }
  }
  return out;
}

/// The placement of the module's descriptor at (set, binding); null when the interface has none.
const Placement* placementAt(const std::vector<Placement>& placements, uint32_t set, uint32_t binding) {
  for (const Placement& p : placements) {
    if (p.resource.set == set && p.resource.binding == binding) return &p;
  }
  return nullptr;
}

/// Calls `place` with each descriptor of the module and its placement; false (and `error`) when
/// the interface has no placement for one (a bug of the interface: reported, not guessed).
template <typename Place>
bool placeEach(const Compiler& compiler, const std::vector<Placement>& placements, std::string& error, Place place) {
  for (const Bound& b : descriptors(compiler)) {
    const Placement* p = placementAt(placements, b.set, b.binding);
    if (!p) {
      error = fmt::format("the shader interface has no descriptor at set {} binding {}", b.set, b.binding);
      return false;
    }
    place(b, *p);
  }
  return true;
}

bool placeGlsl(spirv_cross::CompilerGLSL& compiler, const std::vector<Placement>& placements, std::string& error) {
  return placeEach(compiler, placements, error, [&](const Bound& b, const Placement& p) {
    compiler.unset_decoration(b.id, spv::DecorationDescriptorSet);
    compiler.set_decoration(b.id, spv::DecorationBinding, static_cast<uint32_t>(p.binding));
  });
}

bool placeMsl(spirv_cross::CompilerMSL& compiler, const std::vector<Placement>& placements, std::string& error) {
  return placeEach(compiler, placements, error, [&](const Bound& b, const Placement& p) {
    spirv_cross::MSLResourceBinding binding;
    binding.stage = compiler.get_execution_model();
    binding.desc_set = b.set;
    binding.binding = b.binding;
    binding.msl_buffer = static_cast<uint32_t>(std::max(p.buffer, 0));
    binding.msl_texture = static_cast<uint32_t>(std::max(p.texture, 0));
    binding.msl_sampler = static_cast<uint32_t>(std::max(p.sampler, 0));
    compiler.add_msl_resource_binding(binding);
  });
}

bool placeHlsl(spirv_cross::CompilerHLSL& compiler, const std::vector<Placement>& placements, std::string& error) {
  return placeEach(compiler, placements, error, [&](const Bound& b, const Placement& p) {
    spirv_cross::HLSLResourceBinding binding;
    binding.stage = compiler.get_execution_model();
    binding.desc_set = b.set;
    binding.binding = b.binding;
    // Each class's register at the placement's number, in space `set`; SPIRV-Cross takes the
    // one the resource's type calls for.
    for (auto* slot : {&binding.cbv, &binding.srv, &binding.uav, &binding.sampler}) {
      slot->register_space = b.set;
      slot->register_binding = static_cast<uint32_t>(p.binding);
    }
    compiler.add_hlsl_resource_binding(binding);
  });
}

}  // namespace

std::vector<std::pair<uint32_t, uint32_t>> descriptorBindings(const std::vector<uint32_t>& words) {
  std::vector<std::pair<uint32_t, uint32_t>> out;
  try {
    const Compiler reflection(words);
    for (const Bound& b : descriptors(reflection)) out.emplace_back(b.set, b.binding);
  } catch (const std::exception&) {
    out.clear();  // not a module SPIRV-Cross can read: nothing is known of it
  }
  return out;
}

bool crossCompile(const std::vector<uint32_t>& words, Target target, const std::vector<Placement>& placements,
                  Translation& out, std::string& error) {
  // SPIRV-Cross reports what it cannot translate by throwing spirv_cross::CompilerError.
  try {
    std::unique_ptr<spirv_cross::CompilerGLSL> compiler;
    switch (target) {
      case Target::Glsl:
      case Target::Essl: {
        auto glsl = std::make_unique<spirv_cross::CompilerGLSL>(words);
        spirv_cross::CompilerGLSL::Options options = glsl->get_common_options();
        options.es = target == Target::Essl;
        options.version = options.es ? 320 : 450;
        options.vulkan_semantics = false;
        // mxc's shaders compute in single precision throughout (physics-notes.md's figures
        // assume it); ES would otherwise default fragment floats to mediump.
        options.fragment.default_float_precision = spirv_cross::CompilerGLSL::Options::Highp;
        options.fragment.default_int_precision = spirv_cross::CompilerGLSL::Options::Highp;
        glsl->set_common_options(options);
        if (!placeGlsl(*glsl, placements, error)) return false;
        compiler = std::move(glsl);
        break;
      }
      case Target::Msl: {
        auto msl = std::make_unique<spirv_cross::CompilerMSL>(words);
        spirv_cross::CompilerMSL::Options options = msl->get_msl_options();
        options.platform = spirv_cross::CompilerMSL::Options::macOS;
        options.set_msl_version(2, 1);
        msl->set_msl_options(options);
        if (!placeMsl(*msl, placements, error)) return false;
        compiler = std::move(msl);
        break;
      }
      case Target::Hlsl: {
        auto hlsl = std::make_unique<spirv_cross::CompilerHLSL>(words);
        spirv_cross::CompilerHLSL::Options options = hlsl->get_hlsl_options();
        options.shader_model = 60;
        hlsl->set_hlsl_options(options);
        if (!placeHlsl(*hlsl, placements, error)) return false;
        compiler = std::move(hlsl);
        break;
      }
      case Target::Spirv:
      case Target::Wgsl:
        error = fmt::format("SPIRV-Cross does not write {}", targetName(target));
        return false;
    }
    out.text = compiler->compile();
    const auto model = compiler->get_execution_model();
    out.entryPoint = compiler->get_cleansed_entry_point_name("main", model);
    return true;
  } catch (const std::exception& e) {
    error = fmt::format("SPIRV-Cross cannot translate the shader to {}: {}", targetName(target), e.what());
    return false;
  }
}

}  // namespace mxc::target
