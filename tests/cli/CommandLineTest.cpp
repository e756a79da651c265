// The conventions of the command line (cli/CommandLine.cpp): `-` is standard output for every
// -o, --help shows the defaults, -q and -v on every command, --version names the libraries and
// devices, an unknown command is named, a missing device has its own exit code.

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli/CommandSpec.h"
#include "support/CommandSupport.h"

namespace mxc::test {
namespace {

const std::string kDefault = "materialx/examples/OpenPbr/open_pbr_default.mtlx";

TEST(CommandLine, DashIsStandardOutputForEveryOutput) {
  const std::string doc = corpus(kDefault);
  CommandRun r = mxc("compile " + doc + " -o -");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  ASSERT_GE(r.out.size(), 4u);
  EXPECT_EQ(r.out.substr(0, 4), std::string("\x03\x02\x23\x07", 4)) << "the SPIR-V magic number, little-endian, alone";
  r = mxc("compile " + doc + " --glsl -");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.rfind("#version 400", 0), 0u) << r.out.substr(0, 80);
  r = mxc("render " + doc + " -o - --format png --size 16 --spp 1");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << "a PNG and nothing else";
  r = mxc("inspect " + doc + " -o -");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.rfind("document", 0), 0u);
  r = mxc("furnace " + doc + " -o - --angles 1 --samples 64");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.rfind("{", 0), 0u);
  const fs::path dirs = writeTemp("dash_dirs.csv", "0,0,1,0,0,1\n");
  r = mxc("eval " + doc + " --dirs " + dirs.string() + " -o -");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.rfind("material,row,", 0), 0u);
  fs::remove(dirs);
  // An image needs its format; standard output holds one material's output.
  r = mxc("render " + doc + " -o -");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("give it with --format"), std::string::npos) << r.err;
  const fs::path two = writeTemp("dash_two.mtlx", kTwoMaterialsOfOneShader);
  r = mxc("compile " + two.string() + " -o -");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("choose one with --material"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
  r = mxc("compile " + two.string() + " -o - --material B");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  fs::remove(two);
}

// `mxc compile --library DIR FILE -o OUT` failed with "no document to compile": a list option
// took every word after it, FILE included. Every repeatable option of every command takes one
// value per occurrence, before or after the positional.
TEST(CommandLine, EachOptionTakesOneValuePerOccurrenceBeforeOrAfterTheDocument) {
  const cli::CommandSpec top = cli::describeCommandLine();
  std::vector<std::pair<std::vector<std::string>, const cli::CommandSpec*>> commands;
  for (const cli::CommandSpec& c : top.commands) {
    if (c.commands.empty()) commands.push_back({{c.name}, &c});
    for (const cli::CommandSpec& sub : c.commands) commands.push_back({{c.name, sub.name}, &sub});
  }
  const std::string folderA = fs::temp_directory_path().string(), folderB = sourceDir().string();
  std::set<std::string> checked;
  for (const auto& [path, command] : commands) {
    std::string positional;
    for (const cli::OptionSpec& o : command->options) {
      if (!o.positional.empty()) positional = o.positional;
    }
    for (const cli::OptionSpec& o : command->options) {
      // The command's other required options, given once (render's -o, eval's --dirs).
      std::vector<std::string> required;
      for (const cli::OptionSpec& other : command->options) {
        if (other.required && !other.names.empty() && &other != &o) required.insert(required.end(), {other.names.front(), "x.csv"});
      }
      if (!o.repeatable || o.names.empty() || o.value.empty()) continue;
      const std::string& name = o.names.front();
      // Values the option's own check accepts.
      std::string a = folderA, b = folderB;
      if (!o.choices.empty()) a = o.choices.front(), b = o.choices.back();
      else if (o.number) a = "1", b = "2";
      else if (o.value == "INPUT=VALUE") a = "base_weight=1", b = "coat_weight=1";
      const std::string joined = fmt::format("{}", fmt::join(path, " "));
      std::vector<std::string> before = path;
      before.insert(before.end(), {name, a, "doc.mtlx"});
      before.insert(before.end(), required.begin(), required.end());
      std::vector<std::string> after = path;
      after.insert(after.end(), {"doc.mtlx", name, a, name, b});
      after.insert(after.end(), required.begin(), required.end());
      try {
        const cli::ParsedCommandLine first = cli::parseCommandLineWords(before);
        EXPECT_EQ(first.command, joined);
        EXPECT_EQ(first.values.at(name), std::vector<std::string>{a}) << joined << " " << name << " " << a << " doc.mtlx";
        if (!positional.empty()) {
          EXPECT_EQ(first.values.at(positional), std::vector<std::string>{"doc.mtlx"}) << joined << " " << name;
        }
        const cli::ParsedCommandLine second = cli::parseCommandLineWords(after);
        EXPECT_EQ(second.values.at(name), (std::vector<std::string>{a, b})) << joined << " doc.mtlx " << name;
        if (!positional.empty()) {
          EXPECT_EQ(second.values.at(positional), std::vector<std::string>{"doc.mtlx"}) << joined << " " << name;
        }
      } catch (const std::exception& e) {
        ADD_FAILURE() << joined << " " << name << ": " << e.what();
      }
      checked.insert(joined + " " + name);
    }
  }
  // The cases among them (24 options in all today).
  for (const char* c : {"compile --library", "compile --search-path", "inspect --library", "render -o", "render --set",
                        "eval --param", "bench accuracy --library"}) {
    EXPECT_EQ(checked.count(c), 1u) << c;
  }
  EXPECT_GE(checked.size(), 20u);
}

