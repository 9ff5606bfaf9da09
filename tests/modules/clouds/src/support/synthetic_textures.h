#pragma once
// Layer textures for CPU tests of the shared model: a fixed pseudo-random field at every texel
// (so heterogeneous cases have structure), with the weather maxima the empty-space skip reads
// made from it by the module's own function.
#include <cstdint>
#include <vector>

#include "cloud_types.h"
#include "cpu_reference.h"

namespace test {

inline clouds::tools::CpuTextures syntheticTextures() {
  clouds::tools::CpuTextures t;
  auto fill = [](std::vector<std::uint8_t>& v, std::size_t texels, std::uint32_t seed) {
    v.resize(texels * 4);
    std::uint32_t state = seed;
    for (auto& b : v) {
      state = state * 1664525u + 1013904223u;
      b = static_cast<std::uint8_t>(state >> 24);
    }
  };
  // The 3D noises with room for their mip chains (n x n x 3n/2), random at every level.
  fill(t.shape, 128u * 128u * 192u, 1);
  fill(t.detail, 32u * 32u * 48u, 2);
  fill(t.curl, 128u * 128u, 3);
  fill(t.weather, 512u * 512u, 4);
  using clouds::shader::kWeatherMapSize;
  using clouds::shader::kWeatherMaxCoarseSize;
  using clouds::shader::kWeatherMaxFineSize;
  t.weatherMaxFine = clouds::tools::weatherMaxima(t.weather, kWeatherMapSize, kWeatherMaxFineSize);
  t.weatherMaxCoarse =
      clouds::tools::weatherMaxima(t.weatherMaxFine, kWeatherMaxFineSize, kWeatherMaxCoarseSize);
  return t;
}

}  // namespace test
