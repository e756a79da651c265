// What the commands promise about their outputs (README, "Outputs"): nothing destroyed, nothing
// half-written, every write checked, outputs committed together, temporaries removed on an
// interrupt. Special files are private FIFOs and device nodes in a temporary folder; a full disk
// is the file-size limit (ulimit -f), a small tmpfs where the machine lets a test mount one, or
// /dev/full; signals go to a child process.

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <chrono>
#include <csignal>
#include <thread>

#include "runtime/ImageIO.h"
#include "support/CommandSupport.h"

namespace mxc::test {
namespace {

const std::string kDefault = "materialx/examples/OpenPbr/open_pbr_default.mtlx";

/// A document with two materials, "first" and "second".
const std::string kTwoMaterials = mtlx(
    "  <open_pbr_surface name=\"s1\" type=\"surfaceshader\" />\n"
    "  <surfacematerial name=\"first\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" "
    "nodename=\"s1\" /></surfacematerial>\n"
    "  <open_pbr_surface name=\"s2\" type=\"surfaceshader\"><input name=\"base_color\" type=\"color3\" "
    "value=\"0.8, 0.1, 0.1\" /></open_pbr_surface>\n"
    "  <surfacematerial name=\"second\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" "
    "nodename=\"s2\" /></surfacematerial>\n");


bool isSpirv(const std::string& bytes) {
  return bytes.size() >= 20 && static_cast<unsigned char>(bytes[0]) == 0x03 && static_cast<unsigned char>(bytes[3]) == 0x07;
}

mode_t modeOf(const fs::path& path) {
  struct stat st {};
  ::lstat(path.c_str(), &st);
  return st.st_mode;
}

/// No temporary of mxc's left in the folder.
void expectNoTemporaries(const TempFolder& folder) {
  for (const std::string& name : folder.entries()) EXPECT_EQ(name.find(".mxc-"), std::string::npos) << name;
}

/// Reads a FIFO on a thread until its writer closes it.
class FifoReader {
 public:
  explicit FifoReader(fs::path path) : thread_([this, path] { bytes_ = readFileBytes(path); }) {}
  std::string finish() {
    thread_.join();
    return bytes_;
  }

