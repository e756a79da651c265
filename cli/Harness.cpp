#include "cli/Harness.h"

#include <unistd.h>

#include <fmt/format.h>

namespace mxc::cli {


rt::VulkanContext* Device::context() {
  if (context_) return context_.get();
  try {
    context_ = std::make_unique<rt::VulkanContext>(rt::DeviceOptions{options_.device, options_.validation});
  } catch (const std::bad_alloc&) {
    throw;  // "out of memory", exit 4 (cli/Main.cpp)
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return nullptr;
  }
  return context_.get();
}

rt::AlbedoTables* Device::tables() {
  if (tables_) return tables_.get();
  rt::VulkanContext* c = context();
  if (!c) return nullptr;
  try {
    tables_ = std::make_unique<rt::AlbedoTables>(*c);
  } catch (const std::bad_alloc&) {
    throw;  // "out of memory", exit 4 (cli/Main.cpp)
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return nullptr;
  }
  return tables_.get();
}

bool Device::checkValidation() {
  if (!context_) return true;
  for (const std::string& m : context_->validationMessages()) std::fprintf(stderr, "validation: %s\n", m.c_str());
  return context_->validationMessages().empty();
}

std::optional<MaterialProgram> prepareMaterial(MaterialPipeline& pipeline, Session& session, rt::VulkanContext& context,
                                               const ir::Material& material, glsl::ShaderKind kind) {
  MaterialProgram program;
  program.shader = pipeline.compiler().shader(material, kind);
  auto words = pipeline.compiler().spirv(program.shader);
  session.printDiagnostics();
  if (!words) return std::nullopt;
  program.spirv = std::move(*words);
  Diagnostics& diagnostics = session.workspace.diagnostics;
  const size_t errors = diagnostics.errorCount();
  program.resources =
      std::make_unique<rt::MaterialResources>(context, program.shader.interface, pipeline.documentFolder(), diagnostics);
  session.printDiagnostics();
  if (diagnostics.errorCount() > errors) return std::nullopt;
  return program;
}

Progress::Progress(size_t total) : total_(total), tty_(isatty(fileno(stderr)) != 0) {}

void Progress::step(const std::string& what) {
  ++done_;
  if (tty_ && total_ > 1) std::fprintf(stderr, "\r\033[K[%zu/%zu] %s", done_, total_, what.c_str());
}

Progress::~Progress() {
  if (tty_ && total_ > 1 && done_ > 0) std::fprintf(stderr, "\r\033[K");
}

}  // namespace mxc::cli
