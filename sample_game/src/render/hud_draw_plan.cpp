#include "render/hud_draw_plan.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace sample {
namespace {

struct PixelBox {
  std::int32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // [x0, x1) x [y0, y1)

  bool empty() const { return x1 <= x0 || y1 <= y0; }
  bool overlaps(const PixelBox& o) const {
    return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
  }
  PixelBox clippedTo(const PixelBox& o) const {
    return {std::max(x0, o.x0), std::max(y0, o.y0), std::min(x1, o.x1), std::min(y1, o.y1)};
  }
  VkRect2D rect() const { return {{x0, y0}, {std::uint32_t(x1 - x0), std::uint32_t(y1 - y0)}}; }
};

// The pixels a draw command may touch: its clip rectangle inside the display, as the recorder
// sets its scissor.
PixelBox scissorOf(const ImDrawCmd& command, VkExtent2D display) {
  const float x0 = std::max(command.ClipRect.x, 0.0f);
  const float y0 = std::max(command.ClipRect.y, 0.0f);
  const float x1 = std::min(command.ClipRect.z, float(display.width));
  const float y1 = std::min(command.ClipRect.w, float(display.height));
  return {std::int32_t(x0), std::int32_t(y0), std::int32_t(x1), std::int32_t(y1)};
}

// Every pixel a triangle might touch: those whose centres lie in its bounding box, edges
// included.
PixelBox boundsOf(const ImDrawVert& a, const ImDrawVert& b, const ImDrawVert& c) {
  const auto first = [](float from) { return std::int32_t(std::ceil(from - 0.5f)); };
  const auto end = [](float to) { return std::int32_t(std::floor(to - 0.5f)) + 1; };
  return {first(std::min({a.pos.x, b.pos.x, c.pos.x})),
          first(std::min({a.pos.y, b.pos.y, c.pos.y})), end(std::max({a.pos.x, b.pos.x, c.pos.x})),
          end(std::max({a.pos.y, b.pos.y, c.pos.y}))};
}

struct OpaqueRectangle {
  PixelBox pixels;
  glm::vec4 color;
};

// ImGui's rectangle (ImDrawList::PrimRect: corners a b c d, indices a b c a c d) when the six
// indices at `index` are one, untextured and opaque: its pixels and colour.
std::optional<OpaqueRectangle> opaqueRectangleAt(const ImDrawList& list, const ImDrawCmd& command,
                                                 int index, const ImVec2& whiteUv) {
  const ImDrawIdx* i = list.IdxBuffer.Data + index;
  if (i[3] != i[0] || i[4] != i[2]) return std::nullopt;
  const ImDrawVert* v = list.VtxBuffer.Data + command.VtxOffset;
  const std::array<const ImDrawVert*, 4> corners = {&v[i[0]], &v[i[1]], &v[i[2]], &v[i[5]]};
  for (const ImDrawVert* corner : corners) {
    if (corner->uv.x != whiteUv.x || corner->uv.y != whiteUv.y || corner->col != corners[0]->col) {
      return std::nullopt;
    }
  }
  if ((corners[0]->col >> IM_COL32_A_SHIFT & 0xFFu) != 0xFFu) return std::nullopt;
  // Axis-aligned: a and c opposite corners, b and d each sharing one coordinate with a.
  const ImVec2 a = corners[0]->pos, b = corners[1]->pos, c = corners[2]->pos, d = corners[3]->pos;
  const bool aligned = (b.x == c.x && b.y == a.y && d.x == a.x && d.y == c.y) ||
                       (b.x == a.x && b.y == c.y && d.x == c.x && d.y == a.y);
  if (!aligned) return std::nullopt;
  const PixelSpan columns = pixelsCoveredBetween(std::min(a.x, c.x), std::max(a.x, c.x));
  const PixelSpan rows = pixelsCoveredBetween(std::min(a.y, c.y), std::max(a.y, c.y));
  const ImU32 col = corners[0]->col;
  const auto channel = [col](int shift) { return float(col >> shift & 0xFFu) / 255.0f; };
  return OpaqueRectangle{PixelBox{columns.first, rows.first, columns.end, rows.end},
                         glm::vec4(channel(IM_COL32_R_SHIFT), channel(IM_COL32_G_SHIFT),
                                   channel(IM_COL32_B_SHIFT), 1.0f)};
}

}  // namespace

