#include "cli/Harness.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "cli/Verbosity.h"
#include "compiler/common/Parallel.h"

namespace mxc::cli {


rt::VulkanContext* Device::context() {
  if (context_) return context_.get();
  try {
    const auto start = std::chrono::steady_clock::now();
    context_ = std::make_unique<rt::VulkanContext>(rt::DeviceOptions{options_.device, options_.validation});
    detail("device {} ({:.0f} ms to start)", context_->deviceName(), millisecondsSince(start));
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
    const auto start = std::chrono::steady_clock::now();
    tables_ = std::make_unique<rt::AlbedoTables>(*c);
    detail("albedo tables computed on the device in {:.0f} ms", millisecondsSince(start));
  } catch (const std::bad_alloc&) {
    throw;  // "out of memory", exit 4 (cli/Main.cpp)
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return nullptr;
  }
  return tables_.get();
}

rt::TextureCache* Device::textures() {
  if (textures_) return textures_.get();
  rt::VulkanContext* c = context();
  if (!c) return nullptr;
  textures_ = std::make_unique<rt::TextureCache>(*c);
  return textures_.get();
}

bool Device::checkValidation() {
  if (!context_) return true;
  for (const std::string& m : context_->validationMessages()) std::fprintf(stderr, "validation: %s\n", m.c_str());
  return context_->validationMessages().empty();
}

std::optional<MaterialProgram> prepareMaterial(MaterialPipeline& pipeline, Session& session, rt::VulkanContext& context,
                                               const ir::Material& material, glsl::ShaderKind kind,
                                               rt::TextureCache* textures) {
  auto programs = prepareMaterials({{&pipeline, &material}}, session, context, kind, textures);
  if (!programs) return std::nullopt;
  return std::move(programs->front());
}

std::optional<std::vector<MaterialProgram>> prepareMaterials(const std::vector<MaterialToPrepare>& materials,
                                                             Session& session, rt::VulkanContext& context,
                                                             glsl::ShaderKind kind, rt::TextureCache* textures) {
  // Each compilation reports into diagnostics of its own (the workspace's are not shared across
  // threads); they join the workspace's in the materials' order.
  struct Compiled {
    MaterialProgram program;
    Diagnostics diagnostics;
    bool ok = false;
  };
  std::vector<Compiled> compiled(materials.size());
  runOnEveryCore(materials.size(), [&](size_t i) {
    const MaterialToPrepare& m = materials[i];
    Compiled& c = compiled[i];
    c.program.shader = m.pipeline->compiler().shader(*m.material, kind);
    auto words = compileShader(c.program.shader, m.pipeline->compiler().request(), c.diagnostics);
    c.ok = words.has_value();
    if (words) c.program.spirv = std::move(*words);
  });

  Diagnostics& diagnostics = session.workspace.diagnostics;
  std::vector<MaterialProgram> programs;
  for (size_t i = 0; i < materials.size(); ++i) {
    Compiled& c = compiled[i];
    for (const Diagnostic& d : c.diagnostics.all()) diagnostics.add(d);
    session.printDiagnostics();
    if (!c.ok) return std::nullopt;
    const size_t errors = diagnostics.errorCount();
    c.program.resources = std::make_unique<rt::MaterialResources>(context, c.program.shader.interface,
                                                                  materials[i].pipeline->documentFolder(), diagnostics, textures);
    session.printDiagnostics();
    if (diagnostics.errorCount() > errors) return std::nullopt;
    programs.push_back(std::move(c.program));
  }
  return programs;
}

Progress::Progress(size_t total)
    : total_(total), tty_(isatty(fileno(stderr)) != 0 && !quiet()), start_(std::chrono::steady_clock::now()) {}

void Progress::step(const std::string& what) {
  ++done_;
  if (!tty_ || total_ == 0) return;
  using namespace std::chrono;
  const auto now = steady_clock::now();
  const double elapsed = duration<double>(now - start_).count();
  if (elapsed < 1.0 || (drawn_ && now - lastDraw_ < milliseconds(100) && done_ < total_)) return;
  lastDraw_ = now;
  drawn_ = true;
  const size_t done = std::min(done_, total_);
  const double share = double(done) / double(total_);  // total_ > 0
  const int left = int(std::lround(elapsed * double(total_ - done) / double(done)));  // done >= 1 here
  constexpr int kBar = 24;
  const int filled = int(share * kBar);
  // The estimate before the label: a narrow terminal cuts the label, not the estimate.
  std::string line = fmt::format("[{}{}] {:3.0f}% ETA {}:{:02d}  {}/{} {}", std::string(size_t(filled), '#'),
                                 std::string(size_t(kBar - filled), '-'), 100.0 * share, left / 60, left % 60, done,
                                 total_, what);
  winsize size{};
  const size_t columns = ioctl(fileno(stderr), TIOCGWINSZ, &size) == 0 && size.ws_col > 1 ? size.ws_col : 80;
  if (line.size() > columns - 1) line.resize(columns - 1);  // no wrap: "\r" returns to the line's start
  std::fprintf(stderr, "\r\033[K%s", line.c_str());
}

void Progress::clear() {
  if (drawn_) std::fprintf(stderr, "\r\033[K");
  drawn_ = false;
}

Progress::~Progress() { clear(); }

}  // namespace mxc::cli
