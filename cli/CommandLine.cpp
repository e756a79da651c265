// The command line of mxc: every command's options and how they map to its options struct, in
// one file. CLI11 is header-only and heavy to compile (about 11 s per file that registers
// options, 50 s under the sanitizers), so this is the one file that includes it; the commands'
// logic (cli/*Command.cpp) sees only their options structs.

#include "cli/CommandLine.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli/AccuracyBench.h"
#include "cli/SpecializationBench.h"
#include "cli/Verbosity.h"
#include "cli/CommandSpec.h"
#include "cli/CompileCommand.h"
#include "cli/EvalCommand.h"
#include "cli/ExitCode.h"
#include "cli/InspectCommand.h"
#include "cli/RenderCommand.h"
#include "compiler/common/ColorSpace.h"
#include "compiler/target/NagaTranslator.h"
#include "compiler/target/Target.h"
#include "runtime/ImageIO.h"
#include "runtime/VulkanContext.h"

#include <glslang/build_info.h>
#include <spirv-tools/libspirv.h>
#ifdef MXC_MIMALLOC
#include <mimalloc.h>
#endif

namespace mxc::cli {

namespace {

/// A check that an option's number is finite, and >= 0 when `nonNegative` (CLI11's own number
/// checks let "nan" and "inf" through, and both parse as floats).
CLI::Validator finiteNumber(bool nonNegative) {
  return CLI::Validator(
      [nonNegative](std::string& text) -> std::string {
        size_t used = 0;
        double v = 0.0;
        try {
          v = std::stod(text, &used);
        } catch (const std::exception&) {
          return fmt::format("'{}' is not a number", text);
        }
        if (used != text.size()) return fmt::format("'{}' is not a number", text);
        if (!std::isfinite(v)) return fmt::format("'{}' is not a finite number", text);
        if (nonNegative && v < 0.0) return fmt::format("'{}' is negative", text);
        return {};
      },
      nonNegative ? "NUMBER >= 0" : "NUMBER");
}

/// Set while parseCommandLineWords parses: the commands' callbacks then run nothing.
thread_local bool tParseOnly = false;

/// Runs `action` when `command` is parsed, its result the exit code (but under
/// parseCommandLineWords, which parses only).
void onRun(CLI::App& command, int& exitCode, std::function<int()> action) {
  command.callback([action = std::move(action), &exitCode] {
    if (!tParseOnly) exitCode = action();
  });
}

void addLibraryOptions(CLI::App& command, LibraryOptions& options) {
  command.add_option("--library", options.folders,
                     "Node library folder (every .mtlx under it) or file, layered over the built-in library; "
                     "repeatable, later ones shadow earlier definitions of the same name");
  command.add_flag("--no-builtin", options.noBuiltin, "Do not load mxc's built-in node library");
}

void addInputOptions(CLI::App& command, MaterialOptions& options) {
  command.add_option("--set", options.set,
                     "Override an input of the shading node: INPUT=VALUE, the value written as in a document "
                     "(--set base_color=0.8,0.2,0.1); repeatable")
      ->type_name("INPUT=VALUE");
  command.add_option("--param", options.parameters,
                     "Keep an input of the shading node variable: a uniform of the shader, with the document's (or "
                     "--set's) value as its default; repeatable")
      ->type_name("INPUT");
  std::string names;
  for (Accuracy a : kAccuracies) names += (names.empty() ? "" : "|") + std::string(accuracyName(a));
  command
      .add_option_function<std::string>(
          "--accuracy", [&options](const std::string& name) { options.accuracy = *parseAccuracy(name); },
          "Accuracy tier of the shader: fast (analytic albedo fits, no multiple-scattering compensation), "
          "balanced (tables and multiple-scattering compensation; the default), reference (Monte Carlo random walk "
          "through the slab stacks: the ground truth, eval an unbiased estimate)")
      ->type_name(names)
      ->default_str(std::string(accuracyName(options.accuracy)))
      ->check(CLI::Validator(
          [names](std::string& text) -> std::string {
            return parseAccuracy(text) ? std::string() : fmt::format("'{}' is not a tier ({})", text, names);
          },
          ""));
  command.add_flag("--param-all", options.parameterAll,
                   "Keep every input of the material that has a value (the shading node's and its graphs' interface "
                   "inputs) a uniform of the shader, each named in the interface JSON with its input, as a "
                   "general-purpose generator does; an effect an input can turn on stays compiled in");
  command.add_flag("--no-specialize", options.noSpecialize,
                   "Compile the general shader, for comparison: every input of the shading node a uniform, every "
                   "effect of the shading model and the library's refraction and absorption code compiled in, and "
                   "(render) the environment and lights read at run time instead of fixed in the pipeline");
  command
      .add_option("--reference-samples", options.referenceSamples,
                  "With --accuracy reference: random walks averaged per evaluation of f cos (default: 1 for render, "
                  "where the image converges with --spp; 1024 for eval)")
      ->type_name("N")
      ->check(CLI::Range(1, 1 << 20));
}

void addSearchPathOption(CLI::App& command, MaterialOptions& options) {
  command.add_option("--search-path", options.searchPaths,
                     "A folder searched for image files not found beside the document, and for --mesh names, before "
                     "those of MATERIALX_SEARCH_PATH (':'-separated); repeatable (MaterialX's search path: a document "
                     "of its test suite names resources/Images/..., found under the tree's root)");
}

void addMaterialOptions(CLI::App& command, MaterialOptions& options) {
  addInputOptions(command, options);
  addSearchPathOption(command, options);
  command.add_option("--material", options.material, "Only the material of this name (default: every material)")
      ->type_name("NAME");
  addLibraryOptions(command, options.libraries);
}

void addDeviceOptions(CLI::App& command, DeviceOptions& options) {
  command.add_option("--device", options.device,
                     "Vulkan device: an index or part of its name (default: Mesa lavapipe when present)")
      ->type_name("INDEX|NAME");
  command.add_flag("--validation", options.validation,
                   "Enable the Khronos validation layer; any validation message fails the run (exit 1)");
}

void registerInspect(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<InspectOptions>();
  CLI::App* command = app.add_subcommand(
      "inspect",
      "Show a document: its materials, their shader nodes with every input (set or default, with its source "
      "line), and the resolved graph as an indented tree");
  command->add_option("file", options->file, "The .mtlx document (with --effects: or a scene .json)")->required();
  auto* json = command->add_flag("--json", options->json, "Write JSON (schema mxc-inspect-1, docs/inspect-json.md)");
  auto* dot = command->add_flag("--dot", options->dot, "Write a Graphviz DOT graph");
  json->excludes(dot);
  auto* ir = command->add_flag("--ir", options->ir,
                               "Show the slab IR of each material after the passes (with --json: schema mxc-ir-1, "
                               "docs/ir-json.md)");
  ir->excludes(dot);
  auto* effects = command->add_flag(
      "--effects", options->effects,
      "List, per material, each effect its shader simulates or leaves out and why: the input value at its line, or "
      "the scene fact (a scene file's lights and environment; for a document, mxc render's default scene). With "
      "--json: schema mxc-effects-1 (docs/specialization.md)");
  effects->excludes(dot);
  effects->excludes(ir);
  command->add_flag("--shading-model-graphs", options->shadingModelGraphs,
                    "With --ir: lower open_pbr_surface and standard_surface through the node graphs that implement "
                    "them in the libraries (MaterialX's, with --library) instead of mxc's own lowering")
      ->needs(ir);
  command->add_option("-o,--output", options->output, "Write the report to this file (atomically) instead of stdout");
  command->add_flag("--partial", options->partial,
                    "Write the report even when the document has errors (the exit code is still 1)");
  addInputOptions(*command, options->inputs);
  addSearchPathOption(*command, options->inputs);
  addLibraryOptions(*command, options->libraries);
  onRun(*command, exitCode, [options] { return runInspect(*options); });
}

void registerCompile(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<CompileOptions>();
  CLI::App* command = app.add_subcommand(
      "compile",
      "Compile the materials of a document to SPIR-V (validated by SPIRV-Tools), or with --target to GLSL, ESSL, "
      "MSL, HLSL (SPIRV-Cross) or WGSL (naga), each validated by its own toolchain where one runs here; beside "
      "each shader, its interface (.json) and vertex stage for a host renderer. With several "
      "materials, output names get _<material> before their extension. Several documents, folders (every .mtlx "
      "under them) or scenes compile in one process, -j at a time: -o and --glsl then name folders, written as "
      "DIR/<document>/<material>.spv, each document's files together or not at all; a failing document does not "
      "stop the others, and the exit code is 1 when any failed");
  command->add_option("files", options->files,
                      "The .mtlx documents, folders or scene files (.json); none with --tables DIR writes the tables alone")
      ->type_name("FILE|DIR");
  command->add_option("-o,--output", options->output,
                      "Write the shader here, in --target's language (a folder for several documents)")
      ->type_name("FILE|DIR");
  command
      ->add_option("--target", options->target,
                   "The language -o is written in: spirv (Vulkan 1.1), glsl (OpenGL 4.5), essl (OpenGL ES 3.2), msl "
                   "(Metal 2.1), hlsl (shader model 6.0) or wgsl (WebGPU). Default: the one -o's extension names "
                   "(.spv .glsl .essl .metal .hlsl .wgsl), else spirv")
      ->check(CLI::IsMember([] {
        std::vector<std::string> names;  // the target module's own list
        for (target::Target t : target::allTargets()) names.emplace_back(target::targetName(t));
        return names;
      }()));
  command->add_option("--depfile", options->depfile,
                      "Also write a Makefile-style depfile here: the files written depend on the document, its "
                      "includes, the library files and the image files (for Ninja, Make, CMake's DEPFILE)")
      ->type_name("FILE");
  command->add_flag("--list-outputs", options->listOutputs,
                    "Print the files the command would write, one per line, and write nothing (for build systems "
                    "that declare outputs before running)");
  command->add_option("--glsl", options->glsl,
                      "Write the Vulkan GLSL (4.00 with ARB extensions; compute stages 4.40) that mxc compiles to SPIR-V here (a folder for several documents)")
      ->type_name("FILE|DIR");
  command->add_option("--tables", options->tables,
                      "Write the albedo tables the shaders sample to this folder (mxc_albedo_tables.bin; the "
                      "interface JSON beside each SPIR-V file names it)")
      ->type_name("DIR");
  command->add_option("-j,--jobs", options->jobs, "Documents compiled at once in a batch (default: one per core)")
      ->check(CLI::Range(1, 256));
  command->add_option("--stage", options->stage,
                      "frag: fragment shader of the renderer; comp: compute shader evaluating f cos; furnace: compute "
                      "shader of the directional albedo; sample: compute shader drawing sample directions")
      ->check(CLI::IsMember({"frag", "comp", "furnace", "sample"}));
  command->add_flag("-O,--optimize", options->optimize, "Optimise the module with SPIRV-Tools' performance passes");
  const std::string linear = fmt::format("{}", fmt::join(linearColorSpaceNames(), ", "));
  command
      ->add_option("--working-space", options->materials.workingSpace,
                   fmt::format("The linear colour space the shader computes in: colour values and colour textures "
                               "tagged with a `colorspace` are converted into it (default: lin_rec709, MaterialX's "
                               "default target; one of {}). mxc's own renderer works in lin_rec709",
                               linear))
      ->type_name("SPACE")
      ->check(CLI::Validator(
          [linear](std::string& text) -> std::string {
            const ColorSpace* space = findColorSpace(text);
            if (space && space->encoding == Encoding::Linear) return {};
            return fmt::format("'{}' is not a linear colour space mxc knows ({})", text, linear);
          },
          ""));
  addMaterialOptions(*command, options->materials);
  onRun(*command, exitCode, [options] { return runCompile(*options); });
}

void registerEval(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<EvalOptions>();
  CLI::App* command = app.add_subcommand(
      "eval",
      "Evaluate each material's BSDF on the device: for every row wo_x,wo_y,wo_z,wi_x,wi_y,wi_z of a CSV file "
      "(directions in a frame with normal +z, tangent +x; normalised), print f(wo, wi) |cos theta_i| and the "
      "sampling pdf as CSV");
  command->add_option("file", options->file, "The .mtlx document")->required();
  command->add_option("--dirs", options->dirs, "CSV file of direction pairs")->required();
  command->add_option("-o,--output", options->output, "Write the CSV here (atomically) instead of stdout");
  addMaterialOptions(*command, options->materials);
  addDeviceOptions(*command, options->device);
  onRun(*command, exitCode, [options] { return runEval(*options); });
}

void registerFurnace(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<FurnaceOptions>();
  CLI::App* command = app.add_subcommand(
      "furnace",
      "The white furnace: each material's directional albedo (reflected, transmitted, total, with Monte Carlo "
      "standard errors) at N view angles from normal incidence, as JSON");
  command->add_option("file", options->file, "The .mtlx document")->required();
  command->add_option("--angles", options->angles, "Number of view angles, 90 deg * k / N")
      ->check(CLI::Range(1, 4096));
  command->add_option("--samples", options->samples, "Samples per angle")->check(CLI::Range(64, 1 << 26));
  command->add_option("--seed", options->seed, "Random seed")->check(CLI::NonNegativeNumber);
  command->add_option("-o,--output", options->output, "Write the JSON here (atomically) instead of stdout");
  addMaterialOptions(*command, options->materials);
  addDeviceOptions(*command, options->device);
  onRun(*command, exitCode, [options] { return runFurnace(*options); });
}

void registerRender(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* command = app.add_subcommand(
      "render",
      "Render each material on a mesh (a sphere by default): lights evaluated exactly, the environment (analytic, or an HDR image "
      "importance-sampled with MIS) integrated by Monte Carlo over --spp frames. .exr: linear radiance with "
      "coverage alpha; .png (and other 8-bit formats): tone-mapped (--tonemap), sRGB, over --background or the "
      "environment image. With several materials, file names get _<material>");
  command->add_option("file", options->file, "The .mtlx document, or a scene file (.json: docs/scenes.md)")->required();
  command->add_option("-o,--output", options->outputs,
                      "Output image (.png, .exr, .jpg, ...), or - for standard output (with --format); repeatable")
      ->required();
  command->add_option("--format", options->format,
                      "The image format of -o - (standard output), as a file extension: png, exr, jpg, tif, hdr, ...")
      ->type_name("EXT");
  command->add_option("--size", options->size, "N (square) or WxH, in pixels, each 8 to 8192")
      ->type_name("N|WxH");
  command->add_option("--spp", options->spp, "Samples (frames) per pixel")->check(CLI::Range(1, 1 << 20));
  command->add_option("--light", options->lights,
                      "dir:X,Y,Z[:INTENSITY[:R,G,B]] (towards the light) or point:X,Y,Z[:INTENSITY[:R,G,B]]; "
                      "repeatable, up to 8; 'none' for no light (default: dir:-1,1.2,1.5:2, none with an --env image)")
      ->type_name("SPEC");
  command->add_option("--env", options->environment,
                      "Environment: none, white (the furnace), sky (analytic), or an equirectangular HDR image "
                      "(.exr, .hdr, ...: importance-sampled, and the background unless --background is given)");
  command->add_option("--env-intensity", options->environmentIntensity, "Environment radiance scale")
      ->check(finiteNumber(true));
  command->add_option("--env-rotation", options->environmentRotation,
                      "Turn of the environment image about +y, in degrees (counter-clockwise seen from above)")
      ->check(finiteNumber(false));
  command->add_option("--emission-scale", options->emissionScale, "Radiance per unit of emission")
      ->check(finiteNumber(true));
  command->add_option("--exposure", options->exposure, "Exposure of 8-bit outputs, in stops: scales the rendered radiance, not the --background colour")->check(finiteNumber(false))
      ->check(CLI::Range(-64.0, 64.0));
  command->add_option("--tonemap", options->toneMapping,
                      "Tone curve of 8-bit outputs: aces (Narkowicz's ACES fit, default), neutral (Khronos PBR Neutral) "
                      "or none (clamp); named in the file's metadata")
      ->check(CLI::IsMember({"none", "aces", "neutral"}));
  command->add_option("--background", options->background,
                      "Background of 8-bit outputs, linear R,G,B (default: the environment image, else 0.05,0.05,0.05)")
      ->type_name("R,G,B");
  command->add_option("--mesh", options->mesh,
                      "sphere, plane, a name found on the search path as resources/Geometry/NAME.glb or .obj "
                      "(shaderball, teapot, cube, ...), or a .glb, .gltf or .obj file");
  command->add_option("--look", options->look,
                      "A look of the document: one image with its material assignments to the mesh's parts (glTF "
                      "nodes, OBJ groups: Preview_Mesh and Calibration_Mesh of the shader ball) or to the mesh")
      ->type_name("NAME");
  command->add_option("--camera-position", options->cameraPosition,
                      "X,Y,Z (default: framed to fit the mesh, from the front; from above for the plane)")
      ->type_name("X,Y,Z");
  command->add_option("--camera-target", options->cameraTarget, "X,Y,Z (default: the centre of the mesh's bounds)")
      ->type_name("X,Y,Z");
  command->add_option("--camera-up", options->cameraUp, "X,Y,Z (default: 0,1,0)")
      ->type_name("X,Y,Z");
  command->add_option("--fov", options->fovDegrees, "Vertical field of view in degrees")->check(CLI::Range(1.0, 170.0));
  addMaterialOptions(*command, options->materials);
  addDeviceOptions(*command, options->device);
  onRun(*command, exitCode, [options, command] {
    for (const CLI::Option* option : command->get_options()) {
      if (option->count() > 0 && !option->get_lnames().empty()) options->explicitOptions.push_back("--" + option->get_lnames()[0]);
    }
    return runRender(*options);
  });
}

void registerBench(CLI::App& app, int& exitCode) {
  CLI::App* bench =
      app.add_subcommand("bench", "Measure mxc against itself: 'mxc bench accuracy', 'mxc bench specialize'");
  bench->require_subcommand(1);
  auto options = std::make_shared<AccuracyBenchOptions>();
  CLI::App* command = bench->add_subcommand(
      "accuracy",
      "Every accuracy tier of a set of materials against the reference tier: the error of the directional albedo, "
      "of f cos and of a rendered sphere, and the cost (ns per evaluation, ms per frame, SPIR-V instructions, the "
      "reference's time to 1% noise). Writes accuracy.md, accuracy.csv and accuracy.png (error against cost) to "
      "--report-dir. Takes minutes: the reference is refined until its noise is below the errors it measures");
  command->add_option("files", options->files,
                      "Documents (every material of each); default: a fixed set of corpus materials covering coat, "
                      "fuzz, metal, glass, subsurface, thin film and emission");
  command->add_option("--corpus", options->corpus, "The corpus folder of the fixed set (default: ../shared/corpus "
                      "beside the source tree)");
  command->add_flag("--fixed-set", options->withFixedSet,
                    "With FILES: the fixed set first, then the materials of FILES it does not hold already");
  command->add_option("--report-dir", options->reportDir, "Folder of the report files (default: generated/reports)");
  command->add_option("--albedo-walks", options->albedoWalks, "Cap of the reference's walks per view")
      ->check(CLI::Range(64, 1 << 26));
  command->add_option("--eval-walks", options->evalWalks, "Cap of the reference's walks per direction pair")
      ->check(CLI::Range(4, 1 << 22));
  command->add_option("--image-frames", options->imageFrames, "Cap of the reference image's frames")
      ->check(CLI::Range(2, 1 << 16));
  command->add_option("--tier-frames", options->tierFrames, "Frames of the fast and balanced images")
      ->check(CLI::Range(1, 1 << 16));
  command->add_option("--image-size", options->imageSize, "Width and height of the error images")
      ->check(CLI::Range(8, 4096));
  command->add_option("--frame-size", options->frameSize, "Width and height of the frame-time image")
      ->check(CLI::Range(8, 4096));
  addLibraryOptions(*command, options->libraries);
  addDeviceOptions(*command, options->device);
  onRun(*command, exitCode, [options] { return runAccuracyBench(*options); });

  auto specialize = std::make_shared<SpecializationBenchOptions>();
  command = bench->add_subcommand(
      "specialize",
      "Each material's specialized shader against the general one (--no-specialize), and against MaterialX's own "
      "shader of the document when --materialx gives its GLSL: SPIR-V instructions (plain and -O), compile time to "
      "SPIR-V and to a pipeline, and frame time in two scenes (a key light; the sky and a key light), all measured in "
      "one run. Writes specialization.md (with the medians and the targets) and specialization.csv to --report-dir");
  command->add_option("files", specialize->files,
                      "Documents (every material of each); default: the documents of the comparison with MaterialX "
                      "(tests/bench/materialx_compare.py) and two plain diffuse presets");
  command->add_option("--corpus", specialize->corpus, "The corpus folder of the fixed set (default: ../shared/corpus "
                      "beside the source tree)");
  command->add_option("--materialx", specialize->materialx,
                      "The manifest of MaterialX's generated shaders that 'python3 tests/bench/materialx_compare.py "
                      "--specialization' writes (build/materialx-compare/manifest.json)");
  command->add_option("--report-dir", specialize->reportDir, "Folder of the report files (default: generated/reports)");
  command->add_option("--size", specialize->size, "Width and height of the timed images")->check(CLI::Range(8, 4096));
  command->add_option("--frames", specialize->frames, "Frames per timed image (the first is not timed)")
      ->check(CLI::Range(2, 1 << 16));
  command->add_option("--repeat", specialize->repeat, "Compilations per shader (the median time is reported)")
      ->check(CLI::Range(1, 100));
  addLibraryOptions(*command, specialize->libraries);
  addDeviceOptions(*command, specialize->device);
  onRun(*command, exitCode, [specialize] { return runSpecializationBench(*specialize); });
}

/// -q and -v on every command (cli/Verbosity.h): one setting for the process.
void addVerbosityOptions(CLI::App& app) {
  for (CLI::App* command : app.get_subcommands({})) {
    if (!command->get_subcommands({}).empty()) {
      addVerbosityOptions(*command);  // bench: on its own commands
      continue;
    }
    CLI::Option* q = command->add_flag_callback(
        "-q,--quiet", [] { setVerbosity(Verbosity::Quiet); },
        "Print nothing but errors: no warnings, notes, summaries or progress (reports and data still go to -o or "
        "stdout)");
    CLI::Option* v = command->add_flag_callback(
        "-v,--verbose", [] { setVerbosity(Verbosity::Verbose); },
        "Also say on stderr what each stage did and how long it took (libraries, document, lowering, GLSL, SPIR-V, "
        "device)");
    q->excludes(v);
  }
}

/// Every option takes one value per occurrence, as compilers' options do (`-I DIR FILE`): a
/// list option (--library, --search-path, --set, render's -o, ...) would otherwise take every
/// word that follows it, the document included. Recurses into every command.
void oneValuePerOccurrence(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    if (!option->get_positional() && option->get_type_size() != 0) option->allow_extra_args(false);
  }
  for (CLI::App* command : app.get_subcommands({})) oneValuePerOccurrence(*command);
}

/// --help's defaults, shown as CLI11 captured them from the options structs, less those that
/// mean nothing to a reader: an empty list ("[]"), and a 0 that stands for "chosen by the
/// command" (the description says what is chosen). Recurses into every command.
void tidyDefaults(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    const std::string shown = option->get_default_str();
    if (shown == "[]" || (shown == "0" && option->get_description().find("(default:") != std::string::npos)) {
      option->default_str("");
    }
  }
  for (CLI::App* command : app.get_subcommands({})) tidyDefaults(*command);
}

