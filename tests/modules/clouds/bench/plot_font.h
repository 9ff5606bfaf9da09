#pragma once
// Text for the benchmark chart, rasterised from Dear ImGui's embedded default font
// (ProggyClean). Only ImGui's CPU font atlas is used: no context, no rendering backend.
#include <memory>
#include <string_view>

#include "plot_canvas.h"

struct ImFont;
struct ImFontAtlas;

namespace bench {

enum class TextSize {
  Label,  // 13 px: ticks, legend, point labels, axis titles
  Title,  // 26 px: exactly twice the font's design size, so the pixel font stays crisp
};

// Owns one font atlas holding both sizes. Building it takes a few milliseconds; renderPlot
// builds one per call, so calls share no font state.
class PlotFont {
 public:
  PlotFont();
  ~PlotFont();
  PlotFont(const PlotFont&) = delete;
  PlotFont& operator=(const PlotFont&) = delete;

  int lineHeightPx(TextSize size) const;
  int textWidthPx(TextSize size, std::string_view utf8) const;

  // Draws `utf8` with the top of its line box at `topPx`, reading left to right from `leftPx`.
  void draw(Canvas& canvas, TextSize size, int leftPx, int topPx, std::string_view utf8,
            Rgb colour) const;
  // Draws `utf8` rotated a quarter turn anticlockwise (reading bottom to top, as a y-axis
  // title): the text starts at `bottomPx` and the top of its line box is at `leftPx`.
  void drawUpward(Canvas& canvas, TextSize size, int leftPx, int bottomPx, std::string_view utf8,
                  Rgb colour) const;

 private:
  // Visits each glyph of `utf8` with its pen position along the baseline direction.
  template <typename GlyphFn>
  void forEachGlyph(TextSize size, std::string_view utf8, GlyphFn visit) const;
  // Calls plot(alongPx, acrossPx, coverage) for every inked texel of the text, in text space:
  // `along` runs with the reading direction, `across` down from the top of the line box.
  template <typename TexelFn>
  void drawGlyphs(TextSize size, std::string_view utf8, TexelFn plot) const;
  const ImFont& font(TextSize size) const;

  std::unique_ptr<ImFontAtlas> atlas_;
  ImFont* labelFont_ = nullptr;
  ImFont* titleFont_ = nullptr;
  const unsigned char* alpha_ = nullptr;  // the atlas texture, one coverage byte per texel
  int atlasWidth_ = 0;
  int atlasHeight_ = 0;
};

}  // namespace bench
