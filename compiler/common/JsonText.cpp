#include "compiler/common/JsonText.h"

namespace mxc {

std::string jsonText(const nlohmann::json& value, int indent, bool* lossy) {
  try {
    return value.dump(indent);
  } catch (const nlohmann::json::type_error& e) {
    if (e.id != 316) throw;  // 316: invalid UTF-8, the one error dump can raise on a value
  }
  if (lossy) *lossy = true;
  return value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string notUtf8Warning(const std::string& what) {
  return what + " holds a name (a path, a node name) with bytes that are not UTF-8; JSON holds only UTF-8, so each such "
                "byte is written as U+FFFD";
}

}  // namespace mxc
