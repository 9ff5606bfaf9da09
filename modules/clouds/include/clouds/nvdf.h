#pragma once
// NVDF: a hero cloud's normalised voxel data fields (Schneider 2023, "Nubis³"), as the clouds
// module reads them from disk. One file holds one cloud:
//  - the dimensional profile, [0, 1]: 0 at the cloud's edge, 1 in its core; the density before
//    the noise erodes it, and what the lighting reads as "how deep inside" (in-scatter, ambient);
//  - the detail type, [0, 1]: 0 wispy, 1 billowy (which noise erodes the profile);
//  - the density scale, [0, 1]: the "wetness" a region of the cloud keeps after erosion;
//  - a signed distance field (metres): a point whose distance is d > 0 has no cloud within d,
//    so the march may jump d; d <= 0 marks the cloud's envelope, where it samples.
// The byte layout is docs/nvdf-format.md's; this header is the C++ side of it. The voxels are
// in the cloud's own frame (metres, y up); a scene places, scales and turns the whole cloud.
#include "clouds/clouds.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace clouds {

// The version this build writes and the only one it reads.
inline constexpr std::uint32_t kNvdfVersion = 1;
// Bounds a file is checked against: a side of at most 1024 voxels and 2^26 voxels in all
// (384 MiB as the GPU holds them), voxels of 1 cm to 1 km.
inline constexpr std::uint32_t kNvdfMaxSide = 1024;
inline constexpr std::uint64_t kNvdfMaxVoxels = std::uint64_t{1} << 26;
inline constexpr float kNvdfMinVoxelMetres = 0.01f;
inline constexpr float kNvdfMaxVoxelMetres = 1000.0f;

// The fields of one voxel, in the order NvdfVolume::fields holds them (unorm8 each).
enum NvdfChannel : std::uint32_t {
  kNvdfProfile = 0,
  kNvdfDetailType = 1,
  kNvdfDensityScale = 2,
  kNvdfReserved = 3,  // 0 in version 1
  kNvdfChannels = 4,
};

struct NvdfVolume {
  glm::uvec3 size{0u};           // voxels along x, y (up) and z
  float voxelMetres = 0.0f;      // the edge of a voxel
  glm::vec3 originMetres{0.0f};  // where voxel (0, 0, 0)'s centre lies in the cloud's frame
  // What density 1 of the fields stands for in the source's units (an imported grid's largest
  // value; 1 for authored clouds): extinction = profile x scale x this x extinction per metre.
  float densityMultiplier = 1.0f;
  // The signed distances are stored as snorm16 of this range (|d| beyond it reads as the range).
  float sdfRangeMetres = 0.0f;
  // kNvdfChannels bytes per voxel, x fastest, then y, then z.
  std::vector<std::uint8_t> fields;
  // One snorm16 per voxel, same order: distance = value / 32767 x sdfRangeMetres.
  std::vector<std::int16_t> signedDistance;

  std::size_t voxelCount() const;
  std::size_t voxelIndex(glm::uvec3 voxel) const;
  float field(glm::uvec3 voxel, NvdfChannel channel) const;  // [0, 1]
  float distanceMetres(glm::uvec3 voxel) const;
  // Bytes the module's GPU copy takes: 4 per voxel (its atlas keeps the three fields and the
  // signed distance at 8 bits, rounded down so that it stays a bound: hero_clouds.h).
  std::size_t deviceBytes() const;
  // The cloud's bounds in its frame (metres): the voxel centres' box grown by one voxel, the
  // reach of trilinear filtering.
  glm::vec3 boundsMinMetres() const;
  glm::vec3 boundsMaxMetres() const;
};

// Empty when every field is consistent and in range, else "NvdfVolume.<field>: <reason>".
std::string validateNvdf(const NvdfVolume& volume);

// The file's bytes for a valid volume (validateNvdf() empty).
std::vector<std::byte> encodeNvdf(const NvdfVolume& volume);

// Parses a file's bytes, checking the header field by field, the sizes, the checksum and every
// value; `source` names the file in messages. On failure: nullopt and ErrorCode::InvalidAsset
// with "<source>: <field>: <reason>". Never reads out of bounds, whatever the bytes.
std::optional<NvdfVolume> decodeNvdf(std::span<const std::byte> bytes, std::string_view source,
                                     Error* error);

std::optional<NvdfVolume> readNvdf(const std::filesystem::path& file, Error* error);
bool writeNvdf(const std::filesystem::path& file, const NvdfVolume& volume, Error* error);

}  // namespace clouds
