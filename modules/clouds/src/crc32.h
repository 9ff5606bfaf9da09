#pragma once
// CRC-32 (ISO-HDLC: the one of zlib, PNG and gzip; reflected polynomial 0xEDB88320, initial
// and final value 0xFFFFFFFF), for checksums of the module's asset files. "123456789" gives
// 0xCBF43926.
#include <cstddef>
#include <cstdint>
#include <span>

namespace clouds {

// The CRC of `bytes` continued from `crc` (pass the result of one call into the next to checksum
// data in parts; start from 0).
std::uint32_t crc32(std::span<const std::byte> bytes, std::uint32_t crc = 0);

}  // namespace clouds