 private:
  std::string bytes_;
  std::thread thread_;
};

// --- Special files and links --------------------------------------------------------------

TEST(OutputSafety, FifoAndDeviceOutputsAreWrittenThroughNotReplaced) {
  TempFolder folder("special");
  const fs::path fifo = folder / "module.spv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  FifoReader reader(fifo);
  CommandRun r = mxc("compile " + corpus(kDefault) + " -q -o " + fifo.string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(isSpirv(reader.finish())) << "the FIFO's reader gets the module";
  EXPECT_TRUE(S_ISFIFO(modeOf(fifo))) << "the FIFO is still a FIFO";

  // A private copy of /dev/null (character device 1,3): needs CAP_MKNOD, which CI has as root.
  const fs::path null = folder / "null";
  if (::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0) GTEST_SKIP() << "mknod is not permitted here";
  for (const std::string& command : {"compile " + corpus(kDefault) + " -q -o " + null.string() + " --glsl " + null.string(),
                                     "inspect --json -o " + null.string() + " " + corpus(kDefault)}) {
    r = mxc(command);
    EXPECT_EQ(r.exitCode, 0) << command << ": " << r.err;
    EXPECT_TRUE(S_ISCHR(modeOf(null))) << command << ": the device node was replaced by a regular file";
  }
  expectNoTemporaries(folder);
}

TEST(OutputSafety, SymbolicLinksAreFollowedAndKept) {
  TempFolder folder("links");
  writeText(folder / "real.spv", "old");
  fs::create_symlink("real.spv", folder / "link.spv");
  fs::create_symlink("created.glsl", folder / "dangling.glsl");
  CommandRun r = mxc("compile " + corpus(kDefault) + " -q -o " + (folder / "link.spv").string() + " --glsl " +
                     (folder / "dangling.glsl").string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(folder / "link.spv"));
  EXPECT_TRUE(isSpirv(readFileBytes(folder / "real.spv"))) << "the file the link names holds the module";
  EXPECT_TRUE(fs::is_symlink(folder / "dangling.glsl"));
  EXPECT_EQ(readFileBytes(folder / "created.glsl").rfind("#version 400", 0), 0u) << "a dangling link's target is created";
  expectNoTemporaries(folder);
}

TEST(OutputSafety, ReplacingAFileKeepsItsMode) {
  TempFolder folder("mode");
  const fs::path out = folder / "private.spv";
  writeText(out, "old");
  fs::permissions(out, fs::perms::owner_read | fs::perms::owner_write);
  CommandRun r = mxc("compile " + corpus(kDefault) + " -q -o " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(isSpirv(readFileBytes(out)));
  EXPECT_EQ(modeOf(out) & 07777, 0600u);
  // A new file gets what open(2) would give it: 0666 without the umask (022 here).
  r = mxc("compile " + corpus(kDefault) + " -q -o " + (folder / "new.spv").string(), "umask 022;");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(modeOf(folder / "new.spv") & 07777, 0644u);
}

// --- Full disks and standard output -------------------------------------------------------

TEST(OutputSafety, AFullDiskKeepsTheOldFileAndExits3) {
  TempFolder folder("full");
  // The file-size limit makes every write past 8 blocks fail (EFBIG), on any file system.
  const std::string limit = "ulimit -f 8;";
  writeText(folder / "keep.spv", "old spv");
  CommandRun r = mxc("compile " + corpus(kDefault) + " -q -o " + (folder / "keep.spv").string(), limit);
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("cannot write '" + (folder / "keep.spv").string() + "'"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(".mxc-"), std::string::npos) << "errors name the output, not the temporary: " << r.err;
  EXPECT_EQ(readFileBytes(folder / "keep.spv"), "old spv");
  // Every image format, in one render: none is replaced.
  std::string outputs;
  for (const char* ext : {".png", ".bmp", ".tga", ".jpg", ".exr"}) {
    writeText(folder / (std::string("keep") + ext), "old image");
    outputs += " -o " + (folder / (std::string("keep") + ext)).string();
  }
  r = mxc("render " + corpus(kDefault) + outputs + " --size 128 --spp 1", limit);
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_EQ(r.out.find("wrote"), std::string::npos) << r.out;
  for (const char* ext : {".png", ".bmp", ".tga", ".jpg", ".exr"}) {
    EXPECT_EQ(readFileBytes(folder / (std::string("keep") + ext)), "old image") << ext;
  }
  expectNoTemporaries(folder);
}

TEST(OutputSafety, AFullTmpfsKeepsTheOldFile) {
  // A real full file system: a 64 KiB tmpfs, mounted in a private user and mount namespace.
  if (std::system("unshare -rm true 2>/dev/null") != 0) GTEST_SKIP() << "no private mount namespace here (unshare -rm)";
  TempFolder folder("tmpfs");
  fs::create_directories(folder / "small");
  const std::string mount = (folder / "small").string();
  // One render to every format; the images of a 256x256 render do not all fit in 64 KiB.
  std::string outputs;
  for (const char* ext : {"png", "bmp", "tga", "jpg", "exr"}) outputs += " -o " + mount + "/keep." + ext;
  writeText(folder / "script.sh",
            "mount -t tmpfs -o size=64k none " + mount + " || exit 99\n"
            "for ext in png bmp tga jpg exr; do echo old > " + mount + "/keep.$ext; done\n"
            MXC_BINARY " render " + corpus(kDefault) + outputs + " --size 256 --spp 1 2>" + (folder / "err").string() + "\n"
            "echo \"$?\" > " + (folder / "result").string() + "\n"
            "for ext in png bmp tga jpg exr; do cat " + mount + "/keep.$ext >> " + (folder / "result").string() + "; done\n"
            "ls -A " + mount + " | wc -l >> " + (folder / "result").string() + "\n");
  const int status = std::system(("unshare -rm sh " + (folder / "script.sh").string()).c_str());
  if (WIFEXITED(status) && WEXITSTATUS(status) == 99) GTEST_SKIP() << "tmpfs cannot be mounted here";
  // Exit 3, every old file as it was, and no temporary: five files in the file system.
  EXPECT_EQ(readFileBytes(folder / "result"), "3\nold\nold\nold\nold\nold\n5\n");
  EXPECT_NE(readFileBytes(folder / "err").find("No space left on device"), std::string::npos) << readFileBytes(folder / "err");
}

TEST(OutputSafety, StandardOutputErrorsExit3) {
  for (const std::string redirect : {">/dev/full", ">&-"}) {
    CommandRun r = mxc("inspect --json " + corpus(kDefault), "", redirect);
    EXPECT_EQ(r.exitCode, 3) << redirect << ": " << r.err;
    EXPECT_NE(r.err.find("cannot write to standard output"), std::string::npos) << r.err;
    // The summary lines of compile go to standard output too.
    r = mxc("compile " + corpus(kDefault), "", redirect);
    EXPECT_EQ(r.exitCode, 3) << redirect << ": " << r.err;
  }
  // -q prints nothing: a closed standard output is then no error.
  EXPECT_EQ(mxc("compile -q " + corpus(kDefault), "", ">&-").exitCode, 0);
}

// Standard output cannot be taken back: the regular files of the set are replaced only once it
// was written. Before, `-o - --glsl g.glsl >/dev/full` exited 3 with g.glsl already replaced.
TEST(OutputSafety, AFailedStandardOutputReplacesNoFileOfTheSet) {
  TempFolder folder("stdout_first");
  writeText(folder / "g.glsl", "old");
  writeText(folder / "a.exr", "old");
  CommandRun r = mxc("compile " + corpus(kDefault) + " -o - --glsl " + (folder / "g.glsl").string(), "", ">/dev/full");
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("standard output"), std::string::npos) << r.err;
  EXPECT_EQ(readFileBytes(folder / "g.glsl"), "old");
  r = mxc("render " + corpus(kDefault) + " -o " + (folder / "a.exr").string() + " -o - --format png --size 16 --spp 1", "",
          ">/dev/full");
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_EQ(readFileBytes(folder / "a.exr"), "old");
  expectNoTemporaries(folder);
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"a.exr", "g.glsl"}));
  // With standard output writable, both are written.
  r = mxc("compile " + corpus(kDefault) + " -o - --glsl " + (folder / "g.glsl").string(), "", ">/dev/null");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readFileBytes(folder / "g.glsl").rfind("#version", 0), 0u);
}

