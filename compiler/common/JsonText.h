#pragma once
/// \file
/// JSON as text, for every report and interface file mxc writes. JSON text is UTF-8 (RFC 8259,
/// s. 8.1), and a path on Linux is any bytes: nlohmann::json::dump throws on a byte that is not
/// UTF-8 (type_error 316), which reached users as the library's message.

#include <string>

#include <nlohmann/json.hpp>

namespace mxc {

/// `value` dumped with `indent` (-1: compact). A string holding bytes that are not UTF-8 is
/// written with U+FFFD in their place, and `lossy` (when given) is set to true, so that the
/// caller can say which file lost them; it is left alone otherwise.
std::string jsonText(const nlohmann::json& value, int indent, bool* lossy = nullptr);

/// The warning a caller prints for a lossy jsonText: "<what> holds text that is not UTF-8 ...".
std::string notUtf8Warning(const std::string& what);

}  // namespace mxc
