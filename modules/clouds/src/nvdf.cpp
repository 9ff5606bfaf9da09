// The NVDF codec (clouds/nvdf.h; the byte layout is docs/nvdf-format.md's). Decoding trusts
// nothing: every size is checked against the bytes there are before it is used, the header
// and the payload each carry a CRC-32, and each value is checked against its range.
#include "clouds/nvdf.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "crc32.h"

namespace clouds {

namespace {

constexpr char kMagic[4] = {'N', 'V', 'D', 'F'};
constexpr std::size_t kHeaderBytes = 64;
constexpr std::size_t kHeaderCrcOffset = 60;  // the header's own CRC covers the bytes before it
constexpr std::size_t kSignedDistanceBytes = 2;
constexpr std::int16_t kSnorm16Max = 32767;
// Files larger than any valid volume's are refused before they are read.
constexpr std::uintmax_t kMaxFileBytes =
    kHeaderBytes + kNvdfMaxVoxels * (kNvdfChannels + kSignedDistanceBytes);

// Little-endian fields, whatever the host's byte order.
class Writer {
 public:
  explicit Writer(std::vector<std::byte>& out) : out_(out) {}
  void u32(std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out_.push_back(std::byte((v >> (8 * i)) & 0xffu));
  }
  void u64(std::uint64_t v) {
    u32(std::uint32_t(v & 0xffffffffu));
    u32(std::uint32_t(v >> 32));
  }
  void f32(float v) { u32(std::bit_cast<std::uint32_t>(v)); }

 private:
  std::vector<std::byte>& out_;
};

class Reader {
 public:
  explicit Reader(std::span<const std::byte> bytes) : bytes_(bytes) {}
  std::uint32_t u32(std::size_t offset) const {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) {
      v |= std::to_integer<std::uint32_t>(bytes_[offset + i]) << (8 * i);
    }
    return v;
  }
  std::uint64_t u64(std::size_t offset) const {
    return std::uint64_t{u32(offset)} | std::uint64_t{u32(offset + 4)} << 32;
  }
  float f32(std::size_t offset) const { return std::bit_cast<float>(u32(offset)); }

 private:
  std::span<const std::byte> bytes_;
};

bool fail(Error* error, std::string message) {
  if (error != nullptr) *error = Error{ErrorCode::InvalidAsset, std::move(message)};
  return false;
}

std::string describe(float value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

std::uint64_t voxelsOf(glm::uvec3 size) {
  return std::uint64_t{size.x} * size.y * size.z;
}

// Empty when the shape fields are in range, else "<field>: <reason>".
std::string checkShape(glm::uvec3 size, float voxelMetres, glm::vec3 origin, float multiplier,
                       float sdfRange) {
  const char* axes[3] = {"size.x", "size.y", "size.z"};
  for (int a = 0; a < 3; ++a) {
    if (size[a] < 1 || size[a] > kNvdfMaxSide) {
      return std::string(axes[a]) + ": must be in [1, " + std::to_string(kNvdfMaxSide) +
             "] voxels, got " + std::to_string(size[a]);
    }
  }
  if (voxelsOf(size) > kNvdfMaxVoxels) {
    return "size: " + std::to_string(voxelsOf(size)) + " voxels, more than the " +
           std::to_string(kNvdfMaxVoxels) + " allowed";
  }
  if (!(voxelMetres >= kNvdfMinVoxelMetres && voxelMetres <= kNvdfMaxVoxelMetres)) {
    return "voxelMetres: must be in [" + describe(kNvdfMinVoxelMetres) + ", " +
           describe(kNvdfMaxVoxelMetres) + "], got " + describe(voxelMetres);
  }
  const char* originAxes[3] = {"originMetres.x", "originMetres.y", "originMetres.z"};
  for (int a = 0; a < 3; ++a) {
    if (!(std::abs(origin[a]) <= 1e7f)) {
      return std::string(originAxes[a]) + ": must be finite and within 10,000 km, got " +
             describe(origin[a]);
    }
  }
  if (!(multiplier > 0.0f && multiplier <= 1e9f)) {
    return "densityMultiplier: must be in (0, 1e9], got " + describe(multiplier);
  }
  if (!(sdfRange > 0.0f && sdfRange <= 1e7f)) {
    return "sdfRangeMetres: must be in (0, 1e7], got " + describe(sdfRange);
  }
  return {};
}

// Empty when the per-voxel values are valid, else "<field>: <reason>".
std::string checkVoxels(const NvdfVolume& v) {
  const std::size_t count = v.voxelCount();
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint8_t* voxel = &v.fields[i * kNvdfChannels];
    const std::int16_t distance = v.signedDistance[i];
    if (voxel[kNvdfReserved] != 0) {
      return "fields[" + std::to_string(i) + "].reserved: must be 0 in version 1, got " +
             std::to_string(voxel[kNvdfReserved]);
    }
    if (distance < -kSnorm16Max) {
      return "signedDistance[" + std::to_string(i) + "]: -32768 is not a snorm16 value";
    }
    // Where there is cloud the march must sample: a positive distance there would skip it.
    if (voxel[kNvdfProfile] > 0 && distance > 0) {
      return "signedDistance[" + std::to_string(i) +
             "]: positive inside the cloud (dimensional profile " +
             std::to_string(voxel[kNvdfProfile]) + "/255), the march would skip it";
    }
  }
  return {};
}

}  // namespace