// `-o dir/` names no file: refused for two materials as for one, not written as dir/_first.
TEST(OutputSafety, AFolderAsTheOutputOfSeveralMaterialsIsRefused) {
  TempFolder folder("folder_output");
  writeText(folder / "two.mtlx", kTwoMaterials);
  fs::create_directory(folder / "out");
  for (const std::string command : {"compile", "render"}) {
    for (const std::string& output : {(folder / "out").string() + "/", (folder / "out").string()}) {
      const std::string options = command == "render" ? " --size 16 --spp 1" : "";
      CommandRun r = mxc(command + " " + (folder / "two.mtlx").string() + " -o " + output + options);
      EXPECT_EQ(r.exitCode, 3) << command << " -o " << output << ": " << r.err;
      EXPECT_NE(r.err.find("it is a directory"), std::string::npos) << r.err;
      EXPECT_TRUE(fs::is_empty(folder / "out")) << command << " -o " << output;
    }
  }
}

// --- Outputs against inputs and each other ------------------------------------------------

TEST(OutputSafety, AnOutputThatIsAnInputIsAUsageError) {
  TempFolder folder("overinput");
  const fs::path doc = folder / "a.mtlx";
  fs::copy_file(corpus(kDefault), doc);
  const std::string original = readFileBytes(doc);
  fs::create_hard_link(doc, folder / "hard.mtlx");
  fs::create_symlink("a.mtlx", folder / "soft.spv");
  for (const std::string& out : {doc.string(), (folder / "hard.mtlx").string(), (folder / "soft.spv").string()}) {
    CommandRun r = mxc("compile " + doc.string() + " -o " + out);
    EXPECT_EQ(r.exitCode, 2) << out;
    EXPECT_NE(r.err.find("writing it would destroy that input"), std::string::npos) << r.err;
    r = mxc("inspect " + doc.string() + " -o " + out);
    EXPECT_EQ(r.exitCode, 2) << out;
  }
  EXPECT_EQ(readFileBytes(doc), original);
  // An included document, an image the material reads, and eval's direction table.
  writeText(folder / "inc.mtlx", mtlx("  <constant name=\"k\" type=\"float\" />\n"));
  writeText(folder / "main.mtlx",
            "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
            "  <xi:include href=\"inc.mtlx\" />\n" +
                imageDocument("tex.png").substr(std::string("<?xml version=\"1.0\"?>\n<materialx version=\"1.39\">\n").size()));
  ASSERT_FALSE(rt::writeImage(folder / "tex.png", rt::RgbaImage{1, 1, {0.5f, 0.5f, 0.5f, 1.0f}}).has_value());
  CommandRun r = mxc("compile " + (folder / "main.mtlx").string() + " -o " + (folder / "inc.mtlx").string());
  EXPECT_EQ(r.exitCode, 2) << r.err;
  r = mxc("compile " + (folder / "main.mtlx").string() + " --glsl " + (folder / "tex.png").string());
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("an image file this command reads"), std::string::npos) << r.err;
  writeText(folder / "dirs.csv", "0,0,1,0,0,1\n");
  r = mxc("eval " + corpus(kDefault) + " --dirs " + (folder / "dirs.csv").string() + " -o " + (folder / "dirs.csv").string());
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_EQ(readFileBytes(folder / "dirs.csv"), "0,0,1,0,0,1\n");
}

