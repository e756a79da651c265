#include "compiler/glsl/ClosureEmitter.h"

#include <fmt/format.h>

#include "compiler/glsl/AlbedoScaling.h"
#include "compiler/glsl/SlabWalk.h"

namespace mxc::glsl {

const LayeringTier& layeringTier(Accuracy accuracy) {
  static const AlbedoScaling albedoScaling;
  static const SlabWalk slabWalk;
  switch (accuracy) {
    // Both reduce the slab tree to lobes by albedo scaling; they differ in the library code
    // the lobes run (MXC_ACCURACY_*: fitted or tabulated albedos, multiple scattering).
    case Accuracy::Fast:
    case Accuracy::Balanced: return albedoScaling;
    // The stacks themselves, walked by Monte Carlo.
    case Accuracy::Reference: return slabWalk;
  }
  return albedoScaling;
}

Closure buildClosure(const ir::Material& material, const ExprEmitter& exprs, Accuracy accuracy) {
  Closure out;
  out.lines.add("  c.emission = vec3(0.0);");
  out.lines.add("  c.transparency = vec3(0.0);");
  layeringTier(accuracy).layers(material, exprs, out);
  out.lines.add(fmt::format("  c.count = {};", out.lobes));
  out.lines.add("  mxc_closure_prepare(c, wo);");
  return out;
}

}  // namespace mxc::glsl
