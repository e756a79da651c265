#include "compiler/resolve/NodeDefMatcher.h"

#include <algorithm>

#include <fmt/format.h>

namespace mxc::resolve {

namespace {

/// Levenshtein distance, for "did you mean" suggestions (names are short).
size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + items[i];
  return out;
}

/// What keeps a nodedef from matching a node, in words; empty when it matches.
std::vector<std::string> mismatches(const doc::Node& node, const lib::Signature& sig) {
  std::vector<std::string> problems;
  for (const doc::Input& in : node.inputs) {
    const doc::Input* declared = sig.findInput(in.name);
    if (!declared) {
      std::vector<std::string> names;
      for (const doc::Input* d : sig.inputs) names.emplace_back(d->name);
      problems.push_back(fmt::format("it has no input '{}' (its inputs: {})", in.name, join(names)));
    } else if (declared->type != in.type) {
      problems.push_back(fmt::format("its input '{}' has type {}, not {}", in.name, declared->type, in.type));
    }
  }
  return problems;
}

std::string describe(const doc::NodeDef& nd, const lib::Signature& sig) {
  std::vector<std::string> ports;
  for (const doc::Input* in : sig.inputs) ports.push_back(fmt::format("{}:{}", in->name, in->type));
  return fmt::format("{} ({}) -> {}", nd.name, join(ports), sig.outputType());
}

bool outputTypeMatches(const doc::Node& node, const lib::Signature& sig) {
  if (node.type == "multioutput") return sig.outputs.size() > 1;
  return sig.outputs.size() == 1 && sig.outputs[0]->type == node.type;
}

}  // namespace

