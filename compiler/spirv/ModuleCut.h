#pragma once
/// \file
/// One material's module cut from a module compiled for several, in the same canonical form as
/// a module compiled for it alone, so that a batch writes the bytes a single compile writes.
///
/// Materials that share a shader library (the same GLSL but for the body of their
/// `mxc_material_closure`) compile as one shader: each material's function renamed
/// (`mxc_material_closure_m<k>`) and a forwarder under the library's name that calls them all.
/// glslang parses the library once and SPIRV-Tools validates the module once; each material's
/// module is then cut from it:
///  - calls of the forwarder call the material's function (the two have one function type: the
///    same GLSL signature), which takes the forwarder's name;
///  - what the entry point no longer reaches (the forwarder, the other materials' functions and
///    their types and constants, names and decorations of removed IDs) is removed;
///  - capabilities that only removed code needed are removed (those the cut knows how to
///    decide; a module declaring any other, or an OpExtension, is refused, and its materials
///    compile alone).
/// None of these can make a valid module invalid: no remaining instruction refers to a removed
/// ID, and a call keeps its argument and result types.
///
/// The cut module, and a module compiled for one material alone (the same function with no
/// forwarder), are written in one canonical form: global types, constants and variables in the
/// order the code first uses them (operands before the instruction using them), IDs numbered in
/// the order they are defined or first used, names and decorations sorted by the ID they name,
/// the entry point's interface by ID. Both therefore depend only on what the module contains,
/// not on which other materials were compiled beside it.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mxc::spirv {

struct CutRequest {
  /// The function (by the name before its parameter list) whose callers are redirected to
  /// `member`; empty for a module of one material, which is only put in canonical form.
  std::string forwarder;
  /// The function that takes the forwarder's place and name.
  std::string member;
};

/// A module parsed once (SPIRV-Tools' parser says which operands are IDs) and cut as many
/// times as a group has members.
class ModuleCutter {
 public:
  /// `module` as glslang wrote it; a module holding an instruction the cut does not handle (a
  /// decoration group, OpDecorateId, OpLine) makes every cut() fail, saying so.
  explicit ModuleCutter(const std::vector<uint32_t>& module);
  ~ModuleCutter();
  ModuleCutter(const ModuleCutter&) = delete;
  ModuleCutter& operator=(const ModuleCutter&) = delete;

  /// The module of `request.member`, in canonical form; nullopt with `error` saying why when
  /// the module cannot be cut (see the constructor, and the capabilities and extensions above).
  std::optional<std::vector<uint32_t>> cut(const CutRequest& request, std::string& error) const;

  struct Parsed;  ///< the instructions, in flat arrays (defined in ModuleCut.cpp)

 private:
  std::unique_ptr<Parsed> parsed_;
};

/// ModuleCutter(module).cut(request, error).
std::optional<std::vector<uint32_t>> cutModule(const std::vector<uint32_t>& module, const CutRequest& request,
                                               std::string& error);

}  // namespace mxc::spirv
