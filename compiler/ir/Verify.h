#pragma once
/// \file
/// The IR verifier: the rules a material keeps between stages (after lowering and after every
/// pass), one error kind per broken rule, as naga's `valid/` module. The slot schema says which
/// slots each interface, medium and emission kind may hold, with their types, so a slot cannot
/// be reused with another meaning (the conical emitter once kept its angles in Roughness and
/// Exponent, and a generalized Schlick factor over it overwrote the outer angle).

#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "compiler/ir/Material.h"

namespace mxc::ir {

enum class VerifyRule : uint8_t {
  IndexInRange,       ///< a node, interface, medium or emission index points into its table
  ExpressionInRange,  ///< a parameter's expression exists, and its arguments come before it
  NodeShape,          ///< a scattering node has the children and parameters its kind uses, and no others
  Acyclic,            ///< the scattering graph from the root has no cycle
  SlotAllowed,        ///< a slot is in the schema of its interface, medium or emission kind
  SlotType,           ///< a slot's value has a type its schema allows
  ParamType,          ///< coverages, mix weights, tints and thin-film values have their types
};

std::string_view verifyRuleName(VerifyRule rule);

struct VerifyError {
  VerifyRule rule;
  std::string message;
};

/// A slot a kind may hold, with the types its value may have.
struct SlotSpec {
  Slot slot;
  std::span<const Type> types;
};

std::span<const SlotSpec> slotSchema(InterfaceKind kind);
std::span<const SlotSpec> slotSchema(const Medium& medium);
std::span<const SlotSpec> slotSchema(Emission::Kind kind);

/// Every broken rule of the material (empty when it is well-formed).
std::vector<VerifyError> verify(const Material& m);

/// Thrown by the pass manager when a request asks for verification and a stage broke a rule:
/// a compiler bug, named with the stage that left the IR broken.
class VerifyFailure : public std::logic_error {
 public:
  VerifyFailure(const std::string& stage, const Material& m, const std::vector<VerifyError>& errors);
};

}  // namespace mxc::ir