const doc::NodeDef* matchNodeDef(const doc::Node& node, const lib::NodeLibrary& library, Diagnostics& diagnostics) {
  // An explicit nodedef attribute names the definition; it must fit the node.
  if (!node.nodedef.empty()) {
    const doc::NodeDef* nd = library.findNodeDef(node.nodedef);
    if (!nd) {
      diagnostics.error(node.attributeLocation("nodedef"),
                        fmt::format("node '{}' names nodedef '{}', which is not defined", node.name, node.nodedef));
      return nullptr;
    }
    if (nd->node != node.category) {
      // MaterialX follows the nodedef attribute whatever the element name; so do we, loudly
      // (MaterialX's own stdlib_ng.mtlx has an <ifgreater> naming ND_ifgreatereq_color4I).
      diagnostics.warning(node.attributeLocation("nodedef"),
                          fmt::format("node '{}' is a <{}> but names nodedef '{}', which defines <{}>; the nodedef "
                                      "attribute wins",
                                      node.name, node.category, nd->name, nd->node));
    }
    const lib::Signature& sig = library.signature(*nd);
    if (!outputTypeMatches(node, sig)) {
      diagnostics.error(node.attributeLocation("type"),
                        fmt::format("node '{}' has type {}, but nodedef '{}' outputs {}", node.name, node.type,
                                    nd->name, sig.outputType()));
    }
    for (const std::string& problem : mismatches(node, sig)) {
      diagnostics.error(node.location, fmt::format("node '{}' does not fit nodedef '{}': {}", node.name, nd->name, problem));
    }
    return nd;
  }

  std::vector<const doc::NodeDef*> candidates = library.nodeDefsFor(node.category);
  if (candidates.empty()) {
    std::string suggestion;
    size_t best = 3;  // suggest only close names
    for (std::string_view category : library.categories()) {
      // The category in a namespace, written without it: say which namespace.
      const size_t colon = category.rfind(':');
      if (colon != std::string_view::npos && category.substr(colon + 1) == node.category) {
        suggestion = fmt::format(" (<{}> is defined in namespace '{}': write <{}>)", node.category,
                                 category.substr(0, colon), category);
        break;
      }
      size_t d = editDistance(category, node.category);
      if (d < best) best = d, suggestion = fmt::format(" (did you mean <{}>?)", category);
    }
    // A nodedef without `node` whose `nodename` names this category (MaterialX's test suite
    // writes one: stdlib/definition/definition_reduced_interface.mtlx) defines no category.
    for (const doc::NodeDef* nd : library.nodeDefsWithoutCategory()) {
      if (nd->element.valid() && nd->element.attributeOr("nodename", "") == node.category) {
        suggestion = fmt::format(" (nodedef '{}' at {} writes nodename=\"{}\"; the attribute is node=\"{}\")", nd->name,
                                 nd->location.str(), node.category, node.category);
        break;
      }
    }
    // MaterialX reads and validates a node of a category nothing defines; so does mxc, with a
    // warning. Compiling a material that needs it is an error (lower::Context).
    diagnostics.warning(node.location, fmt::format("unknown node category <{}>: no nodedef defines it{}", node.category,
                                                   suggestion));
    return nullptr;
  }

  std::vector<const doc::NodeDef*> typed;
  for (const doc::NodeDef* nd : candidates) {
    if (outputTypeMatches(node, library.signature(*nd))) typed.push_back(nd);
  }
  if (typed.empty()) {
    std::vector<std::string> types;
    for (const doc::NodeDef* nd : candidates) {
      std::string t(library.signature(*nd).outputType());
      if (std::find(types.begin(), types.end(), t) == types.end()) types.push_back(t);
    }
    diagnostics.error(node.attributeLocation("type"),
                      fmt::format("<{}> has no definition with output type {} (node '{}'); its output types are: {}",
                                  node.category, node.type, node.name, join(types)));
    return nullptr;
  }

  std::vector<const doc::NodeDef*> fitting;
  for (const doc::NodeDef* nd : typed) {
    if (mismatches(node, library.signature(*nd)).empty()) fitting.push_back(nd);
  }
  if (fitting.empty()) {
    // Report against the closest definition: the one with the fewest problems.
    const doc::NodeDef* closest = typed[0];
    size_t fewest = SIZE_MAX;
    for (const doc::NodeDef* nd : typed) {
      size_t n = mismatches(node, library.signature(*nd)).size();
      if (n < fewest) fewest = n, closest = nd;
    }
    std::vector<std::string> problems = mismatches(node, library.signature(*closest));
    // Point at the first offending input when there is one.
    SourceLocation where = node.location;
    for (const doc::Input& in : node.inputs) {
      const doc::Input* declared = library.signature(*closest).findInput(in.name);
      if (!declared || declared->type != in.type) {
        where = in.location;
        break;
      }
    }
    std::string message = fmt::format("no nodedef of <{}> with output type {} fits node '{}': the closest, {}, does "
                                      "not fit because {}",
                                      node.category, node.type, node.name, closest->name, join(problems));
    if (typed.size() > 1) {
      std::vector<std::string> sigs;
      for (const doc::NodeDef* nd : typed) sigs.push_back(describe(*nd, library.signature(*nd)));
      message += fmt::format("; candidates: {}", join(sigs));
    }
    diagnostics.error(where, message);
    return nullptr;
  }

  // Versions: a requested version must exist; otherwise the default version wins.
  if (!node.version.empty()) {
    std::vector<const doc::NodeDef*> versioned;
    for (const doc::NodeDef* nd : fitting) {
      if (nd->version == node.version) versioned.push_back(nd);
    }
    if (versioned.empty()) {
      std::vector<std::string> versions;
      for (const doc::NodeDef* nd : fitting) versions.emplace_back(nd->version.empty() ? "(unversioned)" : nd->version);
      diagnostics.error(node.attributeLocation("version"),
                        fmt::format("<{}> has no version {} (available: {})", node.category, node.version, join(versions)));
      return nullptr;
    }
    fitting = versioned;
  } else if (fitting.size() > 1) {
    std::vector<const doc::NodeDef*> defaults;
    for (const doc::NodeDef* nd : fitting) {
      if (nd->isDefaultVersion) defaults.push_back(nd);
    }
    if (!defaults.empty()) fitting = defaults;
  }
  // Several definitions can still fit when they differ only in inputs the node leaves unset
  // (<clamp type="color3"> with only `in` fits ND_clamp_color3 and ND_clamp_color3FA). As in
  // MaterialX, the first one declared wins: libraries list the plain variant first.
  return fitting[0];
}

}  // namespace mxc::resolve
