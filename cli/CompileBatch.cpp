#include "cli/CompileBatch.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <stop_token>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "cli/ExitCode.h"
#include "cli/Harness.h"
#include "cli/InterfaceOutputs.h"
#include "cli/MaterialPipeline.h"
#include "cli/Scene.h"
#include "cli/SceneDocuments.h"
#include "cli/Verbosity.h"
#include "compiler/common/Parallel.h"
#include "compiler/driver/ShaderGroups.h"
#include "compiler/glsl/ShaderBuilder.h"
#include "compiler/spirv/SpirvCompiler.h"

namespace mxc::cli {

namespace fs = std::filesystem;

namespace {

/// One document (or scene) of the batch, and the folder of its outputs under -o / --glsl.
struct Item {
  fs::path file;
  fs::path relative;  ///< "openpbr-presets/open_pbr_gold" for a folder's document, the stem for a file
};

enum class Outcome { Compiled, Nothing, Failed };

struct ItemResult {
  Outcome outcome = Outcome::Failed;
  size_t materials = 0;
  std::string messages;  ///< the document's diagnostics and errors, printed together
};

/// The documents the arguments name, in order: a folder's .mtlx files sorted by path.
std::variant<std::vector<Item>, std::string> collect(const std::vector<std::string>& arguments) {
  std::vector<Item> items;
  for (const std::string& argument : arguments) {
    const fs::path path(argument);
    std::error_code error;
    if (fs::is_directory(path, error)) {
      std::vector<fs::path> found;
      for (auto it = fs::recursive_directory_iterator(path, fs::directory_options::skip_permission_denied, error);
           !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
        if (it->is_regular_file(error) && it->path().extension() == ".mtlx") found.push_back(it->path());
      }
      if (error) return fmt::format("{}: cannot list the folder: {}", argument, error.message());
      std::sort(found.begin(), found.end());
      const fs::path base = fs::absolute(path).lexically_normal();
      const fs::path name = base.has_filename() ? base.filename() : base.parent_path().filename();
      for (const fs::path& f : found) {
        fs::path relative = name / fs::absolute(f).lexically_normal().lexically_relative(base);
        items.push_back({f, relative.replace_extension()});
      }
    } else if (fs::exists(path, error)) {
      items.push_back({path, path.stem()});
    } else {
      return fmt::format("{}: no such file or folder", argument);
    }
  }
  // Two documents must not write one folder of outputs.
  std::map<fs::path, const Item*> seen;
  for (const Item& item : items) {
    auto [at, fresh] = seen.emplace(item.relative, &item);
    if (!fresh) {
      return fmt::format("{} and {} would both write their outputs to {}/: compile them in separate runs",
                         at->second->file.string(), item.file.string(), item.relative.string());
    }
  }
  return items;
}

/// Everything the workers share, read-only but for the counters.
struct Batch {
  const CompileOptions& options;
  const lib::LibraryStack* libraries;
  glsl::ShaderKind kind;
  fs::path tables;  ///< --tables' file, written once before the documents
  ShaderCache* shaderCache;  ///< shaders compiled so far, shared by the workers
};

/// The request that compiles a document of the batch.
CompileRequest documentRequest(const Batch& batch, const Item& item) {
  CompileRequest request;
  request.document = item.file;
  request.stage = batch.kind;
  request.optimize = batch.options.optimize;
  request.target = batch.options.resolvedTarget;
  request.libraries = batch.libraries;
  request.shaderCache = batch.shaderCache;
  return request;
}

/// A document (or scene) of the batch between its two steps: loaded, lowered and its shaders
/// built (prepare), then compiled and written (finish). In between, the batch plans the group
/// compiles of every document's shaders (driver/ShaderGroups.h).
struct Job {
  ItemResult result;
  Session session;  ///< its messages go to result.messages (so a Job does not move)
  std::unique_ptr<MaterialPipeline> single;
  std::unique_ptr<SceneDocuments> scene;
  /// The materials to compile, each with the pipeline of its document, and their shaders.
  std::vector<std::pair<MaterialPipeline*, const ir::Material*>> units;
  std::vector<std::shared_ptr<const glsl::MaterialShader>> shaders;
  bool prepared = false;  ///< false: result says why not (or that there is nothing to compile)
  Job() { session.capture = &result.messages; }
};

/// Loads and lowers the document's materials and builds their shaders.
void prepareItem(const Batch& batch, const Item& item, Job& job) {
  const CompileOptions& options = batch.options;
  ItemResult& result = job.result;
  Session& session = job.session;
  const std::string file = item.file.string();
  auto& units = job.units;
  auto& single = job.single;
  auto& scene = job.scene;
  if (isSceneFile(item.file)) {
    auto read = readScene(item.file);
    if (auto* why = std::get_if<std::string>(&read)) {
      session.printLine(*why);
      return;
    }
    scene = std::make_unique<SceneDocuments>(session);
    if (scene->load(std::get<Scene>(read), options.materials, batch.kind, options.optimize, options.resolvedTarget,
                    batch.shaderCache) != kOk) {
      return;
    }
    // What a single compile of the scene compiles: its objects' materials and its look's.
    auto used = scene->used(std::get<Scene>(read));
    if (auto* why = std::get_if<std::string>(&used)) {
      session.printLine(fmt::format("{}: error: {}", file, *why));
      return;
    }
    for (const SceneDocuments::Found& hit : std::get<std::vector<SceneDocuments::Found>>(used)) {
      units.emplace_back(hit.pipeline, hit.material);
    }
  } else {
    single = std::make_unique<MaterialPipeline>(session);
    if (single->run(documentRequest(batch, item), options.materials, false) != kOk) return;
    for (const ir::Material& m : single->materials()) units.emplace_back(single.get(), &m);
  }
  if (units.empty()) {
    result.outcome = Outcome::Nothing;
    return;
  }
  for (const auto& [pipeline, material] : units) {
    job.shaders.push_back(std::make_shared<const glsl::MaterialShader>(pipeline->compiler().shader(*material)));
  }
  job.prepared = true;
}

/// Compiles a prepared document's materials; its outputs are committed together.
void finishItem(const Batch& batch, const Item& item, Job& job) {
  const CompileOptions& options = batch.options;
  ItemResult& result = job.result;
  Session& session = job.session;
  const std::string file = item.file.string();
  const auto& units = job.units;
  // The outputs: DIR/<document>/<material>.spv (or the target's extension) and .frag or .comp,
  // declared before the work.
  OutputSet outputs;
  const std::string shaderExtension(target::fileExtension(options.resolvedTarget));
  const std::string glslExtension = batch.kind == glsl::ShaderKind::Raster ? ".frag" : ".comp";
  auto pathsOf = [&](const ir::Material& m) {
    std::pair<fs::path, fs::path> paths;
    if (!options.output.empty()) paths.first = fs::path(options.output) / item.relative / (fileSafeName(m.name) + shaderExtension);
    if (!options.glsl.empty()) paths.second = fs::path(options.glsl) / item.relative / (fileSafeName(m.name) + glslExtension);
    return paths;
  };
  for (const auto& [pipeline, material] : units) {
    const auto [shaderPath, glslPath] = pathsOf(*material);
    for (const fs::path& path : {shaderPath, glslPath}) {
      if (path.empty()) continue;
      std::error_code error;
      fs::create_directories(path.parent_path(), error);
      if (auto why = outputs.declare(path, path == shaderPath ? "-o" : "--glsl")) {
        session.printLine("error: " + *why);
        return;
      }
      if (path == shaderPath) {
        if (auto why = declareInterfaceOutputs(outputs, path, batch.kind)) {
          session.printLine("error: " + *why);
          return;
        }
      }
    }
  }
  if (auto why = outputs.checkDistinct()) {
    session.printLine(fmt::format("error: {}: {}", file, *why));  // two materials whose names map to one file
    return;
  }
  bool failed = false;
  for (size_t u = 0; u < units.size(); ++u) {
    const auto& [pipeline, material] = units[u];
    if (auto why = pipeline->checkOutputsAreNotInputs(outputs)) {
      session.printLine("error: " + *why);
      return;
    }
    const auto start = std::chrono::steady_clock::now();
    Compiler& compiler = pipeline->compiler();
    const glsl::MaterialShader& shader = *job.shaders[u];
    ShaderCache::Served served = ShaderCache::Served::Compiled;
    std::optional<std::vector<uint32_t>> words = compiler.spirv(shader, &served);
    session.printDiagnostics();
    const auto [spv, glslPath] = pathsOf(*material);
    if (!glslPath.empty()) {
      if (auto why = outputs.stage(glslPath, shader.glsl.text)) {
        session.printLine("error: " + *why);
        return;
      }
    }
    if (!words) {
      failed = true;
      continue;
    }
    if (!spv.empty()) {
      std::string error;
      const Staged staged = stageShaderOutputs(outputs, spv, true, compiler, *material, shader, *words, batch.kind,
                                               batch.tables, pipeline->documentFolder(), error);
      session.printDiagnostics();
      if (staged == Staged::OutputFailed) {
        session.printLine("error: " + error);
        return;
      }
      if (staged == Staged::TranslationFailed) {
        failed = true;
        continue;
      }
    }
    if (verbose()) {  // counting the instructions is work of its own
      detail("{}: {}: {} SPIR-V instructions, {} {:.1f} ms", file, material->name, spirv::instructionCount(*words),
             served == ShaderCache::Served::Compiled       ? "compiled and written in"
             : served == ShaderCache::Served::SameCode     ? "the module of a shader of the same code, written in"
                                                           : "cut from its library's shader, written in",
             millisecondsSince(start));
    }
    ++result.materials;
  }
  // All or nothing for the document, as for a single compile.
  if (failed || !outputs.complete()) {
    session.printLine(fmt::format("error: {}: a shader did not compile; none of its outputs written", file));
    result.materials = 0;
    return;
  }
  if (auto why = outputs.commit()) {
    session.printLine("error: " + *why);
    result.materials = 0;
    return;
  }
  result.outcome = Outcome::Compiled;
}

}  // namespace

bool isBatch(const CompileOptions& options) {
  std::error_code error;
  return options.files.size() > 1 || (options.files.size() == 1 && fs::is_directory(options.files[0], error));
}

int runCompileBatch(const CompileOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  auto collected = collect(options.files);
  if (auto* why = std::get_if<std::string>(&collected)) {
    std::fprintf(stderr, "error: %s\n", why->c_str());
    return kUsage;
  }
  const std::vector<Item>& items = std::get<std::vector<Item>>(collected);
  if (options.output == "-" || options.glsl == "-") {
    std::fprintf(stderr, "error: -o and --glsl name folders when compiling several documents\n");
    return kUsage;
  }
  for (const std::string& folder : {options.output, options.glsl}) {
    std::error_code error;
    if (folder.empty()) continue;
    if (fs::exists(folder, error) && !fs::is_directory(folder, error)) {
      std::fprintf(stderr, "error: %s: with several documents, -o and --glsl name folders (one file per material)\n",
                   folder.c_str());
      return kUsage;
    }
    fs::create_directories(folder, error);
    if (error) {
      std::fprintf(stderr, "error: %s: cannot create the folder: %s\n", folder.c_str(), error.message().c_str());
      return kOutputFailed;
    }
  }
  // glslang builds its built-in symbol tables (135 M instructions) at the first compile of a
  // version, once per process, and every compile waits for them. The vertex stage every raster
  // output has beside it is of the fragment stage's version: it compiles first, on a thread of its
  // own, while the libraries load and the documents are prepared. That thread then prepares
  // documents too, and the workers are one fewer until it does: had they all prepared at once,
  // they would finish first and wait with a core idle for the tables (2 to 14 ms of the corpus
  // batch's 190).
  std::mutex startMutex;
  std::condition_variable_any preparationStarts;
  std::function<void()> prepareSome;  // set, under startMutex, when the preparation starts
  std::exception_ptr helperFailure;   // what escaped prepareSome on that thread (out of memory)
  std::jthread vertexStage;
  if (kindOf(options.stage) == glsl::ShaderKind::Raster && !options.output.empty()) {
    vertexStage = std::jthread([&](std::stop_token stop) {
      try {
        glsl::vertexStageSpirv();
      } catch (const std::exception&) {
        // The workers meet the same failure where they write the vertex stage, and report it.
      }
      std::unique_lock<std::mutex> lock(startMutex);
      // A batch that ends before its preparation (libraries that do not load) stops the wait.
      if (!preparationStarts.wait(lock, stop, [&] { return bool(prepareSome); })) return;
      lock.unlock();
      try {
        prepareSome();
      } catch (...) {
        helperFailure = std::current_exception();  // rethrown by the batch's thread after the join
      }
    });
  }
  // The libraries, once for every document.
  Session libraries;
  if (!libraries.loadLibraries(options.materials.libraries)) {
    libraries.printDiagnostics();
    return kInvalidDocument;
  }
  libraries.printDiagnostics();
  ShaderCache shaderCache;
  Batch batch{options, &libraries.workspace.libraries, kindOf(options.stage), {}, &shaderCache};
  if (!options.tables.empty()) {
    OutputSet tables;
    std::string error;
    auto declared = declareTables(tables, options.tables, error);
    if (!declared) {
      std::fprintf(stderr, "error: %s\n", error.c_str());
      return kOutputFailed;
    }
    if (printError(stageTables(tables, *declared)) || printError(tables.commit())) return kOutputFailed;
    batch.tables = *declared;
  }

  const size_t workers = std::max<size_t>(1, std::min(items.size(), options.jobs > 0 ? size_t(options.jobs) : coreCount()));
  detail("{} document(s) on {} worker(s)", items.size(), workers);
  // Every document prepared (loaded, lowered, its shaders built), `workers` at a time.
  std::vector<std::unique_ptr<Job>> jobs(items.size());
  auto forEachItem = [&](const std::function<void(size_t)>& step) { runOnThreads(items.size(), workers, step); };
  // An exception ends the document with an error; the others go on.
  auto guarded = [&](size_t i, const std::function<void()>& step) {
    std::string why;
    try {
      step();
      return;
    } catch (const std::bad_alloc&) {
      why = "out of memory";
    } catch (const std::exception& e) {
      why = e.what();
    }
    jobs[i]->prepared = false;
    jobs[i]->result = {};
    jobs[i]->result.messages += fmt::format("error: {}: {}\n", items[i].file.string(), why);
  };
  const auto preparing = std::chrono::steady_clock::now();
  std::atomic<size_t> nextToPrepare{0};
  auto prepareUntilDone = [&] {
    for (size_t i = nextToPrepare++; i < items.size(); i = nextToPrepare++) {
      jobs[i] = std::make_unique<Job>();
      guarded(i, [&] { prepareItem(batch, items[i], *jobs[i]); });
    }
  };
  size_t preparers = workers;
  if (vertexStage.joinable()) {
    {
      std::lock_guard<std::mutex> lock(startMutex);
      prepareSome = prepareUntilDone;
    }
    preparationStarts.notify_all();
    preparers = std::max<size_t>(1, workers - 1);
  }
  try {
    runOnThreads(preparers, preparers, [&](size_t) { prepareUntilDone(); });
  } catch (...) {
    // The vertex thread may be preparing documents, which end with this scope: it finishes first.
    if (vertexStage.joinable()) vertexStage.join();
    throw;
  }
  if (vertexStage.joinable()) vertexStage.join();
  if (helperFailure) std::rethrow_exception(helperFailure);
  detail("prepared {} document(s) in {:.1f} ms", items.size(), millisecondsSince(preparing));
  // The shaders of one library compile as one (driver/ShaderGroups.h), each group before the
  // documents that need it, the largest first, so that no worker waits on another's group.
  {
    std::vector<std::shared_ptr<const glsl::MaterialShader>> shaders;
    for (const auto& job : jobs) {
      if (job->prepared) shaders.insert(shaders.end(), job->shaders.begin(), job->shaders.end());
    }
    CompileRequest request;
    request.optimize = options.optimize;
    planShaderGroups(shaderCache, shaders, request);
  }
  std::mutex printing;
  Progress progress(items.size());
  const auto compiling = std::chrono::steady_clock::now();
  forEachItem([&](size_t i) {
    while (shaderCache.compileAGroup()) {
    }
    if (jobs[i]->prepared) guarded(i, [&] { finishItem(batch, items[i], *jobs[i]); });
    const ItemResult& r = jobs[i]->result;
    std::lock_guard<std::mutex> lock(printing);
    if (!r.messages.empty()) {
      progress.clear();
      std::fputs(r.messages.c_str(), stderr);
    }
    progress.step(items[i].file.filename().string());
  });
  progress.clear();
  detail("compiled and wrote them in {:.1f} ms", millisecondsSince(compiling));

  size_t compiled = 0, nothing = 0, materials = 0;
  std::vector<std::string> failed;
  for (size_t i = 0; i < items.size(); ++i) {
    const ItemResult& result = jobs[i]->result;
    materials += result.materials;
    if (result.outcome == Outcome::Compiled) ++compiled;
    else if (result.outcome == Outcome::Nothing) ++nothing;
    else failed.push_back(items[i].file.string());
  }
  const double seconds = millisecondsSince(start) / 1000.0;
  detail("{} material(s) had the code of a shader compiled for another and took its SPIR-V", shaderCache.hits());
  detail("{} module(s) were cut from shaders compiled for several materials of one library", shaderCache.grouped());
  if (!quiet()) {
    std::printf("compiled %zu material(s) of %zu document(s) in %.2f s (%.1f ms per material, %zu worker(s))%s\n",
                materials, compiled, seconds, materials ? 1000.0 * seconds / double(materials) : 0.0, workers,
                nothing ? fmt::format("; {} document(s) had nothing to compile", nothing).c_str() : "");
  }
  if (!failed.empty()) {
    std::fprintf(stderr, "error: %zu of %zu document(s) failed:\n", failed.size(), items.size());
    for (const std::string& f : failed) std::fprintf(stderr, "  %s\n", f.c_str());
    return kInvalidDocument;
  }
  return kOk;
}

}  // namespace mxc::cli