/// `mxc --version`: mxc's version, then those of the libraries compiled in and loaded (glslang
/// and SPIRV-Tools are linked; OpenImageIO is the image module's; mimalloc, but under the
/// sanitizers) and of each Vulkan device.
std::string versionText() {
  std::string text = fmt::format("mxc {}\n", MXC_VERSION);
  text += fmt::format("glslang {}.{}.{}{}\n", GLSLANG_VERSION_MAJOR, GLSLANG_VERSION_MINOR, GLSLANG_VERSION_PATCH,
                      GLSLANG_VERSION_FLAVOR);
  text += fmt::format("{}\n", spvSoftwareVersionDetailsString());
  text += fmt::format("SPIRV-Cross {}, for --target glsl, essl, msl, hlsl\n", MXC_SPIRV_CROSS_VERSION);
  text += target::nagaVersion() + ", for --target wgsl\n";
  text += rt::imageLibraryVersion() + "\n";
#ifdef MXC_MIMALLOC
  // Linked, mimalloc serves malloc only if it comes before the C library in the lookup order:
  // asked, not assumed.
  const int allocator = mi_version();  // 209: 2.0.9
  void* probe = std::malloc(16);
  const bool serving = mi_is_in_heap_region(probe);
  std::free(probe);
  text += fmt::format("mimalloc {}.{}.{}, {}\n", allocator / 100, allocator / 10 % 10, allocator % 10,
                      serving ? "the memory allocator" : "linked but not serving malloc");
#endif
  for (const std::string& device : rt::VulkanContext::describeDevices()) text += "Vulkan device " + device + "\n";
  if (!text.empty() && text.back() == '\n') text.pop_back();  // CLI11 ends the line
  return text;
}