TEST(CommandLine, HelpShowsTheDefaults) {
  CommandRun r = mxc("render --help");
  ASSERT_EQ(r.exitCode, 0);
  for (const char* shown : {"--size N|WxH=512", "=64", "--env TEXT=sky", "--mesh TEXT=sphere", "=45", "=aces", "=balanced"}) {
    EXPECT_NE(r.out.find(shown), std::string::npos) << shown << " in\n" << r.out;
  }
  EXPECT_EQ(r.out.find("=[]"), std::string::npos) << "an empty list is no default worth showing";
  r = mxc("furnace --help");
  EXPECT_NE(r.out.find("=8"), std::string::npos) << r.out;      // angles
  EXPECT_NE(r.out.find("=65536"), std::string::npos) << r.out;  // samples
}

TEST(CommandLine, QuietAndVerboseOnEveryCommand) {
  const std::string doc = corpus(kDefault);
  for (const char* command : {"inspect", "compile", "eval", "furnace", "render", "bench accuracy", "bench specialize"}) {
    CommandRun help = mxc(std::string(command) + " --help");
    EXPECT_NE(help.out.find("-q,--quiet"), std::string::npos) << command;
    EXPECT_NE(help.out.find("-v,--verbose"), std::string::npos) << command;
  }
  const fs::path spv = fs::temp_directory_path() / ("mxc_cli_quiet_" + std::to_string(::getpid()) + ".spv");
  CommandRun r = mxc("compile -q " + doc + " -o " + spv.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
  r = mxc("compile -v " + doc + " -o " + spv.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("mxc: libraries builtin"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("SPIR-V compiled and validated in"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("compiled 1 material(s)"), std::string::npos) << "the summary stays on stdout";
  r = mxc("compile -q -v " + doc);
  EXPECT_EQ(r.exitCode, 2) << "-q and -v exclude each other";
  fs::remove(spv);
}

TEST(CommandLine, VersionNamesTheLibrariesAndDevices) {
  CommandRun r = mxc("--version");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.rfind("mxc ", 0), 0u) << r.out;
  for (const char* part : {"\nglslang ", "\nSPIRV-Tools v", "\nSPIRV-Cross 20", "\nnaga 30.", "\nOpenImageIO ", "\nVulkan device 0: "}) {
    EXPECT_NE(r.out.find(part), std::string::npos) << part << " in\n" << r.out;
  }
#ifndef __SANITIZE_ADDRESS__
  // mimalloc replaces malloc (cli/CMakeLists.txt), and mxc asks it whether it does.
  EXPECT_NE(r.out.find("\nmimalloc 2."), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(", the memory allocator\n"), std::string::npos) << r.out;
#else
  EXPECT_EQ(r.out.find("mimalloc"), std::string::npos) << "the sanitizers bring their own allocator";
#endif
}

TEST(CommandLine, AnUnknownCommandIsNamed) {
  CommandRun r = mxc("frobnicate x.mtlx");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("error: unknown command 'frobnicate' (commands: inspect, compile, eval, furnace, render, bench)"),
            std::string::npos)
      << r.err;
  r = mxc("bench frobnicate");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("unknown command 'frobnicate' (commands: accuracy, specialize)"), std::string::npos) << r.err;
  r = mxc("");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("no command given"), std::string::npos) << r.err;
}

