#pragma once
// Lightning bolts onto the screen: FrameInputs::lightningBolts projected into the pieces the
// upsample draws (cloud_types.h's LightningBoltsHeader layout), clipped to what the camera
// sees and binned into screen tiles, so that each pixel tests only the pieces near it. A pure
// function of the inputs, tested without a GPU.
#include <cstdint>
#include <vector>

#include "cloud_types.h"
#include "clouds/clouds.h"

namespace clouds::detail {

struct ProjectedBolts {
  shader::LightningBoltsHeader header{};
  std::vector<glm::vec4> segments;    // 3 vec4s per piece on screen (cloud_types.h)
  std::vector<glm::uvec2> tiles;      // per tile, row by row: its first index and count
  std::vector<std::uint32_t> pieces;  // the tiles' pieces' indices
  std::vector<std::uint32_t> blocks;  // the 8 x 8 pixel blocks of the tiles with pieces

  // What follows the header in the buffer: the words header.tiles addresses.
  std::vector<std::uint32_t> words() const;
};

// The pieces of `inputs.lightningBolts` in front of the camera and on screen (with a margin of
// their width), in output pixels of `inputs.renderExtent`, binned into tiles of 8 px (or
// coarser, to keep within kBoltMaxTiles and kBoltMaxTileIndices), the blocks of the tiles that
// hold pieces listed (when within kBoltMaxBlocks).
ProjectedBolts projectBolts(const FrameInputs& inputs);

// The buffer's size for `segments` pieces (0 for none).
std::uint64_t boltBufferBytes(std::uint32_t segments);

}  // namespace clouds::detail
