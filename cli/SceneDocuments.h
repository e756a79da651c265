#pragma once
/// \file
/// The documents of a scene compiled to IR, and the two lookups `mxc render` and `mxc compile`
/// of a scene both make in them: a material by name, and the assignments of a look.

#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "cli/MaterialPipeline.h"
#include "cli/Scene.h"
#include "compiler/document/Document.h"

namespace mxc::cli {

class SceneDocuments {
 public:
  explicit SceneDocuments(Session& session) : session_(session) {}

  /// Runs the compiler to IR on each document of `scene`, with `options` (every material: the
  /// scene chooses; its accuracy tier when it states one) and the request's `stage` and
  /// `optimize`, compiling through `shaderCache` when given (a batch's; else the session's).
  /// Returns kOk, or the exit code to stop with (diagnostics printed).
  int load(const Scene& scene, MaterialOptions options, glsl::ShaderKind stage, bool optimize,
           target::Target target = target::Target::Spirv, ShaderCache* shaderCache = nullptr);

  std::vector<MaterialPipeline*> pipelines() const;

  struct Found {
    MaterialPipeline* pipeline = nullptr;
    const ir::Material* material = nullptr;
  };
  /// The one material named `name` in the documents, or why there is none ("no document of
  /// the scene has a material named 'X'", "more than one document has ...").
  std::variant<Found, std::string> find(const std::string& name) const;

  /// The materials `scene` uses, for `mxc compile` of it: those its objects name, then those its
  /// look assigns, in order, each once; or why one cannot be had (a look no document has, a
  /// name no document or several have).
  std::variant<std::vector<Found>, std::string> used(const Scene& scene) const;

  /// Calls `visit` with every <materialassign> of the looks named `look`, document by document
  /// in order; false when no document has such a look.
  bool forEachAssign(const std::string& look, const std::function<void(const doc::MaterialAssign&)>& visit) const;

 private:
  Session& session_;
  std::vector<std::unique_ptr<MaterialPipeline>> pipelines_;
};

}  // namespace mxc::cli
