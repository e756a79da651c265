// Inputs that would hang, exhaust memory or mislead: special files where files are expected,
// graphs deep enough to blow up a report, images past the device's limits, documents with a
// million errors, damaged images, and an mxc moved away from its build tree.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <thread>

#include "runtime/ImageIO.h"
#include "support/CommandSupport.h"
#include "support/RenderCommandSupport.h"

namespace mxc::test {
namespace {

const std::string kDefault = "materialx/examples/OpenPbr/open_pbr_default.mtlx";


/// A chain of `n` add nodes feeding base_weight: n + 5 lines.
std::string chainDocument(int n) {
  std::string body = "  <constant name=\"n0\" type=\"float\"><input name=\"value\" type=\"float\" value=\"0.5\"/></constant>\n";
  for (int i = 1; i < n; ++i) {
    body += "  <add name=\"n" + std::to_string(i) + "\" type=\"float\"><input name=\"in1\" type=\"float\" nodename=\"n" +
            std::to_string(i - 1) + "\"/></add>\n";
  }
  body += "  <open_pbr_surface name=\"s\" type=\"surfaceshader\"><input name=\"base_weight\" type=\"float\" nodename=\"n" +
          std::to_string(n - 1) + "\"/></open_pbr_surface>\n";
  return mtlx(body);
}

// --- Inputs that are not regular files -------------------------------------------------------

TEST(InputSafety, SpecialFilesAreRefusedNotRead) {
  TempFolder folder("inputs");
  const fs::path fifo = folder / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  fs::create_directories(folder / "dir");
  // `timeout` guards the test itself: before the fix a FIFO blocked and /dev/zero spun forever.
  const std::string guard = "timeout 120";
  struct Case {
    std::string what, arguments, message;
  };
  std::vector<Case> cases;
  for (const auto& [path, kind] : {std::pair{fifo.string(), "it is a FIFO"}, std::pair{std::string("/dev/zero"), "it is a character device"},
                                   std::pair{(folder / "dir").string(), "it is a directory"}}) {
    const fs::path doc = folder / ("image_" + std::to_string(cases.size()) + ".mtlx");
    writeText(doc, imageDocument(path));
    // The image error is at the file input: line 4 of the document.
    cases.push_back({"image " + path, "render " + doc.string() + " -o " + (folder / "x.png").string() + " --size 8 --spp 1",
                     doc.string() + ":4:5: error: cannot read image \"" + path + "\": " + kind});
    cases.push_back({"mesh " + path, "render " + corpus(kDefault) + " -o " + (folder / "x.png").string() + " --mesh " + path,
                     "cannot read the mesh '" + path + "': " + kind});
    cases.push_back({"document " + path, "inspect " + path, "cannot read '" + path + "': " + kind});
    cases.push_back({"directions " + path, "eval " + corpus(kDefault) + " --dirs " + path,
                     "cannot read the directions '" + path + "': " + kind});
    if (path != (folder / "dir").string()) {
      cases.push_back({"library " + path, "inspect --library " + path + " " + corpus(kDefault),
                       "cannot read the library '" + path + "': " + kind});
    }
    const fs::path includer = folder / ("include_" + std::to_string(cases.size()) + ".mtlx");
    writeText(includer, "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
                        "  <xi:include href=\"" + path + "\" />\n</materialx>\n");
    cases.push_back({"include " + path, "inspect " + includer.string(),
                     includer.string() + ":3:21: error: cannot read the included file '" + path + "': " + kind});
  }
  for (const Case& c : cases) {
    CommandRun r = mxc(c.arguments, guard);
    EXPECT_EQ(r.exitCode, 1) << c.what << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.what << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(folder / "x.png"));
}

// --- Blow-ups ------------------------------------------------------------------------------

TEST(InputSafety, TheTextReportOfADeepGraphIsLinear) {
  // Indenting each node by its depth made a 10,000-node chain a 601 MB report.
  TempFolder folder("deep");
  writeText(folder / "deep.mtlx", chainDocument(10000));
  CommandRun r = mxc("inspect " + (folder / "deep.mtlx").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_LT(r.out.size(), 4u << 20) << "bytes of report for 10,000 nodes";
  EXPECT_NE(r.out.find("n1 <add> ND_add_float  line 4"), std::string::npos) << "every node is still shown";
  EXPECT_NE(r.out.find("(continued below)"), std::string::npos);
}

/// 100,000 independent nodes (no deep recursion).
std::string wideDocument() {
  std::string body;
  for (int i = 0; i < 100000; ++i) {
    body += "  <constant name=\"k" + std::to_string(i) + "\" type=\"float\"><input name=\"value\" type=\"float\" value=\"" +
            std::to_string(i) + "\"/></constant>\n";
  }
  return mtlx(body);
}

TEST(InputSafety, RunningOutOfMemoryIsAnErrorNotAnAbort) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit this test sets";
#endif
  TempFolder folder("memory");
  // About 320 MB of address space to inspect, in 150 MB.
  writeText(folder / "deep.mtlx", wideDocument());
  CommandRun r = mxc("inspect " + (folder / "deep.mtlx").string() + " -o " + (folder / "report.txt").string(),
                     "ulimit -v 150000;");
  EXPECT_EQ(r.exitCode, 4) << r.err;
  EXPECT_NE(r.err.find("error: out of memory"), std::string::npos) << r.err;
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"deep.mtlx"})) << "no report and no temporary";
}

