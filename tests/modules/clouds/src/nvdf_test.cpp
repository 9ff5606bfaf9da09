// The NVDF format (clouds/nvdf.h): round trips, every header field and value checked with a
// message naming the file and the field, any truncation refused; and building one from a grid
// (clouds/nvdf_build.h): the exact distance transform and the signed distance's promise.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>

#include "clouds/nvdf.h"
#include "clouds/nvdf_build.h"
#include "crc32.h"
#include "nvdf_sampler.h"

namespace {

using clouds::NvdfVolume;

// A small cloud: a ball of density in a 12 x 10 x 8 grid of 5 m voxels.
clouds::VoxelDensityGrid ballGrid() {
  clouds::VoxelDensityGrid grid;
  grid.size = glm::uvec3(12, 10, 8);
  grid.voxelMetres = 5.0f;
  grid.originMetres = glm::vec3(-30.0f, 100.0f, 7.5f);
  grid.density.resize(12 * 10 * 8);
  for (unsigned z = 0; z < 8; ++z) {
    for (unsigned y = 0; y < 10; ++y) {
      for (unsigned x = 0; x < 12; ++x) {
        const float r = glm::length(glm::vec3(x, y, z) - glm::vec3(5.5f, 4.5f, 3.5f));
        grid.density[(z * 10 + y) * 12 + x] = std::max(0.0f, 3.0f - r) * 0.8f;
      }
    }
  }
  return grid;
}

NvdfVolume ball() {
  clouds::Error error;
  const std::optional<NvdfVolume> volume = clouds::buildNvdf(ballGrid(), {}, &error);
  EXPECT_TRUE(volume) << error.message;
  return *volume;
}

std::string decodeError(std::span<const std::byte> bytes) {
  clouds::Error error;
  const std::optional<NvdfVolume> volume = clouds::decodeNvdf(bytes, "cloud.nvdf", &error);
  if (volume) return "";
  EXPECT_EQ(error.code, clouds::ErrorCode::InvalidAsset);
  return error.message;
}

// Writes a little-endian u32 or f32 at `offset` and re-seals the header's checksum, so the
// decoder's check of that field (not of the checksum) is what refuses the file.
void patchU32(std::vector<std::byte>& bytes, std::size_t offset, std::uint32_t value) {
  for (std::size_t i = 0; i < 4; ++i) bytes[offset + i] = std::byte((value >> (8 * i)) & 0xffu);
  const std::uint32_t crc = clouds::crc32(std::span(bytes).first(60));
  for (std::size_t i = 0; i < 4; ++i) bytes[60 + i] = std::byte((crc >> (8 * i)) & 0xffu);
}
void patchF32(std::vector<std::byte>& bytes, std::size_t offset, float value) {
  patchU32(bytes, offset, std::bit_cast<std::uint32_t>(value));
}
// Re-seals the payload's checksum after a payload edit.
void resealPayload(std::vector<std::byte>& bytes) {
  patchU32(bytes, 56, clouds::crc32(std::span(bytes).subspan(64)));
}

TEST(Crc32, MatchesTheStandardCheckValue) {
  const char* text = "123456789";
  EXPECT_EQ(clouds::crc32(std::as_bytes(std::span(text, 9))), 0xCBF43926u);
  // In parts, as one.
  const std::uint32_t first = clouds::crc32(std::as_bytes(std::span(text, 4)));
  EXPECT_EQ(clouds::crc32(std::as_bytes(std::span(text + 4, 5)), first), 0xCBF43926u);
}

TEST(Nvdf, RoundTripsThroughBytesAndFiles) {
  const NvdfVolume original = ball();
  ASSERT_EQ(clouds::validateNvdf(original), "");
  const std::vector<std::byte> bytes = clouds::encodeNvdf(original);
  EXPECT_EQ(bytes.size(), 64 + original.voxelCount() * 6);
  clouds::Error error;
  const std::optional<NvdfVolume> decoded = clouds::decodeNvdf(bytes, "ball.nvdf", &error);
  ASSERT_TRUE(decoded) << error.message;
  EXPECT_EQ(decoded->size, original.size);
  EXPECT_EQ(decoded->voxelMetres, original.voxelMetres);
  EXPECT_EQ(decoded->originMetres, original.originMetres);
  EXPECT_EQ(decoded->densityMultiplier, original.densityMultiplier);
  EXPECT_EQ(decoded->sdfRangeMetres, original.sdfRangeMetres);
  EXPECT_EQ(decoded->fields, original.fields);
  EXPECT_EQ(decoded->signedDistance, original.signedDistance);

  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "clouds_nvdf_round_trip.nvdf";
  ASSERT_TRUE(clouds::writeNvdf(file, original, &error)) << error.message;
  const std::optional<NvdfVolume> read = clouds::readNvdf(file, &error);
  ASSERT_TRUE(read) << error.message;
  EXPECT_EQ(read->fields, original.fields);
  EXPECT_EQ(read->signedDistance, original.signedDistance);
  std::filesystem::remove(file);
}

TEST(Nvdf, RefusesEachBadHeaderFieldByName) {
  const std::vector<std::byte> good = clouds::encodeNvdf(ball());
  ASSERT_EQ(decodeError(good), "");
  const auto refused = [&](auto edit, const std::string& field) {
    std::vector<std::byte> bytes = good;
    edit(bytes);
    const std::string message = decodeError(bytes);
    EXPECT_NE(message.find("cloud.nvdf: "), std::string::npos) << message;
    EXPECT_NE(message.find(field), std::string::npos) << "expected " << field << " in: " << message;
  };
  using Bytes = std::vector<std::byte>;
  refused([](Bytes& b) { b[0] = std::byte{'X'}; }, "magic");
  refused([](Bytes& b) { patchU32(b, 4, 2); }, "version");
  refused([](Bytes& b) { patchU32(b, 8, 128); }, "headerBytes");
  refused([](Bytes& b) { b[12] = std::byte{13}; }, "headerCrc32");  // size.x changed, not re-sealed
  refused([](Bytes& b) { patchU32(b, 12, 0); }, "size.x");
  refused([](Bytes& b) { patchU32(b, 16, 5000); }, "size.y");
  refused([](Bytes& b) { patchU32(b, 12, 1024), patchU32(b, 16, 1024), patchU32(b, 20, 1024); },
          "size:");
  refused([](Bytes& b) { patchF32(b, 24, std::nanf("")); }, "voxelMetres");
  refused([](Bytes& b) { patchF32(b, 24, 0.0f); }, "voxelMetres");
  refused([](Bytes& b) { patchF32(b, 32, INFINITY); }, "originMetres.y");
  refused([](Bytes& b) { patchF32(b, 40, -1.0f); }, "densityMultiplier");
  refused([](Bytes& b) { patchF32(b, 44, 0.0f); }, "sdfRangeMetres");
  refused([](Bytes& b) { patchU32(b, 48, 12); }, "payloadBytes");
  refused([](Bytes& b) { b.pop_back(); }, "payload:");
  refused([](Bytes& b) { b.push_back(std::byte{0}); }, "payload:");
  refused([](Bytes& b) { b[100] ^= std::byte{1}; }, "payloadCrc32");
}

TEST(Nvdf, RefusesEachBadVoxelByName) {
  const NvdfVolume volume = ball();
  const std::vector<std::byte> good = clouds::encodeNvdf(volume);
  // The reserved byte of voxel 3.
  std::vector<std::byte> bytes = good;
  bytes[64 + 3 * 4 + 3] = std::byte{7};
  resealPayload(bytes);
  EXPECT_NE(decodeError(bytes).find("fields[3].reserved"), std::string::npos);
  // -32768 is not a snorm16 value.
  const std::size_t distances = 64 + volume.voxelCount() * 4;
  bytes = good;
  bytes[distances + 2 * 5] = std::byte{0x00};
  bytes[distances + 2 * 5 + 1] = std::byte{0x80};
  resealPayload(bytes);
  EXPECT_NE(decodeError(bytes).find("signedDistance[5]"), std::string::npos);
  // A positive distance where there is cloud would let the march skip it.
  std::size_t cloudy = 0;
  while (volume.fields[cloudy * 4] == 0) ++cloudy;
  bytes = good;
  bytes[distances + 2 * cloudy] = std::byte{0x10};
  bytes[distances + 2 * cloudy + 1] = std::byte{0x00};
  resealPayload(bytes);
  EXPECT_NE(decodeError(bytes).find("positive inside the cloud"), std::string::npos)
      << decodeError(bytes);
}

TEST(Nvdf, RefusesEveryTruncationWithoutReadingPastTheEnd) {
  const std::vector<std::byte> good = clouds::encodeNvdf(ball());
  for (std::size_t length = 0; length < good.size(); ++length) {
    // A copy of exactly `length` bytes, so a sanitizer would catch a read beyond it.
    const std::vector<std::byte> cut(good.begin(), good.begin() + std::ptrdiff_t(length));
    EXPECT_NE(decodeError(cut), "") << length;
  }
}

TEST(Nvdf, ReadNamesAMissingFile) {
  clouds::Error error;
  EXPECT_FALSE(clouds::readNvdf("/nonexistent/hero.nvdf", &error));
  EXPECT_EQ(error.code, clouds::ErrorCode::InvalidAsset);
  EXPECT_NE(error.message.find("/nonexistent/hero.nvdf"), std::string::npos);
}

TEST(Nvdf, ValidateNamesInconsistentVolumes) {
  NvdfVolume volume = ball();
  volume.fields.pop_back();
  EXPECT_NE(clouds::validateNvdf(volume).find("NvdfVolume.fields"), std::string::npos);
  volume = ball();
  volume.signedDistance.push_back(0);
  EXPECT_NE(clouds::validateNvdf(volume).find("NvdfVolume.signedDistance"), std::string::npos);
  clouds::Error error;
  EXPECT_FALSE(
      clouds::writeNvdf(std::filesystem::temp_directory_path() / "bad.nvdf", volume, &error));
  EXPECT_NE(error.message.find("bad.nvdf"), std::string::npos);
}

// The transform against brute force on random occupancy, including a grid with one voxel set
// and grids long on one axis.
TEST(NvdfBuild, DistanceTransformIsExact) {
  std::mt19937 random(7);
  for (const glm::uvec3 size : {glm::uvec3(9, 7, 5), glm::uvec3(1, 1, 1), glm::uvec3(17, 1, 3)}) {
    for (const double share : {0.03, 0.3}) {
      const std::size_t count = std::size_t(size.x) * size.y * size.z;
      std::vector<bool> inside(count);
      std::vector<glm::vec3> set;
      for (std::size_t i = 0; i < count; ++i) {
        inside[i] = std::uniform_real_distribution<double>(0, 1)(random) < share;
      }
      inside[count / 2] = true;
      for (std::size_t i = 0; i < count; ++i) {
        if (inside[i]) {
          set.emplace_back(float(i % size.x), float(i / size.x % size.y),
                           float(i / (size.x * size.y)));
        }
      }
      const std::vector<float> d = clouds::distanceToNearest(inside, size);
      for (std::size_t i = 0; i < count; ++i) {
        const glm::vec3 p(float(i % size.x), float(i / size.x % size.y),
                          float(i / (size.x * size.y)));
        float best = INFINITY;
        for (const glm::vec3& q : set) best = std::min(best, glm::length(p - q));
        ASSERT_NEAR(d[i], best, 1e-4f) << i;
      }
    }
  }
  EXPECT_TRUE(std::isinf(clouds::distanceToNearest({false, false}, glm::uvec3(2, 1, 1))[1]));
}

// The promise the march relies on: wherever the filtered distance reads d > 0, there is no
// cloud (filtered profile 0) within d. Probed at random points and random directions.
TEST(NvdfBuild, SignedDistanceNeverOverstepsCloud) {
  const NvdfVolume v = ball();
  // The fields filtered as the GPU filters them (the CPU reference's sampler).
  const clouds::reference::NvdfSampler sampler(v);
  const auto filtered = [&](glm::vec3 p, bool distance) {
    return distance ? float(sampler.signedDistanceMetres(p)) : float(sampler.profile(p));
  };
  std::mt19937 random(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int positive = 0;
  for (int probe = 0; probe < 4000; ++probe) {
    const glm::vec3 p = v.originMetres + glm::vec3(unit(random), unit(random), unit(random)) *
                                             (glm::vec3(v.size) - 1.0f) * v.voxelMetres;
    const float d = filtered(p, true);
    if (d <= 0.0f) continue;
    ++positive;
    EXPECT_EQ(filtered(p, false), 0.0f) << "cloud at a point whose distance reads " << d;
    const glm::vec3 direction =
        glm::normalize(glm::vec3(unit(random), unit(random), unit(random)) - 0.5f);
    EXPECT_EQ(filtered(p + direction * (d * 0.999f * unit(random)), false), 0.0f);
  }
  EXPECT_GT(positive, 200);  // the probes did reach clear air
}

// Not uselessly small either: in clear air, the lattice distance to the nearest cloudy voxel
// less the filter's double reach (2 sqrt 3 voxels), rounded down by at most one step of the
// snorm16 code; in cloud, negative.
TEST(NvdfBuild, SignedDistanceIsTheLatticeDistanceLessTheFilterReach) {
  const NvdfVolume v = ball();
  const float quantum = v.sdfRangeMetres / 32767.0f;
  std::vector<glm::vec3> cloudy;
  for (std::size_t i = 0; i < v.voxelCount(); ++i) {
    if (v.fields[i * 4] > 0) {
      cloudy.emplace_back(float(i % v.size.x), float(i / v.size.x % v.size.y),
                          float(i / (v.size.x * v.size.y)));
    }
  }
  for (std::size_t i = 0; i < v.voxelCount(); ++i) {
    const glm::uvec3 voxel(i % v.size.x, i / v.size.x % v.size.y, i / (v.size.x * v.size.y));
    if (v.fields[i * 4] > 0) {
      ASSERT_LT(v.distanceMetres(voxel), 0.0f);
      continue;
    }
    float nearest = INFINITY;
    for (const glm::vec3& c : cloudy)
      nearest = std::min(nearest, glm::length(glm::vec3(voxel) - c));
    const float expected = (nearest - 2.0f * std::sqrt(3.0f)) * v.voxelMetres;
    ASSERT_LE(v.distanceMetres(voxel), expected + 1e-4f) << i;
    ASSERT_GE(v.distanceMetres(voxel), expected - quantum - 1e-4f) << i;
  }
}

TEST(NvdfBuild, ProfileIsTheDensityOverItsLargest) {
  const clouds::VoxelDensityGrid grid = ballGrid();
  const NvdfVolume v = ball();
  const float largest = *std::max_element(grid.density.begin(), grid.density.end());
  EXPECT_FLOAT_EQ(v.densityMultiplier, largest);
  for (std::size_t i = 0; i < v.voxelCount(); ++i) {
    ASSERT_NEAR(float(v.fields[i * 4]) / 255.0f, grid.density[i] / largest, 0.5f / 255.0f);
    ASSERT_EQ(v.fields[i * 4 + clouds::kNvdfDetailType], 128);  // the default 0.5
    ASSERT_EQ(v.fields[i * 4 + clouds::kNvdfDensityScale], 255);
  }
}

TEST(NvdfBuild, OneVoxelBuildsAndNothingAtAllIsRefused) {
  clouds::VoxelDensityGrid grid;
  grid.size = glm::uvec3(1);
  grid.voxelMetres = 1.0f;
  grid.density = {2.0f};
  clouds::Error error;
  const std::optional<NvdfVolume> one = clouds::buildNvdf(grid, {}, &error);
  ASSERT_TRUE(one) << error.message;
  EXPECT_EQ(clouds::validateNvdf(*one), "");
  EXPECT_LT(one->distanceMetres(glm::uvec3(0)), 0.0f);

  grid.density = {0.0f};
  EXPECT_FALSE(clouds::buildNvdf(grid, {}, &error));
  EXPECT_NE(error.message.find("holds no cloud"), std::string::npos);
}

TEST(NvdfBuild, RefusesBadGridsByField) {
  const auto refused = [](clouds::VoxelDensityGrid grid, const std::string& field) {
    clouds::Error error;
    EXPECT_FALSE(clouds::buildNvdf(grid, {}, &error));
    EXPECT_EQ(error.code, clouds::ErrorCode::InvalidAsset);
    EXPECT_NE(error.message.find(field), std::string::npos) << error.message;
  };
  clouds::VoxelDensityGrid grid = ballGrid();
  grid.density[17] = std::nanf("");
  refused(grid, "VoxelDensityGrid.density[17]");
  grid = ballGrid();
  grid.density[3] = -1.0f;
  refused(grid, "VoxelDensityGrid.density[3]");
  grid = ballGrid();
  grid.density.pop_back();
  refused(grid, "VoxelDensityGrid.density: holds");
  grid = ballGrid();
  grid.detailType.assign(grid.density.size(), 1.5f);
  refused(grid, "VoxelDensityGrid.detailType[0]");
  grid = ballGrid();
  grid.voxelMetres = 0.0f;
  refused(grid, "VoxelDensityGrid.voxelMetres");
  grid = ballGrid();
  grid.size.z = 0;
  refused(grid, "VoxelDensityGrid.size.z");
}

}  // namespace
