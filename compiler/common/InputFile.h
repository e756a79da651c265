#pragma once
/// \file
/// Reading the files a command takes as input (documents, includes, libraries, images, meshes,
/// direction tables). Every input must be a regular file: a FIFO blocks a reader forever,
/// `/dev/zero` never ends, and a directory is no document. Each is refused with a message that
/// says what the path is, before a byte is read.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>

namespace mxc {

/// Why `path` cannot be an input file ("it does not exist", "it is a directory", "it is a FIFO",
/// "it is a character device", ...), or nullopt when it is a regular file (symbolic links
/// followed). Used where a library (OpenImageIO) opens the file itself.
std::optional<std::string> inputFileProblem(const std::filesystem::path& path);

/// Reads a whole regular file as bytes, or returns why it cannot ("it is a FIFO", "it is N
/// bytes, above the limit of M bytes", the system's reason). The file is opened without
/// blocking and checked on the open descriptor, so a path swapped for a FIFO after a check
/// cannot block the read either.
std::variant<std::string, std::string> readInputFile(const std::filesystem::path& path, size_t maxBytes);

}  // namespace mxc