TEST(InputSafety, InspectJsonRunsOutOfMemoryCleanlyAtEveryLimit) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves more address space than the limits this test sets";
#endif
  // Freeing a large JSON tree allocates (nlohmann::json flattens it through a vector); where
  // memory ran out just then (686-710 MB of address space for this document) the process
  // aborted (134). The report is now written a node at a time, and memory is held back for
  // the unwinding: at every limit the command succeeds or says "out of memory" with exit 4.
  TempFolder folder("memory_json");
  writeText(folder / "wide.mtlx", wideDocument());
  int succeeded = 0, refused = 0;
  for (int megabytes = 300; megabytes <= 760; megabytes += 16) {
    SCOPED_TRACE(megabytes);
    CommandRun r = mxc("inspect " + (folder / "wide.mtlx").string() + " --json -o " + (folder / "r.json").string(),
                       "ulimit -v " + std::to_string(megabytes * 1000) + ";");
    ASSERT_TRUE(r.exitCode == 0 || r.exitCode == 4) << r.exitCode << ": " << r.err;
    if (r.exitCode == 4) {
      EXPECT_NE(r.err.find("error: out of memory"), std::string::npos) << r.err;
      EXPECT_FALSE(fs::exists(folder / "r.json"));
      ++refused;
    } else {
      fs::remove(folder / "r.json");
      ++succeeded;
    }
  }
  EXPECT_GT(succeeded, 0);
  EXPECT_GT(refused, 0);
}

TEST(InputSafety, RunningOutOfDeviceMemoryIsExit4) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit this test sets";
#endif
  // Lavapipe's device memory is the process's: an 8192 x 8192 float image (1 GiB) in 3 GB of
  // address space. It was exit 1, "vkAllocateMemory failed (VkResult -2)".
  TempFolder folder("device_memory");
  CommandRun r = mxc("render " + corpus(kDefault) + " -o " + (folder / "big.exr").string() + " --size 8192 --spp 1",
                     "ulimit -v 3000000;");
  EXPECT_EQ(r.exitCode, 4) << r.err;
  EXPECT_NE(r.err.find("error: out of memory: vkAllocateMemory failed: the device's memory ran out"), std::string::npos) << r.err;
  EXPECT_TRUE(folder.entries().empty()) << "no image and no temporary";
}