constexpr const char* kExitCodes =
    "Exit codes: 0 success, 1 invalid document or library (errors name file:line:column), 2 usage error, "
    "3 an output could not be written, 4 out of memory, 5 no usable Vulkan device.";

/// Every command and option of mxc into `app`; a command's callback sets `exitCode`.
void defineCommandLine(CLI::App& app, int& exitCode) {
  app.require_subcommand(1);
  app.set_version_flag("--version", versionText,
                       "Print the versions of mxc and of the libraries and Vulkan devices it uses, and exit");
  app.footer(std::string(kExitCodes) + "\nRun 'mxc COMMAND --help' for the options of a command.");
  // --help shows each option's default: the value its options struct starts with.
  app.option_defaults()->always_capture_default();
  registerInspect(app, exitCode);
  registerCompile(app, exitCode);
  registerEval(app, exitCode);
  registerFurnace(app, exitCode);
  registerRender(app, exitCode);
  registerBench(app, exitCode);
  addVerbosityOptions(app);
  oneValuePerOccurrence(app);
  tidyDefaults(app);
}

constexpr const char* kDescription = "mxc: compile MaterialX documents (Standard Surface, OpenPBR, pbrlib graphs) to shaders";

/// The values an option names in its type ("TEXT:{none,aces,neutral}", "fast|balanced|reference").
std::vector<std::string> choicesOf(const std::string& type) {
  std::string list;
  if (const size_t open = type.find('{'); open != std::string::npos && type.back() == '}') {
    list = type.substr(open + 1, type.size() - open - 2);
  } else if (type.find('|') != std::string::npos &&
             std::all_of(type.begin(), type.end(), [](char c) { return std::islower(static_cast<unsigned char>(c)) || c == '|'; })) {
    list = type;  // "fast|balanced|reference"; not a placeholder such as "N|WxH"
  }
  std::vector<std::string> out;
  std::string item;
  for (char c : list + ",") {
    if (c == ',' || c == '|') {
      if (!item.empty()) out.push_back(item);
      item.clear();
    } else {
      item += c;
    }
  }
  return out;
}