TEST(OutputSafety, TwoOutputsOnOnePathAreAUsageError) {
  TempFolder folder("twice");
  const std::string same = (folder / "same").string();
  CommandRun r = mxc("compile " + corpus(kDefault) + " -o " + same + " --glsl " + same);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("-o '" + same + "' and --glsl '" + same + "' name the same file"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(same));
  // Spelled differently, expanded per material (_<material>): still one file each.
  writeText(folder / "names.mtlx", kTwoMaterials);
  r = mxc("compile " + (folder / "names.mtlx").string() + " -o " + (folder / "m.spv").string() + " --glsl " +
          (folder / "./m.spv").string());
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("m_first.spv' and --glsl '"), std::string::npos) << r.err;
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"names.mtlx"}));
  // Through a link to the folder, and through `..` out of a link to a folder elsewhere: the
  // folders are resolved, not compared as spelled.
  fs::create_directories(folder / "real" / "deep");
  fs::create_directory_symlink(folder / "real", folder / "link");
  fs::create_directory_symlink(folder / "real" / "deep", folder / "hop");
  r = mxc("compile " + corpus(kDefault) + " -o " + (folder / "real" / "x").string() + " --glsl " +
          (folder / "link" / "x").string());
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("name the same file"), std::string::npos) << r.err;
  r = mxc("compile " + corpus(kDefault) + " -o " + (folder / "real" / "y").string() + " --glsl " +
          (folder / "hop" / ".." / "y").string());
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("name the same file"), std::string::npos) << r.err;
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"hop", "link", "names.mtlx", "real"}));
}

// --- Sets of outputs ----------------------------------------------------------------------

