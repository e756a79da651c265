#pragma once
/// \file
/// The scattering part of the IR: slabs with explicit interfaces, media and coverage, mixes,
/// and emission, after the OpenPBR formalism (OpenPBR 1.1 "Formalism": Slab(f, V), layer,
/// mix; and the seed commentary, sections 4.1 and 4.2).
///
/// A Slab is an interface BSDF `top` over an optional medium, on an optional `base` (another
/// scattering node), present over `coverage` of the surface:
///   Slab{top, medium, base, coverage} == mix(base, layer(base, Slab(top, medium)), coverage).
/// MaterialX's `layer(top, base * lerp(...))` lowers to it. A Slab without a base is the
/// bottom of its stack: an opaque interface, or a bulk medium (a semi-infinite one is
/// Medium::Extent::Bulk). A Mix is a statistical mixture of two materials (OpenPBR "Mixing").
/// The interface, medium, emission and node tables of a Material are referred to by index.

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "compiler/common/SourceFile.h"
#include "compiler/ir/Expr.h"

namespace mxc::ir {

using Index = uint32_t;
constexpr Index kNone = UINT32_MAX;

/// Where a value of the IR came from: the document element (usually an input, or the nodedef
/// input for a default) and the input's name, for error messages, `inspect`, and the effect
/// summary ("coat kept by coat_weight at line 12").
struct Origin {
  SourceLocation location;
  std::string_view input;  ///< the input name, or the node name for structure
};

/// A value of the IR with its origin. `value` is kNoExpr when absent.
struct Param {
  ExprId value = kNoExpr;
  Origin origin;
  bool present() const { return value != kNoExpr; }
};

/// The named parameters of interfaces, media and emission. Each kind documents which it uses.
enum class Slot : uint8_t {
  Ior,               ///< float: refractive index of the medium below (OpenPBR specular_ior, coat_ior)
  FresnelScale,      ///< float: multiplier of the normal-incidence reflectivity (OpenPBR specular_weight, eq. modulated_ior)
  ReflectionTint,    ///< vec3: tint of the reflection from above (specular_color); non-physical
  TransmissionTint,  ///< vec3: tint of the transmission (transmission_color at depth 0); non-physical
  Alpha,             ///< vec2: GGX alpha along tangent and bitangent (OpenPBR eq. openpbr-anisotropy-formula)
  Normal,            ///< vec3: shading normal
  Tangent,           ///< vec3: tangent (anisotropy direction)
  Color,             ///< vec3: albedo (diffuse, sheen, diffuse sheet) or emission colour
  Roughness,         ///< float: diffuse (Oren-Nayar sigma) or sheen roughness
  F0,                ///< vec3: conductor reflectivity at normal incidence (Schlick)
  F82,               ///< vec3: F82-tint edge colour (OpenPBR "Metal", Kutz 2021)
  F90,               ///< vec3: reflectivity at grazing incidence (generalized Schlick)
  Exponent,          ///< float: Schlick exponent
  Extinction,        ///< vec3: conductor extinction k (complex IOR n + ik)
  ComplexIor,        ///< vec3: conductor n
  Anisotropy,        ///< float: phase-function g (media) or reflection/transmission split (diffuse sheet)
  Absorption,        ///< vec3: absorption coefficient mu_a (1/length)
  Scattering,        ///< vec3: scattering coefficient mu_s (1/length)
  Thickness,         ///< float: medium thickness (length), or thin-film thickness (nm)
  ObservedAlbedo,    ///< vec3: multiple-scattering albedo a user asked for (subsurface_color)
  AbbeNumber,        ///< float: dispersion (OpenPBR "Translucent base"); absent or 0 means none
  Darkening,         ///< float: coat darkening control (OpenPBR "Darkening")
  BaseAlbedo,        ///< vec3: a coat's or fuzz's estimate of the albedo under it, E_b (OpenPBR "Darkening")
  BaseRoughness,     ///< float: a coat's estimate of the roughness under it, r_b (OpenPBR eq. base_roughness_estimate)
  BaseIor,           ///< float: a coat's estimate of the IOR of the medium its base's diffuse light starts in (specular_ior)
  Weight,            ///< float: a lobe scale MaterialX gives but physics does not (pbrlib `weight`)
  Luminance,         ///< float: emission luminance (nits)
  InnerAngle,        ///< float: conical emission, full inside this half-angle (degrees)
  OuterAngle,        ///< float: conical emission, none outside this half-angle (degrees)
  InternalReflectionTint,  ///< vec3: hair: tint of the paths reflected inside the fibre (TRT and longer)
  FibreRoughnessR,    ///< vec2: hair R lobe: longitudinal variance v, azimuthal logistic scale s / sqrt(pi/8) (Chiang 2016 eqs. 7-8)
  FibreRoughnessTT,   ///< vec2: hair TT lobe, as FibreRoughnessR
  FibreRoughnessTRT,  ///< vec2: hair TRT lobe (and longer paths), as FibreRoughnessR
  CuticleTilt,        ///< float: hair: tilt of the cuticle scales (radians; Chiang 2016 s. 4.1 alpha)
  Count
};

std::string_view slotName(Slot slot);
/// The value a slot has when it is absent, for slots whose absence evaluators read as a
/// default (FresnelScale 1, tints 1, AbbeNumber 0 = no dispersion, Weight 1, F82 and F90 1,
/// Exponent 5, Absorption, Scattering and Anisotropy 0); nullopt for slots without one.
std::optional<float> slotDefault(Slot slot);

/// A small ordered set of slots with their parameters.
class Slots {
 public:
  void set(Slot slot, Param param);
  const Param* find(Slot slot) const;
  Param* find(Slot slot);
  /// The expression in a slot, or kNoExpr.
  ExprId value(Slot slot) const {
    const Param* p = find(slot);
    return p ? p->value : kNoExpr;
  }
  void erase(Slot slot);
  const std::vector<std::pair<Slot, Param>>& all() const { return items_; }
  std::vector<std::pair<Slot, Param>>& all() { return items_; }