/// An option's names as the command line spells them, short ones first ("-o", "--output").
std::vector<std::string> optionNames(const CLI::Option& option) {
  std::vector<std::string> names;
  for (const std::string& n : option.get_snames()) names.push_back("-" + n);
  for (const std::string& n : option.get_lnames()) names.push_back("--" + n);
  return names;
}

CommandSpec describe(const CLI::App& app) {
  CommandSpec spec;
  spec.name = app.get_name();
  spec.description = app.get_description();
  for (const CLI::Option* option : app.get_options()) {
    if (option->get_group().empty()) continue;  // hidden
    OptionSpec o;
    o.names = optionNames(*option);
    if (option->get_positional()) o.positional = option->get_name(true, false);
    if (option->get_type_size() != 0) {
      const std::string type = option->get_type_name();
      o.choices = choicesOf(type);
      o.value = type.substr(0, type.find(':'));
      o.number = type.find("INT") != std::string::npos || type.find("FLOAT") != std::string::npos ||
                 type.find("NUMBER") != std::string::npos || type == "N";
    }
    o.repeatable = option->get_expected_max() > 1 || option->get_items_expected_max() > 1;
    o.required = option->get_required();
    o.defaultValue = option->get_default_str();
    o.description = option->get_description();
    spec.options.push_back(std::move(o));
  }
  for (const CLI::App* command : app.get_subcommands({})) spec.commands.push_back(describe(*command));
  return spec;
}

}  // namespace

