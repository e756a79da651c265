#pragma once
/// \file
/// The scattering tree of a material to GLSL that fills an MxcClosure for a view direction:
/// the tree reduced to a weighted mixture of lobes, after OpenPBR 1.1 "Reduction to a mixture
/// of lobes" (albedo scaling, with view-dependent absorption through coat media).

#include <set>
#include <string>
#include <vector>

#include "compiler/glsl/ExprEmitter.h"

namespace mxc::glsl {

/// What the generated closure code needs from the shader library.
struct ClosureFeatures {
  std::set<std::string> lobeKinds;  ///< MXC_LOBE_* names used
  bool thinFilm = false;
  bool emission = false;
  bool transparency = false;
  int lobes = 0;  ///< MXC_MAX_LOBES
};

class ClosureEmitter {
 public:
  ClosureEmitter(const ir::Material& material, const ExprEmitter& exprs);

  /// The body of `void mxc_material_closure(in MxcGeometry g, vec3 wo, out MxcClosure c)`
  /// after the expression statements.
  const Lines& statements() const { return lines_; }
  const ClosureFeatures& features() const { return features_; }

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
  std::string var(const std::string& prefix);
  /// The GLSL of a lobe's normal, normalised unless it is the geometry's unit normal.
  std::string unitNormal(const ir::Param* normal) const;

  const ir::Material& m_;
  const ExprEmitter& x_;
  Lines lines_;
  ClosureFeatures features_;
  int counter_ = 0;
};

}  // namespace mxc::glsl
