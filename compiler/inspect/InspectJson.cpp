#include <fmt/format.h>

#include "compiler/inspect/Inspect.h"

#include "compiler/common/JsonText.h"

namespace mxc::inspect {

using nlohmann::json;
using resolve::InputSource;
using resolve::ResolvedGraph;
using resolve::ResolvedInput;
using resolve::ResolvedNode;

namespace {

json locationJson(SourceLocation location) {
  if (!location.valid()) return nullptr;
  LineColumn lc = location.lineColumn();
  return json{{"file", location.file->path()}, {"line", lc.line}, {"column", lc.column}};
}

/// Values as JSON: booleans, numbers, strings, and flat arrays of numbers for vectors,
/// colours and matrices (row-major), arrays for array types.
json valueJson(const doc::Value& value) {
  return std::visit(
      [&](const auto& d) -> json {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, std::monostate>) {
          return nullptr;
        } else if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, int32_t> || std::is_same_v<T, float> ||
                             std::is_same_v<T, std::string> || std::is_same_v<T, std::vector<int32_t>> ||
                             std::is_same_v<T, std::vector<float>> || std::is_same_v<T, std::vector<std::string>>) {
          return d;
        } else if constexpr (std::is_same_v<T, std::vector<glm::vec2>> || std::is_same_v<T, std::vector<glm::vec3>> ||
                             std::is_same_v<T, std::vector<glm::vec4>>) {
          json out = json::array();
          for (const auto& v : d) {
            json item = json::array();
            for (int k = 0; k < v.length(); ++k) item.push_back(v[k]);
            out.push_back(item);
          }
          return out;
        } else {
          return value.components();
        }
      },
      value.data());
}

json inputJson(const ResolvedInput& in) {
  json j{{"name", in.name}, {"type", in.type}, {"source", resolve::inputSourceName(in.source)}};
  if (in.value) j["value"] = valueJson(*in.value);
  if (!in.structValue.empty()) j["value"] = in.structLiteral();
  if (in.source == InputSource::GeomProp) j["geomprop"] = in.geomprop;
  if (in.source == InputSource::Interface) j["interface"] = in.interfaceName;
  if (in.source == InputSource::Connection) {
    json from{{"output", in.upstream.output}};
    if (in.upstream.node) from["node"] = nodeId(*in.upstream.node);
    if (in.upstream.graph) from["graph"] = in.upstream.graph->name();
    j["from"] = from;
  }
  if (!in.channels.empty()) j["channels"] = in.channels;
  j["location"] = locationJson(in.location);
  return j;
}

json nodeJson(const ResolvedNode& n) {
  json j{{"id", nodeId(n)},
         {"name", n.name()},
         {"category", n.category()},
         {"type", n.node->type},
         {"nodedef", n.nodedef ? json(n.nodedef->name) : json(nullptr)},
         {"graph", n.scope && n.scope->graph ? json(n.scope->graph->name) : json(nullptr)},
         {"location", locationJson(n.node->location)}};
  if (n.nodedef && !n.nodedef->version.empty()) j["version"] = n.nodedef->version;
  json inputs = json::array();
  for (const ResolvedInput& in : n.inputs) inputs.push_back(inputJson(in));
  j["inputs"] = inputs;
  return j;
}

/// The report's text as nlohmann's dump(2) writes the whole object, written one member (and
/// one element of the long arrays) at a time: no tree of the whole document is ever built, so
/// a document of 100,000 nodes needs the text and one node's JSON. Destroying a large tree
/// allocates (nlohmann::json flattens it through a vector), and running out of memory there
/// would end the process (std::terminate) instead of exit 4.
class ReportWriter {
 public:
  /// Members must come in the order of their names (dump's std::map order).
  void member(std::string_view key, const json& value) {
    open(key);
    text_ += indented(jsonText(value, 2, &lossy_), 2);
  }
  void beginArray(std::string_view key) {
    open(key);
    text_ += '[';
    elements_ = 0;
  }
  void element(const json& value) {
    text_ += elements_++ ? ",\n    " : "\n    ";
    text_ += indented(jsonText(value, 2, &lossy_), 4);
  }
  void endArray() { text_ += elements_ ? "\n  ]" : "]"; }
  std::string finish() { return std::move(text_) + "\n}"; }
  bool lossy() const { return lossy_; }