TEST(InputSafety, ImagesBeyondTheDeviceLimitAreDownsampled) {
  // Lavapipe takes 16384 texels per side: a 20000 x 4 image went to vkCreateImage as it was.
  TempFolder folder("large");
  rt::RgbaImage wide{20000, 4, std::vector<float>(20000 * 4 * 4, 0.5f)};
  ASSERT_FALSE(rt::writeImage(folder / "wide.exr", wide).has_value());
  writeText(folder / "wide.mtlx", imageDocument("wide.exr"));
  CommandRun r = mxc("render " + (folder / "wide.mtlx").string() + " -o " + (folder / "x.exr").string() +
                     " --size 8 --spp 1 --validation");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("wide.mtlx:4:5: warning: image '" + (folder / "wide.exr").string() + "' is 20000x4"),
            std::string::npos) << r.err;
  EXPECT_NE(r.err.find("box-filtered by 2 to 10000x2"), std::string::npos) << r.err;
}

/// A material summing `count` image nodes, each of its own 2x2 file in `folder`.
std::string manyTexturesDocument(const TempFolder& folder, int count) {
  std::string body;
  for (int k = 0; k < count; ++k) {
    const std::string file = "t" + std::to_string(k) + ".exr";
    EXPECT_FALSE(rt::writeImage(folder / file, rt::RgbaImage{2, 2, std::vector<float>(16, 0.001f * float(k))}).has_value());
    body += "  <image name=\"i" + std::to_string(k) + "\" type=\"color3\"><input name=\"file\" type=\"filename\" value=\"" +
            file + "\"/></image>\n";
    if (k > 0) {
      body += "  <add name=\"a" + std::to_string(k) + "\" type=\"color3\"><input name=\"in1\" type=\"color3\" nodename=\"" +
              (k == 1 ? std::string("i0") : "a" + std::to_string(k - 1)) + "\"/><input name=\"in2\" type=\"color3\" nodename=\"i" +
              std::to_string(k) + "\"/></add>\n";
    }
  }
  body += "  <open_pbr_surface name=\"s\" type=\"surfaceshader\"><input name=\"base_color\" type=\"color3\" nodename=\"a" +
          std::to_string(count - 1) + "\"/></open_pbr_surface>\n"
          "  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"s\"/></surfacematerial>\n";
  return mtlx(body);
}

TEST(InputSafety, MoreTexturesThanTheDeviceTakesAreAnErrorNotACrash) {
  // Lavapipe takes 32 samplers per stage; a fragment stage holds the material's textures, the
  // albedo tables and the environment: 30 fit, 31 do not (40 crashed inside the device).
  TempFolder folder("textures");
  writeText(folder / "fits.mtlx", manyTexturesDocument(folder, 30));
  CommandRun fits = mxc("render " + (folder / "fits.mtlx").string() + " -o " + (folder / "fits.png").string() +
                        " --size 8 --spp 1 --validation");
  EXPECT_EQ(fits.exitCode, 0) << fits.err;
  EXPECT_TRUE(fs::exists(folder / "fits.png"));
  writeText(folder / "many.mtlx", manyTexturesDocument(folder, 40));
  CommandRun render = mxc("render " + (folder / "many.mtlx").string() + " -o " + (folder / "many.png").string() +
                          " --size 8 --spp 1 --validation");
  EXPECT_EQ(render.exitCode, 1) << render.err;
  EXPECT_NE(render.err.find("error: the vertex stage binds 41 samplers (one per texture), and this device"), std::string::npos)
      << render.err;
  EXPECT_NE(render.err.find("takes at most 32 per stage (maxPerStageDescriptorSamplers)"), std::string::npos) << render.err;
  EXPECT_FALSE(fs::exists(folder / "many.png"));
  writeText(folder / "d.csv", "0,0,1,0,0,1\n");
  CommandRun eval = mxc("eval " + (folder / "many.mtlx").string() + " --dirs " + (folder / "d.csv").string());
  EXPECT_EQ(eval.exitCode, 1) << eval.err;
  EXPECT_NE(eval.err.find("the compute stage binds 41 samplers"), std::string::npos) << eval.err;
}