 private:
  std::vector<std::pair<Slot, Param>> items_;
};

/// Interface BSDFs. One dielectric carries reflection and transmission together (the seed
/// commentary, 4.1: no scatter_mode split).
enum class InterfaceKind : uint8_t {
  Dielectric,           ///< GGX dielectric (Walter 2007): Ior, FresnelScale, ReflectionTint, TransmissionTint, Alpha, Normal, Tangent, AbbeNumber
  Conductor,            ///< GGX conductor, complex IOR: ComplexIor, Extinction, Alpha, Normal, Tangent
  Schlick,               ///< GGX with a generalized Schlick / F82-tint Fresnel (Kutz 2021), reflection and optional transmission: F0, F82, F90, Exponent, Alpha, Normal, Tangent
  Diffuse,              ///< Oren-Nayar (Fujii) or EON: Color, Roughness, Normal
  Burley,               ///< Burley diffuse: Color, Roughness, Normal
  DiffuseTransmission,  ///< diffuse transmission (MaterialX translucent_bsdf): Color, Normal
  DiffuseSheet,         ///< thin-walled subsurface: reflection S(1-g)/2, transmission S(1+g)/2 (OpenPBR "Thin-walled mode"): Color, Anisotropy, Roughness, Normal
  Sheen,                ///< sheen / fuzz, index-matched, no Fresnel: Color, Roughness, Normal, BaseAlbedo (under a fuzz: for its darkening)
  Hair,                 ///< a hair fibre (Chiang 2016): Ior, ReflectionTint (R), TransmissionTint (TT), InternalReflectionTint (TRT), FibreRoughnessR/TT/TRT, CuticleTilt, Absorption (per unit fibre radius), Normal, Tangent (along the fibre); not layerable
};

std::string_view interfaceKindName(InterfaceKind kind);

/// Which dielectric reflection/transmission lobes a pbrlib node asked for. Lowering merges an
/// R node layered over a T node of the same interface into RT.
enum class ScatterMode : uint8_t { R, T, RT };

/// Diffuse model variants.
enum class DiffuseModel : uint8_t {
  OrenNayar,  ///< Fujii's Oren-Nayar (MaterialX oren_nayar_diffuse_bsdf)
  EON,        ///< energy-preserving Oren-Nayar (Portsmouth 2024; OpenPBR "Glossy-diffuse")
};

/// Sheen model variants.
enum class SheenModel : uint8_t {
  ContyKulla,  ///< Estevez & Kulla 2017 (Standard Surface sheen)
  Zeltner,     ///< Zeltner 2022 LTC fuzz (OpenPBR "Fuzz")
};

/// How the IOR of an interface relates to its neighbours.
enum class IorReference : uint8_t {
  MediumAbove,  ///< absolute IOR; the relative IOR follows from the slab above (OpenPBR)
  Ambient,      ///< relative to the ambient medium, as a pbrlib node evaluates it on its own
};

/// The Fresnel modifier of a thin film on an interface (OpenPBR "Thin-film iridescence":
/// it modifies the Fresnel factor; it is not a slab). Coverage blends with and without.
struct ThinFilm {
  Param thickness;  ///< nanometres
  Param ior;
  Param coverage;
  Origin origin;  ///< the input that switches the film on (thin_film_weight), for the effect summary
  bool present() const { return thickness.present(); }
};

struct Interface {
  InterfaceKind kind = InterfaceKind::Dielectric;
  ScatterMode scatter = ScatterMode::RT;  ///< Dielectric and Schlick
  DiffuseModel diffuseModel = DiffuseModel::OrenNayar;
  SheenModel sheenModel = SheenModel::ContyKulla;
  IorReference iorReference = IorReference::MediumAbove;
  Slots slots;
  ThinFilm thinFilm;
  Origin origin;  ///< the BSDF node, or the surface node for a shading model
};

/// A homogeneous medium (VDF): absorption, scattering and a Henyey-Greenstein phase function.
struct Medium {
  enum class Extent : uint8_t {
    Bulk,      ///< semi-infinite (V-infinity): the bottom of its stack
    Finite,    ///< of a thickness (Slot::Thickness); coat media are finite with unit thickness
    ThinWall,  ///< an infinitesimal sheet seen from both sides (thin-walled mode)
  };
  Extent extent = Extent::Bulk;
  Slots slots;  ///< Absorption, Scattering, Anisotropy, Thickness, ObservedAlbedo
  Origin origin;
};

std::string_view extentName(Medium::Extent extent);

/// An emission distribution function. Attached to the slab it comes from (OpenPBR "Emission":
/// under the coat), through a ScatterKind::Emissive node.
struct Emission {
  enum class Kind : uint8_t { Uniform, Conical };
  Kind kind = Kind::Uniform;
  Slots slots;  ///< Color (radiance or luminance-weighted colour); Conical: Normal, InnerAngle, OuterAngle;
                ///< a generalized Schlick factor on either: F0, F90, Exponent
  Origin origin;
};

enum class ScatterKind : uint8_t {
  Slab,      ///< top interface, medium, base, coverage
  Mix,       ///< a, b, weight: (1 - weight) a + weight b
  Add,       ///< a + b: not energy-bounded in general (pbrlib add)
  Tint,      ///< a scaled by weight (a colour): MaterialX multiply(BSDF, colour); bounded only when weight <= 1
  Emissive,  ///< a, and the emission `emission` from under a's top (emitted light crosses the slabs above)
  Ambient,   ///< no surface: the ambient medium (OpenPBR Slab(empty)); what opacity mixes with
  Absorber,  ///< no light leaves: a black surface
};

std::string_view scatterKindName(ScatterKind kind);

/// A node of the scattering tree.
struct ScatterNode {
  ScatterKind kind = ScatterKind::Slab;
  Index top = kNone;       ///< Slab: interface (kNone for an index-matched slab with only a medium)
  Index medium = kNone;    ///< Slab: medium under the interface
  Index base = kNone;      ///< Slab: the material under this slab
  Param coverage;          ///< Slab: presence weight (absent means 1)
  Index a = kNone;         ///< Mix, Add, Tint, Emissive: first child
  Index b = kNone;         ///< Mix, Add: second child
  Param weight;            ///< Mix: weight of b; Tint: colour
  Index emission = kNone;  ///< Emissive
  Origin origin;
};

}  // namespace mxc::ir
