// The HUD's draw plan (hud_draw_plan.h): ImGui's opaque rectangles become clears of exactly
// the pixels their triangles cover, everything else is drawn in ImGui's order, and a
// rectangle over something drawn before it stays drawn. (That the clears and the triangles make
// the same image on the device: HeadlessCapture.ThePanelsClearsDrawWhatItsTrianglesWould.)
#include "render/hud_draw_plan.h"
#include "render/hud_layout.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <functional>
#include <numeric>

namespace {

using sample::HudDrawPlan;
using sample::planHudDraws;

constexpr VkExtent2D kDisplay{320, 180};

// One ImGui frame whose background draw list gets what `draw` adds; its plan.
HudDrawPlan planOf(const std::function<void(ImDrawList&)>& draw, bool clears = true,
                   int* totalIndices = nullptr) {
  ImGuiContext* context = sample::createLayoutContext(kDisplay);
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::NewFrame();
  draw(*ImGui::GetBackgroundDrawList());
  ImGui::Render();
  const ImDrawData& data = *ImGui::GetDrawData();
  const HudDrawPlan plan = planHudDraws(data, io.Fonts->TexUvWhitePixel, kDisplay, clears);
  if (totalIndices != nullptr) *totalIndices = data.TotalIdxCount;
  ImGui::DestroyContext(context);
  return plan;
}

std::uint32_t drawnIndices(const HudDrawPlan& plan) {
  return std::accumulate(
      plan.draws.begin(), plan.draws.end(), 0u,
      [](std::uint32_t n, const sample::HudDraw& d) { return n + d.indexCount; });
}

constexpr ImU32 kOpaqueBlue = IM_COL32(40, 80, 200, 255);

TEST(HudDrawPlan, PixelsAreThoseWhoseCentresTheEdgesEnclose) {
  // Centres at x + 0.5: [0.5, 2.5) holds 0.5 and 1.5; a left edge on a centre takes it, a
  // right edge on one leaves it.
  EXPECT_EQ(sample::pixelsCoveredBetween(0.5f, 2.5f).first, 0);
  EXPECT_EQ(sample::pixelsCoveredBetween(0.5f, 2.5f).end, 2);
  EXPECT_EQ(sample::pixelsCoveredBetween(0.0f, 2.0f).first, 0);
  EXPECT_EQ(sample::pixelsCoveredBetween(0.0f, 2.0f).end, 2);
  EXPECT_EQ(sample::pixelsCoveredBetween(0.6f, 1.4f).first, 1);  // no centre inside
  EXPECT_EQ(sample::pixelsCoveredBetween(0.6f, 1.4f).end, 1);
  EXPECT_EQ(sample::pixelsCoveredBetween(10.2f, 20.7f).first, 10);
  EXPECT_EQ(sample::pixelsCoveredBetween(10.2f, 20.7f).end, 21);
}

TEST(HudDrawPlan, AnOpaqueRectangleIsCleared) {
  const auto oneRectangle = [](ImDrawList& l) {
    l.AddRectFilled({10.2f, 20.0f}, {50.7f, 30.5f}, kOpaqueBlue);
  };
  int indices = 0;
  const HudDrawPlan plan = planOf(oneRectangle, true, &indices);
  ASSERT_EQ(plan.clears.size(), 1u);
  EXPECT_EQ(plan.clears[0].rect.offset.x, 10);
  EXPECT_EQ(plan.clears[0].rect.offset.y, 20);
  EXPECT_EQ(plan.clears[0].rect.extent.width, 41u);   // columns 10 .. 50
  EXPECT_EQ(plan.clears[0].rect.extent.height, 10u);  // rows 20 .. 29: 30.5 is on row 30's centre
  EXPECT_FLOAT_EQ(plan.clears[0].color.r, 40.0f / 255.0f);
  EXPECT_FLOAT_EQ(plan.clears[0].color.g, 80.0f / 255.0f);
  EXPECT_FLOAT_EQ(plan.clears[0].color.b, 200.0f / 255.0f);
  EXPECT_FLOAT_EQ(plan.clears[0].color.a, 1.0f);
  EXPECT_EQ(drawnIndices(plan), std::uint32_t(indices - 6));

  // Asked for triangles only, it is drawn.
  const HudDrawPlan drawn = planOf(oneRectangle, false, &indices);
  EXPECT_TRUE(drawn.clears.empty());
  EXPECT_EQ(drawnIndices(drawn), std::uint32_t(indices));
}

TEST(HudDrawPlan, TranslucentRoundedAndTexturedShapesAreDrawn) {
  int indices = 0;
  const HudDrawPlan plan = planOf(
      [](ImDrawList& l) {
        l.AddRectFilled({10, 10}, {50, 30}, IM_COL32(40, 80, 200, 254));  // translucent
        l.AddRectFilled({60, 10}, {100, 30}, kOpaqueBlue, 6.0f);          // rounded
        l.AddText({10, 40}, IM_COL32_WHITE, "text");                      // the font atlas
        l.AddTriangleFilled({10, 60}, {50, 60}, {10, 90}, kOpaqueBlue);   // not a rectangle
      },
      true, &indices);
  EXPECT_TRUE(plan.clears.empty());
  EXPECT_EQ(drawnIndices(plan), std::uint32_t(indices));
}

TEST(HudDrawPlan, ARectangleOverSomethingDrawnBeforeItStaysDrawnAfterIt) {
  int indices = 0;
  const HudDrawPlan plan = planOf(
      [](ImDrawList& l) {
        l.AddText({12, 12}, IM_COL32_WHITE, "under");
        l.AddRectFilled({10, 10}, {80, 30}, kOpaqueBlue);    // hides the text: drawn
        l.AddRectFilled({10, 100}, {80, 120}, kOpaqueBlue);  // beside it: cleared
        l.AddText({12, 102}, IM_COL32_WHITE, "over");        // over the cleared one
      },
      true, &indices);
  ASSERT_EQ(plan.clears.size(), 1u);
  EXPECT_EQ(plan.clears[0].rect.offset.y, 100);
  EXPECT_EQ(drawnIndices(plan), std::uint32_t(indices - 6));
  // The draws keep ImGui's order: the hiding rectangle after the text under it, in one run.
  ASSERT_FALSE(plan.draws.empty());
  EXPECT_EQ(plan.draws.front().firstIndex, 0u);
}

TEST(HudDrawPlan, AClearStaysInsideItsClipRectangleAndTheDisplay) {
  const HudDrawPlan plan = planOf([](ImDrawList& l) {
    l.PushClipRect({20, 20}, {40, 40});
    l.AddRectFilled({0, 0}, {100, 100}, kOpaqueBlue);
    l.PopClipRect();
    l.AddRectFilled({300, 170}, {400, 250}, kOpaqueBlue);  // past the display's corner
    l.PushClipRect({200, 0}, {210, 10});
    l.AddRectFilled({0, 50}, {10, 60}, kOpaqueBlue);  // wholly clipped: neither cleared nor drawn
    l.PopClipRect();
  });
  ASSERT_EQ(plan.clears.size(), 2u);
  EXPECT_EQ(plan.clears[0].rect.offset.x, 20);
  EXPECT_EQ(plan.clears[0].rect.offset.y, 20);
  EXPECT_EQ(plan.clears[0].rect.extent.width, 20u);
  EXPECT_EQ(plan.clears[0].rect.extent.height, 20u);
  EXPECT_EQ(plan.clears[1].rect.offset.x, 300);
  EXPECT_EQ(plan.clears[1].rect.offset.y, 170);
  EXPECT_EQ(plan.clears[1].rect.extent.width, 20u);
  EXPECT_EQ(plan.clears[1].rect.extent.height, 10u);
  EXPECT_EQ(drawnIndices(plan), 0u);
}

}  // namespace
