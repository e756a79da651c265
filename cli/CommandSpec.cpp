// Shell completions and the man page, written from the command line's definition
// (describeCommandLine in cli/CommandLine.cpp). `mxc --generate bash|zsh|man` prints them; the
// build runs it and `cmake --install` installs the files.

#include "cli/CommandSpec.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace mxc::cli {

namespace {

/// The commands to complete: every command that has no commands of its own, with its path
/// ("compile", "bench accuracy").
void leaves(const CommandSpec& command, const std::string& path, std::vector<std::pair<std::string, const CommandSpec*>>& out) {
  for (const CommandSpec& sub : command.commands) {
    const std::string name = path.empty() ? sub.name : path + " " + sub.name;
    if (sub.commands.empty()) out.emplace_back(name, &sub);
    else leaves(sub, name, out);
  }
}

std::vector<std::string> commandNames(const CommandSpec& command) {
  std::vector<std::string> names;
  for (const CommandSpec& sub : command.commands) names.push_back(sub.name);
  return names;
}

/// The first clause of a description, for a completion menu: up to the first ". ", ": " or
/// "; ", at most about 70 characters, cut at a space.
std::string brief(const std::string& description) {
  std::string out = description;
  for (const char* stop : {". ", ": ", "; ", " ("}) {
    if (const size_t at = out.find(stop); at != std::string::npos) out.resize(at);
  }
  if (out.size() > 70) {
    const size_t space = out.rfind(' ', 70);
    out.resize(space == std::string::npos ? 70 : space);
  }
  return out;
}

/// Whether an option's value is a file or folder name (TEXT is CLI11's name for a string,
/// which mxc's string options that are not paths rename: NAME, SPEC, X,Y,Z, ...).
bool namesFiles(const OptionSpec& o) {
  return o.choices.empty() && !o.number &&
         (o.value == "TEXT" || o.value.find("FILE") != std::string::npos || o.value.find("DIR") != std::string::npos);
}

// --- bash ---

/// The words of a bash `case` pattern for the options that take a value of the given sort.
std::string casePattern(const std::vector<std::string>& names) { return fmt::format("{}", fmt::join(names, "|")); }

std::string bashCommandCase(const CommandSpec& command) {
  std::string out;
  std::vector<std::string> words;
  std::vector<std::string> numbers;  // and every other value with nothing to complete
  std::vector<std::string> files;
  std::string choiceCases;
  for (const OptionSpec& o : command.options) {
    if (!o.positional.empty()) continue;
    words.insert(words.end(), o.names.begin(), o.names.end());
    if (o.value.empty()) continue;
    if (!o.choices.empty()) {
      choiceCases += fmt::format("        {}) COMPREPLY=($(compgen -W \"{}\" -- \"$cur\")); return ;;\n",
                                 casePattern(o.names), fmt::join(o.choices, " "));
    } else if (namesFiles(o)) {
      files.insert(files.end(), o.names.begin(), o.names.end());
    } else {
      numbers.insert(numbers.end(), o.names.begin(), o.names.end());  // numbers, names, coordinates: nothing to offer
    }
  }
  out += "      case \"$prev\" in\n" + choiceCases;
  if (!numbers.empty()) out += fmt::format("        {}) COMPREPLY=(); return ;;\n", casePattern(numbers));
  if (!files.empty()) out += fmt::format("        {}) COMPREPLY=($(compgen -f -- \"$cur\")); return ;;\n", casePattern(files));
  out += "      esac\n";
  out += fmt::format("      if [[ \"$cur\" == -* ]]; then COMPREPLY=($(compgen -W \"{}\" -- \"$cur\"));\n", fmt::join(words, " "));
  out += "      else COMPREPLY=($(compgen -f -- \"$cur\")); fi\n";
  return out;
}

// --- zsh ---

/// Text inside a single-quoted zsh _arguments spec: no quote, no brackets, colons escaped.
std::string zshText(std::string text) {
  std::string out;
  for (char c : text) {
    if (c == '\'') out += "'\\''";
    else if (c == '[') out += '(';
    else if (c == ']') out += ')';
    else if (c == ':') out += "\\:";
    else out += c;
  }
  return out;
}

std::string zshArguments(const CommandSpec& command, const std::string& indent) {
  std::vector<std::string> specs;
  for (const OptionSpec& o : command.options) {
    const std::string action = !o.choices.empty() ? fmt::format("({})", fmt::join(o.choices, " "))
                               : namesFiles(o) || !o.positional.empty() ? "_files"
                                                                        : " ";
    if (!o.positional.empty()) {
      specs.push_back(fmt::format("'{}:{}:{}'", o.repeatable ? "*" : "1", zshText(o.positional), action));
      continue;
    }
    const std::string value = o.value.empty() ? "" : fmt::format(":{}:{}", zshText(o.value), action);
    const std::string help = fmt::format("[{}]", zshText(brief(o.description)));
    if (o.names.size() == 1) {
      specs.push_back(fmt::format("'{}{}{}{}'", o.repeatable ? "*" : "", o.names[0], help, value));
    } else {
      const std::string exclusive = o.repeatable ? "*" : fmt::format("({})", fmt::join(o.names, " "));
      specs.push_back(fmt::format("'{}'{{{}}}'{}{}'", exclusive, fmt::join(o.names, ","), help, value));
    }
  }
  return indent + "_arguments -s \\\n" + indent + "  " + fmt::format("{}", fmt::join(specs, " \\\n" + indent + "  ")) + "\n";
}

std::string zshDescribe(const CommandSpec& command, const std::string& indent) {
  std::string out = indent + "local -a commands=(\n";
  for (const CommandSpec& sub : command.commands) {
    out += fmt::format("{}  '{}:{}'\n", indent, sub.name, zshText(brief(sub.description)));
  }
  return out + indent + ")\n" + indent + "_describe 'command' commands\n";
}

// --- man ---

/// Text for roff: backslashes and a leading period or quote made literal.
std::string roff(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\\') out += "\\e";
    else if (c == '-') out += "\\-";
    else out += c;
  }
  std::string lines;
  size_t start = 0;
  while (start <= out.size()) {
    size_t end = out.find('\n', start);
    if (end == std::string::npos) end = out.size();
    std::string line = out.substr(start, end - start);
    if (!line.empty() && (line[0] == '.' || line[0] == '\'')) line = "\\&" + line;
    lines += line;
    if (end < out.size()) lines += '\n';
    start = end + 1;
  }
  return lines;
}

