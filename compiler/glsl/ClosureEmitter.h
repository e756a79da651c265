#pragma once
/// \file
/// The scattering tree of a material to GLSL that fills an MxcClosure for a view direction:
/// the tree reduced to a weighted mixture of lobes, after OpenPBR 1.1 "Reduction to a mixture
/// of lobes" (albedo scaling, with view-dependent absorption through coat media).

#include <string>
#include <vector>

#include "compiler/glsl/ExprEmitter.h"

namespace mxc::glsl {

class LobeFields;

class ClosureEmitter {
 public:
  ClosureEmitter(const ir::Material& material, const ExprEmitter& exprs);

  /// The body of `void mxc_material_closure(in MxcGeometry g, vec3 wo, out MxcClosure c)`
  /// after the expression statements.
  const Lines& statements() const { return lines_; }
  /// How many lobes the closure holds (MXC_MAX_LOBES). Which kinds, and whether a thin film is
  /// used, the material's features say (ir::Features).
  int lobeCount() const { return lobes_; }

 private:
  /// What lies above a node: the dielectric coat over it (for its IOR) and absorbing media.
  struct Above {
    std::string coatIor = "1.0";       ///< IOR of the slab above (1: the ambient medium)
    std::string coatCoverage = "0.0";  ///< its coverage
    std::string tau = "vec3(0.0)";     ///< optical depth of absorbing media above
    std::string tauEta = "1.0";
  };

  void node(ir::Index index, const std::string& weight, const Above& above);
  void slab(const ir::ScatterNode& n, const std::string& weight, const Above& above);
  /// Emits the lobe of an interface; returns the GLSL variable holding the lobe.
  std::string lobe(ir::Index iface, const std::string& weight, const Above& above, int mode);
  /// Declares a lobe variable with `fields`, stores it in the closure; returns its name.
  std::string emitLobe(const LobeFields& fields, SourceLocation at, SourceLocation filmAt);
  std::string var(const std::string& prefix);
  /// The GLSL of a lobe's normal, normalised unless it is the geometry's unit normal.
  std::string unitNormal(const ir::Param* normal) const;

  const ir::Material& m_;
  const ExprEmitter& x_;
  Lines lines_;
  int lobes_ = 0;
  int counter_ = 0;
};

}  // namespace mxc::glsl
