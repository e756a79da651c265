#pragma once
/// \file
/// What an IR interface is as a lobe of the shader library: its MxcLobe members (kind,
/// parameters, relative IOR, thin film). Shared by every accuracy tier: what a lobe is does not
/// depend on how the layers combine; the tier gives its mode (which of reflection and
/// transmission it carries) and its weight.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "compiler/glsl/ClosureValues.h"
#include "compiler/glsl/ExprEmitter.h"

namespace mxc::glsl {

/// The members of one MxcLobe with the GLSL of their values: each starts at the contract's
/// initial value (compiler/glsl/Contract.h) and is set by name.
class LobeFields {
 public:
  LobeFields();
  void set(std::string_view member, std::string value);
  const std::vector<std::pair<std::string_view, std::string>>& values() const { return values_; }

 private:
  std::vector<std::pair<std::string_view, std::string>> values_;
};

/// What lies above a lobe that its mapping reads: the dielectric coat over it (its IOR and
/// coverage, for the relative IOR: OpenPBR eq. specular_ior_ratio) and the absorbing media
/// (their optical depth, applied along wi, and their IOR).
struct Above {
  ClosureValues::Id coatIor;
  ClosureValues::Id coatCoverage;
  ClosureValues::Id tau;
  ClosureValues::Id tauEta;
  /// The darkening the coat's layering applies to what is under it (vec3; 1 without one) and
  /// its coat_darkening control (mxc_coat_darkening), for a layer that darkens otherwise.
  ClosureValues::Id darkening;
  ClosureValues::Id darkeningControl;
  /// The nearest dielectric interface above (its IOR and coverage; coverage 0: none), for a
  /// medium under it without an interface of its own (Standard Surface's subsurface).
  ClosureValues::Id interfaceIor;
  ClosureValues::Id interfaceCoverage;
  /// The ambient medium: IOR 1, no coat, no absorption.
  static Above ambient(ClosureValues& v) {
    return {v.constant(1.0f), v.constant(0.0f), v.vec3(0.0f), v.constant(1.0f),
            v.vec3(1.0f),     v.constant(0.0f), v.constant(1.0f), v.constant(0.0f)};
  }
};

/// An MxcLobe for an interface of `material`.
LobeFields mapInterface(ClosureValues& values, const ir::Material& material, const ir::Interface& interface,
                        const Above& above, int mode, ClosureValues::Id weight);

/// The GLSL of the radiance an emission sends towards wo, scaled by `weight`: its colour, the
/// conical falloff and the generalized Schlick factor where it has them. Shared by every tier:
/// where the emission sits is the tier's; what it emits is not.
std::string emittedRadiance(ClosureValues& values, const ir::Emission& emission, ClosureValues::Id weight);

/// The GLSL of a lobe's normal: the slot's value normalised, unless it is the geometry's unit
/// normal (a shading normal from a document need not be unit length: geometry_normal = 0.9,0,0.1).
std::string unitNormal(const ClosureValues& values, const ir::Material& material, const ir::Param* normal);

/// The weight of an interface's lobe reached with `weight`: times the interface's own weight
/// slot where it has one (what mapInterface sets as the lobe's weight).
ClosureValues::Id lobeWeight(ClosureValues& values, const ir::Interface& interface, ClosureValues::Id weight);

/// Appends `MxcLobe <name>;` and one assignment per member but `skip` (which the caller assigns
/// later). The film member is located at `filmAt` when valid, everything else at `at`.
void declareLobe(Lines& out, const std::string& name, const LobeFields& fields, SourceLocation at,
                 SourceLocation filmAt = {}, std::string_view skip = {});
/// declareLobe, then `c.lobes[<index>] = <name>;`.
void writeLobe(Lines& out, const std::string& name, int index, const LobeFields& fields, SourceLocation at,
               SourceLocation filmAt = {});

}  // namespace mxc::glsl