TEST(OutputSafety, ASetOfOutputsIsCommittedTogether) {
  TempFolder folder("set");
  // The second material reads an image that is a folder: an error, found before anything is
  // rendered, and no image of the first material is written either.
  fs::create_directories(folder / "texdir");
  std::string doc = kTwoMaterials;
  doc.replace(doc.find("<input name=\"base_color\" type=\"color3\" value=\"0.8, 0.1, 0.1\" />"),
              std::string("<input name=\"base_color\" type=\"color3\" value=\"0.8, 0.1, 0.1\" />").size(),
              "<input name=\"base_color\" type=\"color3\" nodename=\"tex\" />");
  doc.replace(doc.find("  <open_pbr_surface name=\"s2\""), 0,
              "  <image name=\"tex\" type=\"color3\"><input name=\"file\" type=\"filename\" value=\"texdir\" /></image>\n");
  writeText(folder / "two.mtlx", doc);
  CommandRun r = mxc("render " + (folder / "two.mtlx").string() + " -o " + (folder / "r.png").string() + " --size 16 --spp 1");
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("it is a directory"), std::string::npos) << r.err;
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"texdir", "two.mtlx"}));
  // Without the fault, every output of every material is written.
  writeText(folder / "two.mtlx", kTwoMaterials);
  r = mxc("compile " + (folder / "two.mtlx").string() + " -q -o " + (folder / "m.spv").string() + " --glsl " +
          (folder / "m.glsl").string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(folder.entries(),
            (std::vector<std::string>{"m_first.glsl", "m_first.json", "m_first.spv", "m_first.vert.spv", "m_second.glsl",
                                      "m_second.json", "m_second.spv", "m_second.vert.spv", "texdir", "two.mtlx"}));
}

TEST(OutputSafety, AnUnwritableFolderIsFoundBeforeTheWork) {
  // It was found when the image was written, after the render (10.9 s for a large one); a
  // missing folder was found at once. Root writes where permissions forbid, so as root the test
  // uses /sys, which refuses everyone.
  TempFolder folder("unwritable");
  fs::path locked = folder / "locked";
  fs::create_directories(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  if (::geteuid() == 0) locked = "/sys";
  const CommandRun r = mxc("render " + corpus(kDefault) + " -o " + (locked / "x.png").string() + " --size 16 --spp 1");
  EXPECT_EQ(r.exitCode, 3) << r.err;
  // The option's name says the declaration refused it (a late write failure does not name it).
  EXPECT_NE(r.err.find("error: -o: cannot write '" + (locked / "x.png").string() + "': Permission denied"), std::string::npos)
      << r.err;
  const CommandRun c = mxc("compile " + corpus(kDefault) + " -q -o " + (folder / "ok.spv").string() + " --glsl " +
                           (locked / "x.glsl").string());
  EXPECT_EQ(c.exitCode, 3) << c.err;
  EXPECT_NE(c.err.find("error: --glsl: cannot write"), std::string::npos) << c.err;
  fs::permissions(folder / "locked", fs::perms::owner_all);
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"locked"})) << "nothing written, no temporary left";
  EXPECT_TRUE(fs::is_empty(folder / "locked"));
}

