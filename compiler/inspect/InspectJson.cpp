#include <fmt/format.h>

#include "compiler/inspect/Inspect.h"

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

}  // namespace

json inspectJson(const InspectInput& input) {
  const resolve::ResolvedDocument& rd = input.document;
  const doc::Document& d = *rd.document;
  json out;
  out["schema"] = "mxc-inspect-1";

  json includes = json::array();
  for (const doc::Include& include : d.includes) includes.push_back(include.href);
  out["document"] = {{"path", d.path()},
                     {"version", d.version},
                     {"colorspace", d.colorspace},
                     {"includes", includes},
                     {"upgrades", d.upgradeNotes}};

  json libraries = json::array();
  for (const LibraryInfo& l : input.libraries) libraries.push_back({{"name", l.name}, {"nodedefs", l.nodedefs}});
  out["libraries"] = libraries;

  json materials = json::array();
  for (const resolve::ResolvedMaterial& m : rd.materials) {
    json shaders = json::array();
    for (const auto& s : m.shaders) shaders.push_back({{"input", s.input}, {"node", nodeId(*s.node)}});
    materials.push_back({{"name", m.node->name()},
                         {"node", nodeId(*m.node)},
                         {"category", m.node->category()},
                         {"location", locationJson(m.node->node->location)},
                         {"shaders", shaders}});
  }
  out["materials"] = materials;

  json nodes = json::array();
  for (const auto& n : rd.top.nodes) nodes.push_back(nodeJson(*n));
  json graphs = json::array();
  for (const auto& g : rd.graphs) {
    json interface = json::array();
    for (const ResolvedInput& in : g->interface) interface.push_back(inputJson(in));
    json outputs = json::array();
    for (const ResolvedInput& in : g->outputs) outputs.push_back(inputJson(in));
    json members = json::array();
    for (const auto& n : g->nodes) {
      nodes.push_back(nodeJson(*n));
      members.push_back(nodeId(*n));
    }
    graphs.push_back({{"name", g->name()},
                      {"nodedef", g->implements ? json(g->implements->name) : json(nullptr)},
                      {"location", locationJson(g->graph->location)},
                      {"interface", interface},
                      {"outputs", outputs},
                      {"nodes", members}});
  }
  out["nodes"] = nodes;
  out["graphs"] = graphs;

  json nodedefs = json::array();
  for (const doc::Document* doc : rd.documents) {
    for (const doc::NodeDef& nd : doc->nodedefs) nodedefs.push_back(nd.name);
  }
  out["nodedefs"] = nodedefs;

  json looks = json::array();
  for (const doc::Document* doc : rd.documents) {
    for (const doc::Look& look : doc->looks) {
      json assigns = json::array();
      for (const doc::MaterialAssign& a : look.assigns) {
        assigns.push_back({{"name", a.name}, {"material", a.material}, {"geom", a.geom}, {"collection", a.collection}});
      }
      looks.push_back({{"name", look.name}, {"location", locationJson(look.location)}, {"assigns", assigns}});
    }
  }
  out["looks"] = looks;

  json diagnostics = json::array();
  for (const Diagnostic& diag : input.diagnostics.all()) {
    std::string_view severity = diag.severity == Severity::Error ? "error" : diag.severity == Severity::Warning ? "warning" : "note";
    diagnostics.push_back({{"severity", severity}, {"message", diag.message}, {"location", locationJson(diag.location)}});
  }
  out["diagnostics"] = diagnostics;
  // Beyond Diagnostics::kMaxKept messages only counts are kept.
  out["diagnostics_omitted"] = {{"errors", input.diagnostics.omittedErrors()},
                                {"warnings", input.diagnostics.omittedWarnings()}};
  return out;
}

}  // namespace mxc::inspect