std::string manOptions(const CommandSpec& command) {
  std::string out;
  for (const OptionSpec& o : command.options) {
    if (!o.positional.empty()) continue;
    std::vector<std::string> names;
    for (const std::string& n : o.names) names.push_back("\\fB" + roff(n) + "\\fR");
    out += ".TP\n" + fmt::format("{}", fmt::join(names, ", "));
    if (!o.value.empty()) out += " \\fI" + roff(o.value) + "\\fR";
    std::vector<std::string> notes;
    if (!o.choices.empty()) notes.push_back(fmt::format("one of {}", fmt::join(o.choices, ", ")));
    if (!o.defaultValue.empty()) notes.push_back("default " + o.defaultValue);
    if (o.repeatable && o.description.find("repeatable") == std::string::npos) notes.push_back("repeatable");
    out += "\n" + roff(o.description);
    if (!notes.empty()) out += roff(fmt::format(" ({})", fmt::join(notes, "; ")));
    out += "\n";
  }
  return out;
}

}  // namespace

std::string bashCompletion(const CommandSpec& mxc) {
  std::vector<std::pair<std::string, const CommandSpec*>> commands;
  leaves(mxc, "", commands);
  std::string out = fmt::format(
      "# bash completion for {0}, generated by `{0} --generate bash` from its command-line definition.\n"
      "_{0}() {{\n"
      "  local cur=\"${{COMP_WORDS[COMP_CWORD]}}\" prev=\"${{COMP_WORDS[COMP_CWORD-1]}}\" command=\"\" word i\n"
      "  # The command named so far: the words that name commands, in order.\n"
      "  for ((i = 1; i < COMP_CWORD; i++)); do\n"
      "    word=\"${{COMP_WORDS[i]}}\"\n"
      "    case \"$command:$word\" in\n",
      mxc.name);
  for (const CommandSpec& sub : mxc.commands) {
    out += fmt::format("      \":{0}\") command=\"{0}\" ;;\n", sub.name);
    for (const CommandSpec& leaf : sub.commands) out += fmt::format("      \"{0}:{1}\") command=\"{0} {1}\" ;;\n", sub.name, leaf.name);
  }
  out += "    esac\n  done\n  case \"$command\" in\n";
  out += fmt::format("    \"\") COMPREPLY=($(compgen -W \"{} --help --version\" -- \"$cur\")) ;;\n",
                     fmt::join(commandNames(mxc), " "));
  for (const CommandSpec& sub : mxc.commands) {
    if (!sub.commands.empty()) {
      out += fmt::format("    \"{}\") COMPREPLY=($(compgen -W \"{} --help\" -- \"$cur\")) ;;\n", sub.name,
                         fmt::join(commandNames(sub), " "));
    }
  }
  for (const auto& [path, command] : commands) {
    out += fmt::format("    \"{}\")\n", path) + bashCommandCase(*command) + "      ;;\n";
  }
  out += "  esac\n}\n";
  out += fmt::format("complete -o filenames -F _{0} {0}\n", mxc.name);
  return out;
}