CommandSpec describeCommandLine() {
  CLI::App app{kDescription, "mxc"};
  int exitCode = kOk;
  defineCommandLine(app, exitCode);
  CommandSpec spec = describe(app);
  spec.footer = kExitCodes;
  return spec;
}

/// The name OptionSpec gives an option first (describe()).
static std::string firstName(const CLI::Option& option) {
  return option.get_positional() ? option.get_name(true, false) : optionNames(option).front();
}

ParsedCommandLine parseCommandLineWords(const std::vector<std::string>& words) {
  CLI::App app{kDescription, "mxc"};
  int exitCode = kOk;
  defineCommandLine(app, exitCode);
  // Parse, do not run: every command's callback returns at once (replacing the callbacks
  // would free the options they own, which the parsed values are written to).
  struct ParseOnly {
    ParseOnly() { tParseOnly = true; }
    ~ParseOnly() { tParseOnly = false; }
  } parseOnly;
  std::vector<std::string> argv = words;
  std::reverse(argv.begin(), argv.end());  // CLI11 takes a vector last word first
  try {
    app.parse(argv);
  } catch (const CLI::ParseError& e) {
    throw std::invalid_argument(e.what());
  }
  ParsedCommandLine parsed;
  const CLI::App* command = &app;
  for (;;) {
    const std::vector<const CLI::App*> chosen = command->get_subcommands([](const CLI::App* c) { return c->parsed(); });
    if (chosen.empty()) break;
    command = chosen.front();
    parsed.command += (parsed.command.empty() ? "" : " ") + command->get_name();
  }
  for (const CLI::Option* option : command->get_options()) {
    if (option->count() > 0) parsed.values[firstName(*option)] = option->results();
  }
  return parsed;
}

