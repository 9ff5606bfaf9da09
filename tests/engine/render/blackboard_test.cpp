// The frame graph's blackboard: per-frame values found by type, kept at one address.
#include <gtest/gtest.h>

#include <string>

#include "engine/core/error.h"
#include "engine/render/frame_graph.h"

namespace {

using engine::render::Blackboard;

struct Haze {
  float rangeMetres = 0.0f;
};
struct Shadow {
  int cascades = 0;
};

TEST(Blackboard, FindsEachEntryByItsType) {
  Blackboard board;
  EXPECT_EQ(board.find<Haze>(), nullptr);
  EXPECT_FALSE(board.has<Haze>());
  board.put(Haze{1000.0f});
  board.put(Shadow{4});
  ASSERT_TRUE(board.has<Haze>());
  EXPECT_EQ(board.get<Haze>().rangeMetres, 1000.0f);
  EXPECT_EQ(board.get<Shadow>().cascades, 4);
  EXPECT_EQ(board.size(), 2u);
}

// A pass that holds a pointer to an entry keeps seeing the value a later put() gives it.
TEST(Blackboard, PuttingAgainAssignsInPlace) {
  Blackboard board;
  const Haze* held = &board.put(Haze{1.0f});
  board.put(Shadow{});  // another entry does not move it
  board.put(Haze{2.0f});
  EXPECT_EQ(board.find<Haze>(), held);
  EXPECT_EQ(held->rangeMetres, 2.0f);
  EXPECT_EQ(board.size(), 2u);
}

TEST(Blackboard, AMissingEntryIsAnErrorNamingItsType) {
  const Blackboard board;
  try {
    (void)board.get<Haze>();
    FAIL() << "expected an error";
  } catch (const engine::Error& error) {
    EXPECT_NE(std::string(error.what()).find("Haze"), std::string::npos) << error.what();
  }
}

// Each graph has its own: a rebuilt graph starts empty, so nothing stale survives a rebuild.
TEST(Blackboard, EachGraphHasItsOwn) {
  engine::render::FrameGraph first;
  first.blackboard().put(Haze{5.0f});
  const engine::render::FrameGraph second;
  EXPECT_FALSE(second.blackboard().has<Haze>());
}

}  // namespace