TEST(InputSafety, EveryMissingTextureUsesItsDefaultHoweverManyTexturesAMaterialReads) {
  // The missing-texture mask went through a float: textures 0 and 25 missing gave 2^25 + 1,
  // which a float rounds to 2^25, so texture 0 sampled the placeholder instead of its default.
  TempFolder folder("missing_textures");
  std::string missing = manyTexturesDocument(folder, 26);
  for (const std::string k : {"0", "25"}) {
    const std::string file = "<input name=\"file\" type=\"filename\" value=\"t" + k + ".exr\"/>";
    ASSERT_NE(missing.find(file), std::string::npos);
    missing.replace(missing.find(file), file.size(),
                    "<input name=\"file\" type=\"filename\" value=\"gone" + k + ".exr\"/>"
                    "<input name=\"default\" type=\"color3\" value=\"0.3, 0.2, 0.1\"/>");
  }
  writeText(folder / "missing.mtlx", missing);
  // The same material with files holding the defaults: the image it should render.
  std::vector<float> texels;
  for (int p = 0; p < 4; ++p) texels.insert(texels.end(), {0.3f, 0.2f, 0.1f, 1.0f});
  for (const std::string k : {"0", "25"}) {
    ASSERT_FALSE(rt::writeImage(folder / ("t" + k + ".exr"), rt::RgbaImage{2, 2, texels}).has_value());
  }
  std::string present = missing;
  for (const std::string k : {"0", "25"}) {
    const std::string gone = "value=\"gone" + k + ".exr\"";
    present.replace(present.find(gone), gone.size(), "value=\"t" + k + ".exr\"");
  }
  writeText(folder / "present.mtlx", present);
  const std::string options = " --size 16 --spp 1 --env none";
  rt::RgbaImage withDefaults = renderCommand((folder / "missing.mtlx").string() + options);
  rt::RgbaImage withFiles = renderCommand((folder / "present.mtlx").string() + options);
  ASSERT_EQ(withDefaults.pixels.size(), withFiles.pixels.size());
  ASSERT_FALSE(withDefaults.pixels.empty());
  float worst = 0.0f, brightest = 0.0f;
  for (size_t i = 0; i < withFiles.pixels.size(); ++i) {
    worst = std::max(worst, std::abs(withDefaults.pixels[i] - withFiles.pixels[i]));
    brightest = std::max(brightest, withFiles.pixels[i]);
  }
  EXPECT_LT(worst, 1e-4f);
  EXPECT_GT(brightest, 0.05f);  // the sphere is lit: the comparison sees the base colour
}

TEST(InputSafety, TexturesPast32HaveTheirOwnMissingMask) {
  // One uint held the bits: texture 32 + k aliased texture k (a target that takes 40 textures).
  TempFolder folder("missing_mask");
  writeText(folder / "40.mtlx", manyTexturesDocument(folder, 40));
  CommandRun compile = mxc("compile " + (folder / "40.mtlx").string() + " -q -o " + (folder / "m.spv").string() +
                           " --glsl " + (folder / "m.glsl").string());
  ASSERT_EQ(compile.exitCode, 0) << compile.err;
  const auto description = nlohmann::json::parse(readFileBytes(folder / "m.json"));
  std::map<std::string, uint32_t> offsets;
  for (const auto& d : description["descriptors"]) {
    if (d["name"] == "mxc_texture_35") {
      EXPECT_EQ(d["missingMember"], "missing_textures_32");
      EXPECT_EQ(d["missingBit"], 3);
    }
    if (d["name"] == "mxc_texture_3") {
      EXPECT_EQ(d["missingMember"], "missing_textures");
      EXPECT_EQ(d["missingBit"], 3);
    }
    if (d["name"] != "MxcParameters") continue;
    for (const auto& m : d["members"]) offsets[m["name"]] = m["offset"];
  }
  ASSERT_TRUE(offsets.count("missing_textures") && offsets.count("missing_textures_32"));
  EXPECT_NE(offsets["missing_textures"], offsets["missing_textures_32"]);
  const std::string glsl = readFileBytes(folder / "m.glsl");
  EXPECT_NE(glsl.find("uint missing_textures_32;"), std::string::npos);
  EXPECT_NE(glsl.find("mxc_params.missing_textures_32) & 8u"), std::string::npos);
  EXPECT_NE(glsl.find("mxc_params.missing_textures) & 8u"), std::string::npos);
}

