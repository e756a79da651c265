#pragma once
/// \file
/// What a material uses, computed once from its IR after the passes, in one typed vocabulary
/// (as pbrt-v4's BxDF::Flags() combines its children's): the lobe kinds the shader library must
/// compile, and the effects a user sees named in `inspect` (each with the input that keeps it).
/// The back end's guards and includes, the effect summary and the scene analysis all read it.

#include <array>
#include <string_view>

#include "compiler/common/FlagSet.h"
#include "compiler/ir/Scatter.h"

namespace mxc::ir {

struct Material;

/// The BSDF lobes of the shader library (compiler/glsl/library/mxc_lobes.glsl): the GLSL
/// constants MXC_LOBE_<NAME> and the guards MXC_HAS_<NAME> are generated from this list.
enum class LobeKind : uint8_t {
  Dielectric,   ///< GGX dielectric, reflection and transmission (Walter 2007)
  Conductor,    ///< GGX conductor with a complex IOR
  Schlick,      ///< GGX with a generalized Schlick / F82-tint Fresnel
  Diffuse,      ///< Fujii's Oren-Nayar
  EON,          ///< energy-preserving Oren-Nayar (Portsmouth 2024)
  Burley,       ///< Burley diffuse
  Translucent,  ///< diffuse transmission
  Sheet,        ///< thin-walled diffuse reflection and transmission
  Sheen,        ///< Estevez & Kulla 2017
  Fuzz,         ///< Zeltner et al. 2022 (OpenPBR fuzz)
  Hair,         ///< Chiang et al. 2016 fibre scattering
  Count
};

/// "DIELECTRIC", "EON", ...: the suffix of MXC_LOBE_* and MXC_HAS_*.
std::string_view lobeKindName(LobeKind kind);
/// The lobe that evaluates an interface.
LobeKind lobeKindOf(const Interface& interface);

/// The effects of `inspect`'s summary, in the order of their names.
enum class Effect : uint8_t {
  Anisotropy,
  Coat,
  Diffuse,
  DiffuseTransmission,
  Dispersion,
  Emission,
  Fuzz,
  Hair,
  Metal,
  Opacity,
  Sheen,
  Specular,
  Subsurface,
  ThinFilm,
  ThinWalled,
  Transmission,
  UnboundedSum,  ///< an add or tint of BSDFs that is not energy-bounded (see the notes)
  Volume,
  Count
};

/// "anisotropy", "coat", "diffuse_transmission", ...
std::string_view effectName(Effect effect);

struct Features {
  FlagSet<LobeKind> lobes;  ///< every lobe kind a closure of the material can hold
  FlagSet<Effect> effects;
  bool thinFilm = false;      ///< an interface has a thin film (the shader library's film code)
  bool emission = false;      ///< emission reaches the surface
  bool transparency = false;  ///< part of the surface is the ambient medium (opacity)

  /// The input that keeps an effect (a coverage, a weight, a colour), for the summary.
  const Origin& origin(Effect effect) const { return origins[static_cast<size_t>(effect)]; }
  std::array<Origin, static_cast<size_t>(Effect::Count)> origins{};
};

/// The features of a material as its IR stands (reachable nodes only).
Features computeFeatures(const Material& m);

}  // namespace mxc::ir
