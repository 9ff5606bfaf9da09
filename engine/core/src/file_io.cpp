#include "engine/core/file_io.h"

#include <fstream>

#include "engine/core/error.h"

namespace engine {
namespace {

template <typename Container>
Container readWhole(const std::filesystem::path& path, std::size_t maxBytes) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw Error(path.string() + ": file not found (or not a regular file)");
  }
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw Error(path.string() + ": cannot read size: " + ec.message());
  if (size > maxBytes) {
    throw Error(path.string() + ": file is " + std::to_string(size) + " bytes, over the limit of " +
                std::to_string(maxBytes));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string() + ": cannot open for reading");
  Container data(static_cast<std::size_t>(size), {});
  in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(size));
  if (!in) throw Error(path.string() + ": read failed");
  return data;
}

}  // namespace

std::vector<std::uint8_t> readBinaryFile(const std::filesystem::path& path, std::size_t maxBytes) {
  return readWhole<std::vector<std::uint8_t>>(path, maxBytes);
}

std::string readTextFile(const std::filesystem::path& path, std::size_t maxBytes) {
  return readWhole<std::string>(path, maxBytes);
}

void writeTextFile(const std::filesystem::path& path, const std::string& text) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  if (!out) throw Error(path.string() + ": cannot open for writing");
  out << text;
  if (!out) throw Error(path.string() + ": write failed");
}

}  // namespace engine
