#pragma once
// Whole-file reads and writes with errors that name the file.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace engine {

// Throws engine::Error naming `path` when it is missing, unreadable or larger than `maxBytes`.
std::vector<std::uint8_t> readBinaryFile(const std::filesystem::path& path,
                                         std::size_t maxBytes = std::size_t{1} << 31);
std::string readTextFile(const std::filesystem::path& path,
                         std::size_t maxBytes = std::size_t{64} << 20);
// Creates parent folders as needed.
void writeTextFile(const std::filesystem::path& path, const std::string& text);

}  // namespace engine