TEST(InputSafety, CompileSaysWhichTargetsTakeTooFewTextures) {
  // Every target guarantees 16 textures per stage; a raster shader adds the albedo tables and the
  // environment to the material's textures.
  TempFolder folder("texture_targets");
  writeText(folder / "14.mtlx", manyTexturesDocument(folder, 14));
  CommandRun fits = mxc("compile " + (folder / "14.mtlx").string() + " -q -o " + (folder / "a.wgsl").string());
  EXPECT_EQ(fits.exitCode, 0) << fits.err;
  EXPECT_EQ(fits.err.find("warning"), std::string::npos) << fits.err;
  writeText(folder / "15.mtlx", manyTexturesDocument(folder, 15));
  CommandRun over = mxc("compile " + (folder / "15.mtlx").string() + " -q -o " + (folder / "b.wgsl").string());
  EXPECT_EQ(over.exitCode, 0) << over.err;
  EXPECT_NE(over.err.find("warning: material M: the shader samples 17 textures in one stage"), std::string::npos) << over.err;
  EXPECT_NE(over.err.find("wgsl (16, WebGPU's default maxSampledTexturesPerShaderStage"), std::string::npos) << over.err;
  EXPECT_NE(over.err.find("spirv (16, Vulkan's required maxPerStageDescriptorSamplers)"), std::string::npos) << over.err;
}

TEST(InputSafety, AFolderNameThatIsNotUtf8GivesJsonWithAWarning) {
  // JSON is UTF-8; a path is any bytes. The JSON library's exception reached the user (exit 1).
  TempFolder folder("not_utf8");
  const fs::path odd = folder / "bad\xff" "dir";
  fs::create_directories(odd);
  fs::copy_file(corpus("openpbr-presets/open_pbr_default.mtlx"), odd / "m.mtlx");
  const std::string warning = "with bytes that are not UTF-8; JSON holds only UTF-8, so each such byte is written as U+FFFD";
  CommandRun compile = mxc("compile '" + (odd / "m.mtlx").string() + "' -q -o '" + (odd / "m.spv").string() + "'");
  EXPECT_EQ(compile.exitCode, 0) << compile.err;
  EXPECT_NE(compile.err.find("warning: \"" + folder.path().string() + "/bad\\xFFdir/m.json\" holds a name"), std::string::npos)
      << compile.err;
  EXPECT_NE(compile.err.find(warning), std::string::npos) << compile.err;
  const auto description = nlohmann::json::parse(readFileBytes(odd / "m.json"));
  EXPECT_EQ(description["documentFolder"], folder.path().string() + "/bad\xef\xbf\xbd" "dir");
  for (const std::string options : {"--json", "--ir --json", "--effects --json"}) {
    CommandRun inspect = mxc("inspect '" + (odd / "m.mtlx").string() + "' " + options);
    EXPECT_EQ(inspect.exitCode, 0) << options << ": " << inspect.err;
    EXPECT_NE(inspect.err.find("warning: the JSON report holds a name"), std::string::npos) << options << ": " << inspect.err;
    EXPECT_NO_THROW(nlohmann::json::parse(inspect.out)) << options;
  }
}

