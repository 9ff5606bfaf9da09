#pragma once
// Overflow-safe size arithmetic for validating ranges read from untrusted files.
#include <cstdint>
#include <limits>

namespace engine::assets::gltf {

// Sums and products saturate at UINT64_MAX instead of wrapping: no real buffer is that large, so
// a saturated end offset fails the range check it feeds rather than passing it after a wrap.
inline std::uint64_t checkedAdd(std::uint64_t a, std::uint64_t b) {
  std::uint64_t sum = 0;
  return __builtin_add_overflow(a, b, &sum) ? std::numeric_limits<std::uint64_t>::max() : sum;
}

inline std::uint64_t checkedMul(std::uint64_t a, std::uint64_t b) {
  std::uint64_t product = 0;
  return __builtin_mul_overflow(a, b, &product) ? std::numeric_limits<std::uint64_t>::max()
                                                : product;
}

// True when [offset, offset + length) lies inside [0, size).
inline bool rangeFits(std::uint64_t offset, std::uint64_t length, std::uint64_t size) {
  return offset <= size && checkedAdd(offset, length) <= size;
}

}  // namespace engine::assets::gltf