int runCommandLine(int argc, char** argv) {
  // The build writes the shell completions and the man page from the definition (hidden).
  if (argc == 3 && std::string(argv[1]) == "--generate") {
    const std::string what = argv[2];
    const CommandSpec spec = describeCommandLine();
    const std::string text = what == "bash"  ? bashCompletion(spec)
                             : what == "zsh" ? zshCompletion(spec)
                             : what == "man" ? manPage(spec, MXC_VERSION)
                                             : std::string();
    if (text.empty()) {
      std::fprintf(stderr, "error: --generate bash|zsh|man\n");
      return kUsage;
    }
    std::fwrite(text.data(), 1, text.size(), stdout);
    return kOk;
  }
  CLI::App app{kDescription, "mxc"};
  int exitCode = kOk;
  defineCommandLine(app, exitCode);
  // The first word that is not an option names the command (mxc has no option that takes a
  // value before it); CLI11 would say only "A subcommand is required" of a misspelt one. The
  // same for `bench`'s own commands.
  const auto commands = [](CLI::App& parent) {
    std::vector<std::string> names;
    for (const CLI::App* sub : parent.get_subcommands({})) names.push_back(sub->get_name());
    return names;
  };
  const auto unknown = [&](CLI::App& parent, int first, int count, char** words) -> std::optional<std::string> {
    for (int i = first; i < count; ++i) {
      const std::string word = words[i];
      if (word.empty() || word[0] == '-') continue;
      const std::vector<std::string> names = commands(parent);
      if (std::find(names.begin(), names.end(), word) != names.end()) return std::nullopt;
      return fmt::format("unknown command '{}' (commands: {})", word, fmt::join(names, ", "));
    }
    return std::nullopt;
  };
  std::optional<std::string> problem = unknown(app, 1, argc, argv);
  if (argc == 1) problem = fmt::format("no command given (commands: {})", fmt::join(commands(app), ", "));
  if (!problem && argc > 1 && std::string(argv[1]) == "bench") problem = unknown(*app.get_subcommand("bench"), 2, argc, argv);
  if (problem) {
    std::fprintf(stderr, "error: %s\nRun with --help for more information.\n", problem->c_str());
    return kUsage;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // prints the message
    return kUsage;
  }
  return exitCode;
}

}  // namespace mxc::cli