std::size_t NvdfVolume::voxelCount() const {
  return std::size_t(size.x) * size.y * size.z;
}

std::size_t NvdfVolume::voxelIndex(glm::uvec3 voxel) const {
  return (std::size_t(voxel.z) * size.y + voxel.y) * size.x + voxel.x;
}

float NvdfVolume::field(glm::uvec3 voxel, NvdfChannel channel) const {
  return float(fields[voxelIndex(voxel) * kNvdfChannels + channel]) / 255.0f;
}

float NvdfVolume::distanceMetres(glm::uvec3 voxel) const {
  return float(signedDistance[voxelIndex(voxel)]) / float(kSnorm16Max) * sdfRangeMetres;
}

std::size_t NvdfVolume::deviceBytes() const {
  return voxelCount() * kNvdfChannels;
}

glm::vec3 NvdfVolume::boundsMinMetres() const {
  return originMetres - voxelMetres;
}

glm::vec3 NvdfVolume::boundsMaxMetres() const {
  return originMetres + glm::vec3(size) * voxelMetres;
}

std::string validateNvdf(const NvdfVolume& volume) {
  const std::string shape = checkShape(volume.size, volume.voxelMetres, volume.originMetres,
                                       volume.densityMultiplier, volume.sdfRangeMetres);
  if (!shape.empty()) return "NvdfVolume." + shape;
  const std::size_t count = volume.voxelCount();
  if (volume.fields.size() != count * kNvdfChannels) {
    return "NvdfVolume.fields: holds " + std::to_string(volume.fields.size()) + " bytes, " +
           std::to_string(count * kNvdfChannels) + " expected";
  }
  if (volume.signedDistance.size() != count) {
    return "NvdfVolume.signedDistance: holds " + std::to_string(volume.signedDistance.size()) +
           " values, " + std::to_string(count) + " expected";
  }
  const std::string voxels = checkVoxels(volume);
  return voxels.empty() ? std::string{} : "NvdfVolume." + voxels;
}

std::vector<std::byte> encodeNvdf(const NvdfVolume& volume) {
  std::vector<std::byte> payload;
  payload.reserve(volume.deviceBytes());
  for (const std::uint8_t b : volume.fields) payload.push_back(std::byte{b});
  for (const std::int16_t d : volume.signedDistance) {
    const auto bits = std::uint16_t(d);
    payload.push_back(std::byte(bits & 0xffu));
    payload.push_back(std::byte(bits >> 8));
  }

  std::vector<std::byte> out;
  out.reserve(kHeaderBytes + payload.size());
  for (const char c : kMagic) out.push_back(std::byte(c));
  Writer w(out);
  w.u32(kNvdfVersion);
  w.u32(std::uint32_t(kHeaderBytes));
  w.u32(volume.size.x);
  w.u32(volume.size.y);
  w.u32(volume.size.z);
  w.f32(volume.voxelMetres);
  w.f32(volume.originMetres.x);
  w.f32(volume.originMetres.y);
  w.f32(volume.originMetres.z);
  w.f32(volume.densityMultiplier);
  w.f32(volume.sdfRangeMetres);
  w.u64(payload.size());
  w.u32(crc32(payload));
  w.u32(crc32(std::span(out).first(kHeaderCrcOffset)));
  out.insert(out.end(), payload.begin(), payload.end());
  return out;
}

