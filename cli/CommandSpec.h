#pragma once
/// \file
/// The command line as data: every command with its options, taken from the CLI11 definition
/// (cli/CommandLine.cpp, describeCommandLine), so that the shell completions and the man page
/// are generated from the same definition as --help and can never disagree with it.

#include <map>
#include <string>
#include <vector>

namespace mxc::cli {

struct OptionSpec {
  std::vector<std::string> names;    ///< "-o", "--output"; empty for a positional
  std::string positional;            ///< the positional's name ("file"), else empty
  std::string value;                 ///< the value's name as --help shows it ("TEXT", "INPUT=VALUE"); empty for a flag
  std::vector<std::string> choices;  ///< the values it accepts, when it names them ("none", "aces", "neutral")
  bool number = false;               ///< the value is a number (nothing to complete)
  bool repeatable = false;
  bool required = false;
  std::string defaultValue;          ///< as --help shows it, empty when none
  std::string description;
};

struct CommandSpec {
  std::string name;         ///< "mxc", "compile", "accuracy"
  std::string description;
  std::vector<OptionSpec> options;  ///< in --help order; help itself included
  std::vector<CommandSpec> commands;
  std::string footer;       ///< the exit codes (the top level only)
};

/// The whole command line (cli/CommandLine.cpp).
CommandSpec describeCommandLine();

/// A command line as mxc's parser assigns its words, without running the command: the command
/// ("compile", "bench accuracy") and the values each option and positional took, in order, by
/// the name OptionSpec gives it first ("--library", "file"). For tests of the grammar; a usage
/// error throws std::invalid_argument with the parser's message.
struct ParsedCommandLine {
  std::string command;
  std::map<std::string, std::vector<std::string>> values;
};
ParsedCommandLine parseCommandLineWords(const std::vector<std::string>& words);

/// A bash completion script (`complete -F _mxc mxc`): commands, options, the choices of an
/// option that names them, file names for every other value but numbers.
std::string bashCompletion(const CommandSpec& mxc);
/// A zsh completion function (`#compdef mxc`), the same content as the bash one with the
/// options' descriptions.
std::string zshCompletion(const CommandSpec& mxc);
/// mxc(1), in roff's man macros: synopsis, each command with its options and defaults, the exit
/// status. `version` goes into the title line.
std::string manPage(const CommandSpec& mxc, const std::string& version);

}  // namespace mxc::cli
