// The depfile's spelling of paths, checked against the two tools that read it: for each awkward
// file name, a real GNU Make and a real Ninja must find the rule up to date after a build and out
// of date once its input is newer. Names no spelling serves in both are refused, with the reason.

#include "cli/Depfile.h"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <functional>

#include "support/CommandSupport.h"

namespace mxc::test {
namespace {

using cli::depfileWord;

std::string word(const std::string& path) {
  std::string error;
  auto out = depfileWord(path, error);
  EXPECT_TRUE(out.has_value()) << path << ": " << error;
  return out.value_or("");
}

std::string refusal(const std::string& path) {
  std::string error;
  EXPECT_FALSE(depfileWord(path, error).has_value()) << path;
  return error;
}

TEST(Depfile, EscapesWhatMakeAndNinjaReadSpecially) {
  EXPECT_EQ(word("/a/plain.mtlx"), "/a/plain.mtlx");
  EXPECT_EQ(word("/a/my doc.mtlx"), "/a/my\\ doc.mtlx");
  EXPECT_EQ(word("/a/x#1"), "/a/x\\#1");
  EXPECT_EQ(word("/a/$HOME"), "/a/$$HOME");
  EXPECT_EQ(word("/a/c:d"), "/a/c\\:d");
  EXPECT_EQ(word("/a/b\\ c"), "/a/b\\\\\\ c") << "2N+1 backslashes before a space";
  EXPECT_EQ(word("/a/b\\c"), "/a/b\\c") << "a backslash before an ordinary character stays";
  EXPECT_EQ(word("/a/[x]{y}@!~,+\xc3\xa9"), "/a/[x]{y}@!~,+\xc3\xa9");
}

TEST(Depfile, RefusesNamesWithNoSpellingBothToolsRead) {
  EXPECT_NE(refusal("/a/50%.mtlx").find("'%'"), std::string::npos);
  EXPECT_NE(refusal("/a/50%.mtlx").find("pattern"), std::string::npos);
  EXPECT_NE(refusal("/a/x=y").find("assignment"), std::string::npos);
  EXPECT_NE(refusal("/a/v(2)").find("archive member"), std::string::npos);
  EXPECT_NE(refusal("/a/x;y").find("recipe"), std::string::npos);
  EXPECT_NE(refusal("/a/x|y").find("order-only"), std::string::npos);
  EXPECT_NE(refusal("/a/bob's").find("Ninja 1.11"), std::string::npos);
  EXPECT_NE(refusal("/a/x*y").find("Ninja 1.11"), std::string::npos);
  EXPECT_NE(refusal("/a/x\ny").find("a line break"), std::string::npos);
  EXPECT_NE(refusal("/a/x\ty").find("a tab"), std::string::npos);
  EXPECT_NE(refusal("/a/x\\#y").find("backslash before '#'"), std::string::npos);
  EXPECT_NE(refusal("/a/x\\:y").find("backslash before ':'"), std::string::npos);
  EXPECT_NE(refusal("/a/x\\$y").find("backslash before '$'"), std::string::npos);
  EXPECT_NE(refusal("/a/x\\").find("ends in a backslash"), std::string::npos);
  EXPECT_NE(refusal("/a/x%y").find("/a/x%y"), std::string::npos) << "the message names the path";
}

/// Runs a shell command in `folder`, returning its standard output and exit code.
std::pair<std::string, int> shell(const fs::path& folder, const std::string& command) {
  const std::string line = "cd '" + folder.string() + "' && " + command + " 2>&1";
  FILE* pipe = ::popen(line.c_str(), "r");
  std::string out;
  if (!pipe) return {out, -1};
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) out.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  return {out, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
}

void setAge(const fs::path& path, std::chrono::seconds offset) {
  fs::last_write_time(path, fs::file_time_type::clock::now() + offset);
}

/// A Ninja path: '$' escapes '$', ' ' and ':' in a build file (the ninja manual's "Lexical syntax").
std::string ninjaPath(const std::string& path) {
  std::string out;
  for (char c : path) {
    if (c == '$' || c == ' ' || c == ':') out += '$';
    out += c;
  }
  return out;
}

/// The dry run `dryRun` in `folder` finds the rule up to date while `input` is older than the
/// output, and out of date (`wouldRebuild` of its output) once the input is newer.
void expectTracksInput(const TempFolder& folder, const fs::path& input, const std::string& dryRun,
                       const std::function<bool(const std::string&)>& wouldRebuild) {
  setAge(input, std::chrono::seconds(-100));
  const auto [fresh, freshCode] = shell(folder.path(), dryRun);
  EXPECT_EQ(freshCode, 0) << fresh;
  EXPECT_FALSE(wouldRebuild(fresh)) << "up to date after the build: " << fresh;
  setAge(input, std::chrono::seconds(100));
  const auto [stale, staleCode] = shell(folder.path(), dryRun);
  EXPECT_EQ(staleCode, 0) << stale;
  EXPECT_TRUE(wouldRebuild(stale)) << "out of date once the input is newer: " << stale;
}

const char* const kAwkwardNames[] = {"plain", "my doc", "x#1", "cost$5", "c:d", "b\\ c", "b\\c", "b\\\\ c", "[x]{y}@!~,+", "\xc3\xa9t\xc3\xa9"};

TEST(Depfile, GnuMakeReadsEachNameBackAsTheFileItNames) {
  for (const std::string name : kAwkwardNames) {
    SCOPED_TRACE(name);
    TempFolder folder("depfile_make");
    const fs::path input = folder / ("in " + name), output = folder / ("out " + name + ".glsl");
    writeText(input, "x");
    writeText(output, "y");
    writeText(folder / "dep.d", word(output.string()) + ": \\\n  " + word(input.string()) + "\n");
    // The depfile's rule is the first, so the default goal; the pattern rule gives it a recipe.
    writeText(folder / "Makefile", "include dep.d\n%.glsl:\n\t@echo REMADE\n");
    expectTracksInput(folder, input, "make -n", [](const std::string& out) { return out.find("REMADE") != std::string::npos; });
  }
}

TEST(Depfile, NinjaReadsEachNameBackAsTheFileItNames) {
  for (const std::string name : kAwkwardNames) {
    SCOPED_TRACE(name);
    TempFolder folder("depfile_ninja");
    const fs::path input = folder / ("in " + name), output = folder / ("out " + name + ".glsl");
    writeText(input, "x");
    setAge(input, std::chrono::seconds(-100));
    writeText(folder / "dep.d", word(output.string()) + ": \\\n  " + word(input.string()) + "\n");
    // `deps = gcc`: Ninja reads the depfile after the command, as it does for a compiler's.
    writeText(folder / "build.ninja", "rule gen\n  command = touch $out && cp dep.d $out.d\n  depfile = $out.d\n"
                                      "  deps = gcc\nbuild " + ninjaPath(output.string()) + ": gen\n");
    const auto [built, builtCode] = shell(folder.path(), "ninja");
    ASSERT_EQ(builtCode, 0) << built;
    expectTracksInput(folder, input, "ninja -n",
                      [](const std::string& out) { return out.find("no work to do") == std::string::npos; });
  }
}

TEST(Depfile, ACompileWhosePathCannotBeSpelledWritesNothing) {
  TempFolder folder("depfile_refused");
  const CommandRun run = mxc("compile " + corpus("openpbr-presets/open_pbr_default.mtlx") + " -q -o '" +
                             (folder / "m%1.spv").string() + "' --depfile " + (folder / "m.d").string());
  EXPECT_EQ(run.exitCode, 3) << run.err;
  EXPECT_NE(run.err.find("error: --depfile " + (folder / "m.d").string() + ": " + (folder / "m%1.spv").string() +
                         " holds '%'"),
            std::string::npos)
      << run.err;
  EXPECT_TRUE(folder.entries().empty()) << "nothing written";
}

}  // namespace
}  // namespace mxc::test
