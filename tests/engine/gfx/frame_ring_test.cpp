// Frames in flight: slots are recycled only after the GPU retires them, timings come back,
// and per-frame constants are reusable.
#include <gtest/gtest.h>

#include "engine/gfx/frame_ring.h"
#include "gpu_test.h"

namespace {

using namespace engine::gfx;

class FrameRingTest : public test::GpuTest {};

TEST_F(FrameRingTest, RecyclesSlotsAndReportsTimings) {
  FrameRing ring(device());
  for (std::uint64_t i = 0; i < 6; ++i) {
    FrameRing::Frame& frame = ring.begin();
    EXPECT_EQ(frame.index, i);
    EXPECT_EQ(frame.slot, i % FrameRing::kFramesInFlight);
    const auto slice = frame.constants->push(static_cast<float>(i));
    EXPECT_NE(slice.buffer, VK_NULL_HANDLE);
    const std::uint32_t scope = frame.timer->begin(frame.cmd, "empty frame");
    frame.timer->end(frame.cmd, scope);
    ring.submit();
    if (i >= FrameRing::kFramesInFlight) {
      EXPECT_EQ(ring.lastRetiredFrameIndex(), i - FrameRing::kFramesInFlight);
      ASSERT_EQ(ring.lastTimings().size(), 1u);
      EXPECT_STREQ(ring.lastTimings()[0].name, "empty frame");
    }
  }
  ring.drain();
  EXPECT_EQ(ring.lastRetiredFrameIndex(), 5u);
}

}  // namespace