std::optional<NvdfVolume> decodeNvdf(std::span<const std::byte> bytes, std::string_view source,
                                     Error* error) {
  const std::string at = std::string(source) + ": ";
  if (bytes.size() < kHeaderBytes) {
    fail(error, at + "header: the file has " + std::to_string(bytes.size()) +
                    " bytes, fewer than the 64 of an NVDF header");
    return std::nullopt;
  }
  if (std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0) {
    fail(error, at + "magic: not an NVDF file (it does not start with \"NVDF\")");
    return std::nullopt;
  }
  const Reader r(bytes);
  if (const std::uint32_t version = r.u32(4); version != kNvdfVersion) {
    fail(error, at + "version: " + std::to_string(version) +
                    " is not supported (this build reads " + std::to_string(kNvdfVersion) + ")");
    return std::nullopt;
  }
  if (const std::uint32_t headerBytes = r.u32(8); headerBytes != kHeaderBytes) {
    fail(error, at + "headerBytes: must be 64 in version 1, got " + std::to_string(headerBytes));
    return std::nullopt;
  }
  if (crc32(bytes.first(kHeaderCrcOffset)) != r.u32(kHeaderCrcOffset)) {
    fail(error, at + "headerCrc32: the header is corrupt (its checksum does not match)");
    return std::nullopt;
  }
  NvdfVolume v;
  v.size = glm::uvec3(r.u32(12), r.u32(16), r.u32(20));
  v.voxelMetres = r.f32(24);
  v.originMetres = glm::vec3(r.f32(28), r.f32(32), r.f32(36));
  v.densityMultiplier = r.f32(40);
  v.sdfRangeMetres = r.f32(44);
  if (const std::string shape =
          checkShape(v.size, v.voxelMetres, v.originMetres, v.densityMultiplier, v.sdfRangeMetres);
      !shape.empty()) {
    fail(error, at + shape);
    return std::nullopt;
  }
  const std::size_t count = v.voxelCount();
  const std::uint64_t payloadBytes = r.u64(48);
  const std::uint64_t expected = std::uint64_t{count} * (kNvdfChannels + kSignedDistanceBytes);
  if (payloadBytes != expected) {
    fail(error, at + "payloadBytes: " + std::to_string(payloadBytes) + " for " +
                    std::to_string(count) + " voxels, " + std::to_string(expected) + " expected");
    return std::nullopt;
  }
  if (bytes.size() != kHeaderBytes + payloadBytes) {
    fail(error, at + "payload: the file has " + std::to_string(bytes.size() - kHeaderBytes) +
                    " bytes after the header, " + std::to_string(payloadBytes) +
                    " expected (truncated or with trailing data)");
    return std::nullopt;
  }
  const std::span payload = bytes.subspan(kHeaderBytes);
  if (crc32(payload) != r.u32(56)) {
    fail(error, at + "payloadCrc32: the voxel data is corrupt (its checksum does not match)");
    return std::nullopt;
  }
  v.fields.resize(count * kNvdfChannels);
  std::memcpy(v.fields.data(), payload.data(), v.fields.size());
  v.signedDistance.resize(count);
  const std::span distances = payload.subspan(v.fields.size());
  for (std::size_t i = 0; i < count; ++i) {
    const auto lo = std::to_integer<std::uint16_t>(distances[2 * i]);
    const auto hi = std::to_integer<std::uint16_t>(distances[2 * i + 1]);
    v.signedDistance[i] = std::int16_t(std::uint16_t(lo | hi << 8));
  }
  if (const std::string voxels = checkVoxels(v); !voxels.empty()) {
    fail(error, at + voxels);
    return std::nullopt;
  }
  return v;
}

std::optional<NvdfVolume> readNvdf(const std::filesystem::path& file, Error* error) {
  const std::string name = file.string();
  std::error_code code;
  const std::uintmax_t fileBytes = std::filesystem::file_size(file, code);
  if (code) {
    fail(error, name + ": cannot read: " + code.message());
    return std::nullopt;
  }
  if (fileBytes > kMaxFileBytes) {
    fail(error, name + ": size: " + std::to_string(fileBytes) +
                    " bytes, more than any valid NVDF file holds");
    return std::nullopt;
  }
  std::ifstream in(file, std::ios::binary);
  std::vector<std::byte> bytes(static_cast<std::size_t>(fileBytes));
  if (!in || !in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()))) {
    fail(error, name + ": cannot read the file");
    return std::nullopt;
  }
  return decodeNvdf(bytes, name, error);
}

bool writeNvdf(const std::filesystem::path& file, const NvdfVolume& volume, Error* error) {
  if (const std::string problem = validateNvdf(volume); !problem.empty()) {
    return fail(error, file.string() + ": " + problem);
  }
  const std::vector<std::byte> bytes = encodeNvdf(volume);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out ||
      !out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()))) {
    return fail(error, file.string() + ": cannot write the file");
  }
  return true;
}

}  // namespace clouds
