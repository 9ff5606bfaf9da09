#include "gltf_asset_folder.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <limits>
#include <string_view>
#include <system_error>

#include "engine/core/error.h"
#include "engine/core/file_io.h"
#include "gltf_checked_math.h"

namespace engine::assets::gltf {
namespace fs = std::filesystem;
namespace {

unsigned char hexValue(char c) {
  if (c >= '0' && c <= '9') return static_cast<unsigned char>(c - '0');
  if (c >= 'a' && c <= 'f') return static_cast<unsigned char>(c - 'a' + 10);
  if (c >= 'A' && c <= 'F') return static_cast<unsigned char>(c - 'A' + 10);
  return 0;  // tinygltf maps invalid digits to 0 too
}

// "scheme:" per RFC 3986 (ALPHA *( ALPHA / DIGIT / "+" / "-" / "." ) ":"). A Windows drive
// letter matches too, which is right: it is not a relative path either.
std::string_view uriScheme(std::string_view uri) {
  if (uri.empty() || !std::isalpha(static_cast<unsigned char>(uri[0]))) return {};
  for (std::size_t i = 1; i < uri.size(); ++i) {
    const auto c = static_cast<unsigned char>(uri[i]);
    if (c == ':') return uri.substr(0, i + 1);
    if (!std::isalnum(c) && c != '+' && c != '-' && c != '.') return {};
  }
  return {};
}

bool hasDotDotSegment(std::string_view path) {
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t end = std::min(path.find_first_of("/\\", start), path.size());
    if (path.substr(start, end - start) == "..") return true;
    start = end + 1;
  }
  return false;
}

fs::path canonicalOrEmpty(const fs::path& path) {
  std::error_code ec;
  fs::path result = fs::weakly_canonical(path, ec);
  return ec ? fs::path() : result;
}

}  // namespace

bool isSupportedDataUri(const std::string& uri) {
  static constexpr std::array<std::string_view, 7> kPrefixes = {
      "data:application/octet-stream;base64,",
      "data:application/gltf-buffer;base64,",
      "data:image/jpeg;base64,",
      "data:image/png;base64,",
      "data:image/bmp;base64,",
      "data:image/gif;base64,",
      "data:text/plain;base64,"};
  return std::any_of(kPrefixes.begin(), kPrefixes.end(),
                     [&](std::string_view prefix) { return uri.starts_with(prefix); });
}

std::string decodeUriLikeTinyGltf(const std::string& uri) {
  std::string out;
  out.reserve(uri.size());
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && uri.size() > i + 2) {
      out += static_cast<char>((hexValue(uri[i + 1]) << 4) | hexValue(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

AssetFolder::AssetFolder(const fs::path& assetFile, std::uint64_t maxFileBytes,
                         std::uint64_t maxTotalBytes)
    : root_(canonicalOrEmpty(fs::absolute(assetFile)).parent_path()),
      maxFileBytes_(maxFileBytes),
      maxTotalBytes_(maxTotalBytes) {}

bool AssetFolder::contains(const fs::path& path) const {
  const fs::path canonical = canonicalOrEmpty(path);
  if (canonical.empty() || root_.empty()) return false;
  // Component-wise prefix test: "/a/bc" must not count as inside "/a/b".
  auto [rootEnd, pathIt] =
      std::mismatch(root_.begin(), root_.end(), canonical.begin(), canonical.end());
  return rootEnd == root_.end() && pathIt != canonical.end();
}

std::uint64_t AssetFolder::checkUri(const std::string& uri) const {
  const std::string quoted = "uri '" + uri.substr(0, 200) + "'";
  if (uri.empty()) throw Error("empty uri");
  if (const auto scheme = uriScheme(uri); !scheme.empty()) {
    throw Error(quoted + ": scheme '" + std::string(scheme) +
                "' is not allowed (only relative paths and base64 data: URIs)");
  }
  const std::string decoded = decodeUriLikeTinyGltf(uri);
  if (std::any_of(decoded.begin(), decoded.end(),
                  [](char c) { return static_cast<unsigned char>(c) < 0x20; })) {
    throw Error(quoted + ": contains control characters");
  }
  if (decoded.empty() || decoded.front() == '/' || decoded.front() == '\\') {
    throw Error(quoted + ": absolute paths are not allowed (must be relative to the asset)");
  }
  if (hasDotDotSegment(decoded)) {
    throw Error(quoted + ": '..' segments are not allowed (must stay in the asset's folder)");
  }
  const fs::path file = root_ / decoded;
  if (!contains(file)) throw Error(quoted + ": resolves outside the asset folder");
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) {
    throw Error(quoted + ": external file " + file.string() + " not found");
  }
  const std::uint64_t size = fs::file_size(file, ec);
  if (ec) throw Error(quoted + ": cannot read size of " + file.string());
  if (size > maxFileBytes_) {
    throw Error(quoted + ": file is " + std::to_string(size) + " bytes, over the limit of " +
                std::to_string(maxFileBytes_));
  }
  return size;
}

tinygltf::FsCallbacks AssetFolder::callbacks() {
  return tinygltf::FsCallbacks{&AssetFolder::fileExists, &AssetFolder::expandPath,
                               &AssetFolder::readWholeFile, &AssetFolder::writeWholeFile, this};
}

bool AssetFolder::readConfined(const std::string& path, std::vector<unsigned char>& out,
                               std::string& err) {
  if (!contains(path)) {
    err = "outside the asset folder";
    return false;
  }
  std::error_code ec;
  const std::uint64_t size = fs::file_size(path, ec);
  if (ec) {
    err = "cannot read size";
    return false;
  }
  if (checkedAdd(bytesRead_, size) > maxTotalBytes_) {
    err =
        "external files together exceed the limit of " + std::to_string(maxTotalBytes_) + " bytes";
    return false;
  }
  try {
    const auto cap =
        std::min<std::uint64_t>(maxFileBytes_, std::numeric_limits<std::size_t>::max());
    out = readBinaryFile(path, static_cast<std::size_t>(cap));
  } catch (const Error& e) {
    err = e.what();
    return false;
  }
  bytesRead_ = checkedAdd(bytesRead_, out.size());
  return true;
}

bool AssetFolder::fileExists(const std::string& path, void* self) {
  std::error_code ec;
  return static_cast<AssetFolder*>(self)->contains(path) && fs::is_regular_file(path, ec);
}

std::string AssetFolder::expandPath(const std::string& path, void* self) {
  // No '~' or environment expansion; tinygltf's fallback search in "." becomes the root.
  const fs::path p(path);
  return p.is_absolute() ? path : (static_cast<AssetFolder*>(self)->root_ / p).string();
}

bool AssetFolder::readWholeFile(std::vector<unsigned char>* out, std::string* err,
                                const std::string& path, void* self) {
  std::string message;
  const bool ok = static_cast<AssetFolder*>(self)->readConfined(path, *out, message);
  if (!ok && err) *err = message;
  return ok;
}

bool AssetFolder::writeWholeFile(std::string* err, const std::string&,
                                 const std::vector<unsigned char>&, void*) {
  if (err) *err = "writing is not allowed while loading";
  return false;
}

}  // namespace engine::assets::gltf