TEST(InputSafety, ThousandsOfErrorsPrintAFewHundred) {
  TempFolder folder("errors");
  std::string body;
  for (int i = 0; i < 5000; ++i) {
    body += "  <constant name=\"a" + std::to_string(i) + "\" type=\"float\"><input name=\"value\" type=\"float\" value=\"x\"/></constant>\n";
  }
  writeText(folder / "errors.mtlx", mtlx(body));
  CommandRun r = mxc("inspect " + (folder / "errors.mtlx").string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_LT(r.err.size(), 200u << 10) << "bytes of diagnostics";
  EXPECT_NE(r.err.find("4800 more error(s)"), std::string::npos) << r.err.substr(r.err.size() - 300);
  // A 10 MB attribute value is not echoed whole.
  writeText(folder / "value.mtlx", mtlx("  <open_pbr_surface name=\"s\" type=\"surfaceshader\"><input name=\"base_weight\" "
                                        "type=\"float\" value=\"" + std::string(10 << 20, 'x') + "\"/></open_pbr_surface>\n"));
  r = mxc("inspect " + (folder / "value.mtlx").string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_LT(r.err.size(), 4096u) << r.err.substr(0, 300);
}

// --- Misleading or missing messages ----------------------------------------------------------

TEST(InputSafety, ATruncatedJpegIsAWarning) {
  TempFolder folder("jpeg");
  // Cut after its headers: libjpeg decodes what there is, fills the rest with grey, and says so.
  rt::RgbaImage image{256, 256, {}};
  for (uint32_t i = 0; i < 256 * 256; ++i) {
    image.pixels.insert(image.pixels.end(), {float(i % 256) / 256.0f, float(i / 256) / 256.0f, 0.7f, 1.0f});
  }
  ASSERT_FALSE(rt::writeImage(folder / "full.jpg", image).has_value());
  const std::string bytes = readFileBytes(folder / "full.jpg");
  writeText(folder / "cut.jpg", bytes.substr(0, bytes.size() * 3 / 4));
  writeText(folder / "cut.mtlx", imageDocument("cut.jpg"));
  CommandRun r = mxc("render " + (folder / "cut.mtlx").string() + " -o " + (folder / "x.png").string() + " --size 8 --spp 1");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("cut.mtlx:4:5: warning: image '" + (folder / "cut.jpg").string() + "' is damaged"),
            std::string::npos) << r.err;
}

TEST(InputSafety, ControlCharactersOfADocumentAreNotEchoedRaw) {
  TempFolder folder("escape");
  writeText(folder / "esc.mtlx", mtlx("  <foo name=\"a\x1b[31mRED\x07\" />\n"));
  CommandRun r = mxc("inspect " + (folder / "esc.mtlx").string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << "an ESC byte reached the terminal";
  EXPECT_EQ(r.err.find('\x07'), std::string::npos);
  EXPECT_NE(r.err.find("a?[31mRED"), std::string::npos) << r.err;
}

// --- Where mxc finds its image module --------------------------------------------------------

TEST(InputSafety, AnInstalledMxcRendersFromAnotherFolder) {
  TempFolder folder("install");
  const fs::path first = folder / "first", moved = folder / "moved";
  const std::string install = std::string(MXC_CMAKE) + " --install " + MXC_BUILD_DIR + " --prefix " + first.string() +
                              " > /dev/null";
  ASSERT_EQ(std::system(install.c_str()), 0);
  // The shell completions and the man page, generated from the command-line definition.
  for (const char* doc : {"share/bash-completion/completions/mxc", "share/zsh/vendor-completions/_mxc",
                          "share/man/man1/mxc.1"}) {
    EXPECT_TRUE(fs::is_regular_file(first / doc) && fs::file_size(first / doc) > 1000) << doc;
  }
  fs::rename(first, moved);  // relocatable: nothing of the first prefix may be needed
  const std::string binary = (moved / "bin/mxc").string();
  const std::string run = "cd " + folder.path().string() + " && " + binary + " render " + corpus(kDefault) +
                          " -o out.png --size 16 --spp 1 > /dev/null";
  EXPECT_EQ(std::system(run.c_str()), 0);
  auto image = rt::readImage(folder / "out.png");
  ASSERT_TRUE(std::holds_alternative<rt::RgbaImage>(image));
  EXPECT_EQ(std::get<rt::RgbaImage>(image).width, 16u);
  // Without its module, mxc says so before rendering, with exit code 3.
  fs::copy_file(moved / "bin/mxc", folder / "lone-mxc");
  const std::string lone = "cd " + folder.path().string() + " && ./lone-mxc render " + corpus(kDefault) +
                           " -o lone.png --size 16 --spp 1 2> lone.err";
  const int status = std::system(lone.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 3) << status;
  EXPECT_NE(readFileBytes(folder / "lone.err").find("cannot load the image I/O module libmxc_imageio.so"), std::string::npos)
      << readFileBytes(folder / "lone.err");
  EXPECT_FALSE(fs::exists(folder / "lone.png"));
}

}  // namespace
}  // namespace mxc::test