void flattenOverWindows(ImGuiStyle& style) {
  // Lines without anti-aliasing: a horizontal or vertical one (borders, separators) is then a
  // rectangle of whole pixels, cleared like the backgrounds.
  style.AntiAliasedLines = false;
  ImVec4& window = style.Colors[ImGuiCol_WindowBg];
  window.w = 1.0f;
  style.Colors[ImGuiCol_PopupBg].w = 1.0f;
  for (int i = 0; i < ImGuiCol_COUNT; ++i) {
    switch (i) {
      case ImGuiCol_ModalWindowDimBg:
      case ImGuiCol_NavWindowingDimBg:
      case ImGuiCol_NavWindowingHighlight:
      case ImGuiCol_DragDropTarget:
        continue;
      default:
        break;
    }
    ImVec4& c = style.Colors[i];
    c = ImVec4(c.x * c.w + window.x * (1.0f - c.w), c.y * c.w + window.y * (1.0f - c.w),
               c.z * c.w + window.z * (1.0f - c.w), 1.0f);
  }
}

PixelSpan pixelsCoveredBetween(float from, float to) {
  return {std::int32_t(std::ceil(from - 0.5f)), std::int32_t(std::ceil(to - 0.5f))};
}

HudDrawPlan planHudDraws(const ImDrawData& data, const ImVec2& whiteUv, VkExtent2D display,
                         bool clearRectangles) {
  HudDrawPlan plan;
  std::vector<PixelBox> drawn;  // what every triangle drawn so far may have touched
  std::uint32_t listFirstIndex = 0;
  std::int32_t listFirstVertex = 0;
  for (int l = 0; l < data.CmdListsCount; ++l) {
    const ImDrawList& list = *data.CmdLists[l];
    for (const ImDrawCmd& command : list.CmdBuffer) {
      const PixelBox scissor = scissorOf(command, display);
      if (scissor.empty() || command.UserCallback != nullptr) continue;
      const auto draw = [&](int first, int end) {  // indices into the list's buffer
        if (end <= first) return;
        plan.draws.push_back(HudDraw{scissor.rect(), listFirstIndex + std::uint32_t(first),
                                     std::uint32_t(end - first),
                                     listFirstVertex + std::int32_t(command.VtxOffset)});
      };
      const int begin = int(command.IdxOffset);
      const int end = begin + int(command.ElemCount);
      int runStart = begin;  // the triangles not yet turned into a draw
      for (int index = begin; index + 3 <= end;) {
        if (clearRectangles && index + 6 <= end) {
          if (auto rectangle = opaqueRectangleAt(list, command, index, whiteUv)) {
            const PixelBox pixels = rectangle->pixels.clippedTo(scissor);
            const bool hidesNothingDrawn = std::none_of(
                drawn.begin(), drawn.end(), [&](const PixelBox& b) { return b.overlaps(pixels); });
            if (hidesNothingDrawn) {
              draw(runStart, index);
              if (!pixels.empty()) plan.clears.push_back({pixels.rect(), rectangle->color});
              index += 6;
              runStart = index;
              continue;
            }
          }
        }
        const ImDrawIdx* i = list.IdxBuffer.Data + index;
        const ImDrawVert* v = list.VtxBuffer.Data + command.VtxOffset;
        drawn.push_back(boundsOf(v[i[0]], v[i[1]], v[i[2]]).clippedTo(scissor));
        index += 3;
      }
      draw(runStart, end);
    }
    listFirstIndex += std::uint32_t(list.IdxBuffer.Size);
    listFirstVertex += list.VtxBuffer.Size;
  }
  return plan;
}

}  // namespace sample