 private:
  void open(std::string_view key) {
    text_ += members_++ ? ",\n  " : "{\n  ";
    text_ += jsonText(json(std::string(key)), -1, &lossy_);
    text_ += ": ";
  }
  static std::string indented(const std::string& dumped, size_t spaces) {
    std::string out;
    out.reserve(dumped.size());
    for (char c : dumped) {
      out += c;
      if (c == '\n') out.append(spaces, ' ');
    }
    return out;
  }
  std::string text_;
  size_t members_ = 0, elements_ = 0;
  bool lossy_ = false;
};

}  // namespace

std::string inspectJson(const InspectInput& input, bool* lossy) {
  const resolve::ResolvedDocument& rd = input.document;
  const doc::Document& d = *rd.document;
  ReportWriter out;

  json diagnostics = json::array();
  for (const Diagnostic& diag : input.diagnostics.all()) {
    std::string_view severity = diag.severity == Severity::Error ? "error" : diag.severity == Severity::Warning ? "warning" : "note";
    diagnostics.push_back({{"severity", severity}, {"message", diag.message}, {"location", locationJson(diag.location)}});
  }
  out.member("diagnostics", diagnostics);
  // Beyond Diagnostics::kMaxKept messages only counts are kept.
  out.member("diagnostics_omitted", {{"errors", input.diagnostics.omittedErrors()},
                                     {"warnings", input.diagnostics.omittedWarnings()}});

  json includes = json::array();
  for (const doc::Include& include : d.includes) includes.push_back(include.href);
  out.member("document", {{"path", d.path()},
                          {"version", d.version},
                          {"colorspace", d.colorspace},
                          {"includes", includes},
                          {"upgrades", d.upgradeNotes}});

  out.beginArray("graphs");
  for (const auto& g : rd.graphs) {
    json interface = json::array();
    for (const ResolvedInput& in : g->interface) interface.push_back(inputJson(in));
    json outputs = json::array();
    for (const ResolvedInput& in : g->outputs) outputs.push_back(inputJson(in));
    json members = json::array();
    for (const auto& n : g->nodes) members.push_back(nodeId(*n));
    out.element({{"name", g->name()},
                 {"nodedef", g->implements ? json(g->implements->name) : json(nullptr)},
                 {"location", locationJson(g->graph->location)},
                 {"interface", interface},
                 {"outputs", outputs},
                 {"nodes", members}});
  }
  out.endArray();

  json libraries = json::array();
  for (const LibraryInfo& l : input.libraries) libraries.push_back({{"name", l.name}, {"nodedefs", l.nodedefs}});
  out.member("libraries", libraries);

  out.beginArray("looks");
  for (const doc::Document* doc : rd.documents) {
    for (const doc::Look& look : doc->looks) {
      json assigns = json::array();
      for (const doc::MaterialAssign& a : look.assigns) {
        assigns.push_back({{"name", a.name}, {"material", a.material}, {"geom", a.geom}, {"collection", a.collection}});
      }
      out.element({{"name", look.name}, {"location", locationJson(look.location)}, {"assigns", assigns}});
    }
  }
  out.endArray();

  out.beginArray("materials");
  for (const resolve::ResolvedMaterial& m : rd.materials) {
    json shaders = json::array();
    for (const auto& s : m.shaders) shaders.push_back({{"input", s.input}, {"node", nodeId(*s.node)}});
    out.element({{"name", m.node->name()},
                 {"node", nodeId(*m.node)},
                 {"category", m.node->category()},
                 {"location", locationJson(m.node->node->location)},
                 {"shaders", shaders}});
  }
  out.endArray();

  out.beginArray("nodedefs");
  for (const doc::Document* doc : rd.documents) {
    for (const doc::NodeDef& nd : doc->nodedefs) out.element(nd.name);
  }
  out.endArray();

  // The document's nodes, then each graph's, as the graphs list them.
  out.beginArray("nodes");
  for (const auto& n : rd.top.nodes) out.element(nodeJson(*n));
  for (const auto& g : rd.graphs) {
    for (const auto& n : g->nodes) out.element(nodeJson(*n));
  }
  out.endArray();

  out.member("schema", "mxc-inspect-1");
  if (lossy && out.lossy()) *lossy = true;
  return out.finish();
}

}  // namespace mxc::inspect