TEST(CommandLine, AMissingDeviceHasItsOwnExitCode) {
  const fs::path dirs = writeTemp("nodevice_dirs.csv", "0,0,1,0,0,1\n");
  CommandRun r = mxc("eval " + corpus(kDefault) + " --dirs " + dirs.string() + " --device no-such-device");
  EXPECT_EQ(r.exitCode, 5);
  EXPECT_NE(r.err.find("no Vulkan device named like 'no-such-device'"), std::string::npos) << r.err;
  r = mxc("render " + corpus(kDefault) + " -o x.png --device 99");
  EXPECT_EQ(r.exitCode, 5);
  fs::remove(dirs);
}

// The bash completion, generated from the definition, is valid bash and completes commands,
// options and the values an option names (run in bash as the shell would call it).
TEST(CommandLine, BashCompletionCompletesCommandsOptionsAndChoices) {
  CommandRun script = mxc("--generate bash");
  ASSERT_EQ(script.exitCode, 0) << script.err;
  const fs::path file = writeTemp("mxc_completion.bash", script.out);
  auto complete = [&](const std::string& words, int cword) {
    const fs::path runner = writeTemp("mxc_complete_run.sh", "source '" + file.string() + "'\nCOMP_WORDS=(" + words +
                                                               ")\nCOMP_CWORD=" + std::to_string(cword) +
                                                               "\n_mxc\necho \"${COMPREPLY[*]}\"\n");
    FILE* pipe = ::popen(("bash " + runner.string() + " 2>&1").c_str(), "r");
    std::string out;
    char buffer[512];
    while (pipe && std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
    if (pipe) ::pclose(pipe);
    fs::remove(runner);
    return out;
  };
  EXPECT_EQ(complete("mxc fu", 1), "furnace\n");
  EXPECT_EQ(complete("mxc bench a", 2), "accuracy\n");
  EXPECT_EQ(complete("mxc render --tonem", 2), "--tonemap\n");
  EXPECT_EQ(complete("mxc render --tonemap n", 3), "none neutral\n");
  EXPECT_EQ(complete("mxc compile --accuracy b", 3), "balanced\n");
  EXPECT_EQ(complete("mxc render x.mtlx --spp ''", 4), "\n") << "a number: nothing to offer";
  EXPECT_NE(complete("mxc bench specialize --rep", 3).find("--repeat"), std::string::npos);
  fs::remove(file);
}

// The man page is generated from the same definition: every option of every command is in it,
// and groff formats it without a warning.
TEST(CommandLine, ManPageHasEveryOptionAndFormatsCleanly) {
  CommandRun page = mxc("--generate man");
  ASSERT_EQ(page.exitCode, 0) << page.err;
  EXPECT_EQ(page.out.rfind(".TH MXC 1", 0), 0u);
  for (const char* command : {"inspect", "compile", "eval", "furnace", "render", "bench accuracy", "bench specialize"}) {
    EXPECT_NE(page.out.find(std::string(".SS mxc ") + command), std::string::npos) << command;
    CommandRun help = mxc(std::string(command) + " --help");
    // Each long option --help lists, as the page writes it (roff's \- for a hyphen).
    for (size_t at = help.out.find("  --"); at != std::string::npos; at = help.out.find("  --", at + 1)) {
      std::string name = help.out.substr(at + 2, help.out.find_first_of(" ,=\n", at + 2) - at - 2);
      std::string escaped;
      for (char c : name) escaped += c == '-' ? std::string("\\-") : std::string(1, c);
      EXPECT_NE(page.out.find("\\fB" + escaped + "\\fR"), std::string::npos) << command << " " << name;
    }
  }
  if (std::system("command -v groff > /dev/null 2>&1") != 0) GTEST_SKIP() << "groff is not installed";
  const fs::path file = writeTemp("mxc.1", page.out);
  FILE* pipe = ::popen(("groff -man -ww -z " + file.string() + " 2>&1").c_str(), "r");
  std::string warnings;
  char buffer[512];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe)) warnings += buffer;
  const int status = pipe ? ::pclose(pipe) : -1;
  EXPECT_EQ(status, 0);
  EXPECT_TRUE(warnings.empty()) << warnings;
  fs::remove(file);
}

}  // namespace
}  // namespace mxc::test