std::string zshCompletion(const CommandSpec& mxc) {
  std::string out = fmt::format(
      "#compdef {0}\n"
      "# zsh completion for {0}, generated by `{0} --generate zsh` from its command-line definition.\n"
      "_{0}() {{\n"
      "  if (( CURRENT == 2 )); then\n",
      mxc.name);
  out += zshDescribe(mxc, "    ");
  out += "    return\n  fi\n  case ${words[2]} in\n";
  for (const CommandSpec& sub : mxc.commands) {
    out += fmt::format("    {})\n", sub.name);
    if (sub.commands.empty()) {
      out += "      shift words; (( CURRENT-- ))\n" + zshArguments(sub, "      ");
    } else {
      out += "      if (( CURRENT == 3 )); then\n" + zshDescribe(sub, "        ") + "        return\n      fi\n";
      out += "      case ${words[3]} in\n";
      for (const CommandSpec& leaf : sub.commands) {
        out += fmt::format("        {})\n", leaf.name) + "          shift 2 words; (( CURRENT -= 2 ))\n" +
               zshArguments(leaf, "          ") + "          ;;\n";
      }
      out += "      esac\n";
    }
    out += "      ;;\n";
  }
  out += "  esac\n}\n";
  out += fmt::format("_{0} \"$@\"\n", mxc.name);
  return out;
}

std::string manPage(const CommandSpec& mxc, const std::string& version) {
  std::string out = fmt::format(".TH MXC 1 \"\" \"mxc {}\" \"User Commands\"\n", version);
  out += ".\\\" Generated by `mxc --generate man` from the command-line definition: do not edit.\n";
  // NAME is "mxc \- what it does" (man-pages(7)); the description starts "mxc: what it does".
  std::string what = mxc.description;
  if (what.rfind(mxc.name + ": ", 0) == 0) what = what.substr(mxc.name.size() + 2);
  out += ".SH NAME\n" + mxc.name + " \\- " + roff(what) + "\n";
  out += ".SH SYNOPSIS\n";
  std::vector<std::pair<std::string, const CommandSpec*>> commands;
  leaves(mxc, "", commands);
  for (const auto& [path, command] : commands) {
    std::string positionals;
    for (const OptionSpec& o : command->options) {
      if (!o.positional.empty()) positionals += fmt::format(" {}\\fI{}\\fR{}", o.required ? "" : "[", roff(o.positional),
                                                            o.repeatable ? "...]" : (o.required ? "" : "]"));
    }
    out += fmt::format(".B mxc {}\n[\\fIoptions\\fR]{}\n.br\n", roff(path), positionals);
  }
  out += ".B mxc\n\\-\\-help | \\-\\-version\n";
  out += ".SH DESCRIPTION\n"
         "mxc reads MaterialX documents (OpenPBR Surface, Autodesk Standard Surface, pbrlib graphs and more), lowers\n"
         "each material's node graph to an IR of layered slabs and their media, and emits GLSL and SPIR-V; it\n"
         "renders, evaluates and measures materials on a Vulkan device (Mesa lavapipe by default).\n"
         "Errors name the file, line and column; outputs are written whole or not at all.\n";
  out += ".SH COMMANDS\n";
  for (const auto& [path, command] : commands) {
    out += fmt::format(".SS mxc {}\n{}\n", roff(path), roff(command->description));
    out += manOptions(*command);
  }
  out += ".SH OPTIONS\n" + manOptions(mxc);
  out += ".SH EXIT STATUS\n" + roff(mxc.footer) + "\n";
  out += ".SH SEE ALSO\nThe README of mxc: commands, the formats of its reports (docs/), measured figures.\n";
  return out;
}

}  // namespace mxc::cli