TEST(OutputSafety, TerminationSignalsRemoveTemporariesAndCommitNothing) {
  TempFolder folder("signals");
  const fs::path doc = folder / "two.mtlx";
  writeText(doc, kTwoMaterials);
  // SIGUSR1, SIGALRM and SIGPIPE end a process by default too, and left the temporaries.
  for (int signal : {SIGINT, SIGTERM, SIGHUP, SIGUSR1, SIGALRM, SIGPIPE}) {
    writeText(folder / "r_first.png", "old");
    writeText(folder / "r_second.png", "old");
    // The first material's images are staged (temporaries) while the second one renders.
    pid_t pid = spawnMxc({"render", doc.string(), "-o", (folder / "r.png").string(), "-o", (folder / "r.exr").string(),
                          "--size", "32", "--spp", "150"});
    ASSERT_GT(pid, 0);
    bool staged = false;
    for (int i = 0; i < 3000 && !staged; ++i) {  // up to 60 s
      for (const std::string& name : folder.entries()) staged = staged || name.rfind(".mxc-", 0) == 0;
      if (!staged) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    EXPECT_TRUE(staged) << "no temporary appeared";
    ::kill(pid, signal);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "signal " << signal << ", status " << status;
    EXPECT_EQ(folder.entries(), (std::vector<std::string>{"r_first.png", "r_second.png", "two.mtlx"})) << signal;
    EXPECT_EQ(readFileBytes(folder / "r_first.png"), "old");
  }
}

TEST(OutputSafety, ConcurrentWritersOfOnePathAllSucceed) {
  TempFolder folder("concurrent");
  const std::string out = (folder / "same.exr").string();
  std::vector<pid_t> children;
  for (int i = 0; i < 4; ++i) {
    children.push_back(spawnMxc({"render", corpus(kDefault), "-o", out, "--size", "16", "--spp", "1"}));
    ASSERT_GT(children.back(), 0);
  }
  for (pid_t pid : children) {
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
  }
  auto image = rt::readImage(out);
  ASSERT_TRUE(std::holds_alternative<rt::RgbaImage>(image));
  EXPECT_EQ(std::get<rt::RgbaImage>(image).width, 16u);
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"same.exr"}));
}

TEST(OutputSafety, ALongFileNameIsWritten) {
  // 254 bytes is a legal name (NAME_MAX 255); a temporary named after it plus a suffix is not.
  // The longest output is the vertex stage beside the SPIR-V (x.vert.spv for x.spv).
  TempFolder folder("long");
  const std::string stem(245, 'n');
  CommandRun r = mxc("compile " + corpus(kDefault) + " -q -o " + (folder / (stem + ".spv")).string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  ASSERT_EQ((stem + ".vert.spv").size(), 254u);
  EXPECT_TRUE(isSpirv(readFileBytes(folder / (stem + ".vert.spv"))));
  EXPECT_TRUE(isSpirv(readFileBytes(folder / (stem + ".spv"))));
}

// --- Options checked before the work ------------------------------------------------------

TEST(OutputSafety, NumericOptionsMustBeFinite) {
  for (const std::string option : {"--exposure inf", "--exposure nan", "--exposure 1e9", "--env-intensity nan",
                                    "--env-intensity -1", "--emission-scale inf", "--light dir:1,1,1:nan"}) {
    CommandRun r = mxc("render " + corpus(kDefault) + " -o " + (fs::temp_directory_path() / "mxc_never.png").string() + " " + option);
    EXPECT_EQ(r.exitCode, 2) << option << ": " << r.err;
  }
}

TEST(OutputSafety, TheImageFormatIsCheckedBeforeRendering) {
  TempFolder folder("format");
  // Checked once the material is compiled (the image module loads meanwhile), before any frame:
  // a render of 100000 samples per pixel would take minutes, the refusal takes a second.
  for (const std::string out : {"noext", "x.sgi", "x.nosuchformat"}) {
    const auto start = std::chrono::steady_clock::now();
    CommandRun r = mxc("render " + corpus(kDefault) + " -o " + (folder / out).string() + " --size 256 --spp 100000");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exitCode, 2) << out << ": " << r.err;
    EXPECT_NE(r.err.find("error: -o '"), std::string::npos) << r.err;
    EXPECT_LT(seconds, 60.0) << "frames were rendered before the format was checked";
  }
  // Scenes too.
  CommandRun r = mxc("render " + (fs::path(MXC_SOURCE_DIR) / "examples/scenes/still_life.json").string() + " -o " +
                     (folder / "x.nosuchformat").string() + " --spp 100000");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("error: -o '"), std::string::npos) << r.err;
  EXPECT_TRUE(folder.entries().empty());
}

}  // namespace
}  // namespace mxc::test
