#pragma once
// How the HUD's Dear ImGui draw data is recorded. Its opaque, axis-aligned, untextured
// rectangles (window, title and widget backgrounds: most of the settings panel's pixels) become
// attachment clears; everything else (text, check marks, translucent shapes) is drawn as
// ImGui's triangles, in ImGui's order.
//
// Why: on a CPU device (lavapipe) an alpha-blended pixel costs ~8 ns and a cleared one a small
// fraction of that, and the panel's backgrounds cover ~80k pixels at 640x360
// (docs/hud_cost.md). The clears are recorded before every draw, because lavapipe finishes
// the draws recorded so far before each clear that follows them; so a rectangle becomes a
// clear only where no triangle before it overlaps it, and the image is the one ImGui's
// triangles would make.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

struct ImDrawData;
struct ImGuiStyle;
struct ImVec2;

namespace sample {

struct HudClear {
  VkRect2D rect{};    // px: the pixels whose centres the rectangle's two triangles cover
  glm::vec4 color{};  // the vertices' colour (UNORM8 / 255), alpha 1
};

struct HudDraw {
  VkRect2D scissor{};            // px, inside the display
  std::uint32_t firstIndex = 0;  // into the draw lists' index buffers laid end to end
  std::uint32_t indexCount = 0;
  std::int32_t vertexOffset = 0;  // into the vertex buffers laid end to end
};

struct HudDrawPlan {
  std::vector<HudClear> clears;  // recorded first, in this order
  std::vector<HudDraw> draws;    // then these, in this order
};

// Opaque windows, and each translucent colour drawn inside one replaced by what it blends to
// over the window's colour: the same look inside, and backgrounds that can be cleared. Colours
// drawn over the scene itself (dimming, highlights) stay. Lines are not anti-aliased (borders
// and separators become rectangles too).
void flattenOverWindows(ImGuiStyle& style);

// `whiteUv`: the font atlas's white pixel (ImFontAtlas::TexUvWhitePixel): a vertex there is
// untextured. `clearRectangles` false: every triangle is drawn (the reference the clears match).
HudDrawPlan planHudDraws(const ImDrawData& data, const ImVec2& whiteUv, VkExtent2D display,
                         bool clearRectangles = true);

// The pixel columns [first, end) whose centres (x + 0.5) lie in [from, to) under the top-left
// fill rule (a centre on the left edge is in, on the right edge out); rows likewise.
struct PixelSpan {
  std::int32_t first = 0;
  std::int32_t end = 0;
};
PixelSpan pixelsCoveredBetween(float from, float to);

}  // namespace sample
