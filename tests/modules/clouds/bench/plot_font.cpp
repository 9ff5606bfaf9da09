#include "plot_font.h"

#include <imgui.h>
#include <imgui_internal.h>  // ImTextCharFromUtf8

#include <cmath>

namespace bench {

namespace {

constexpr float kDesignSizePx = 13.0f;  // ProggyClean is a pixel font drawn on a 13 px grid

ImFont* addDefaultFont(ImFontAtlas& atlas, float sizePx) {
  // AddFontDefault only picks these pixel-font settings when given no config: one texel per
  // pixel and whole-pixel advances, so glyphs can be copied texel for pixel without resampling.
  ImFontConfig config;
  config.SizePixels = sizePx;
  config.OversampleH = 1;
  config.OversampleV = 1;
  config.PixelSnapH = true;
  return atlas.AddFontDefault(&config);
}

}  // namespace

PlotFont::PlotFont() : atlas_(std::make_unique<ImFontAtlas>()) {
  labelFont_ = addDefaultFont(*atlas_, kDesignSizePx);
  titleFont_ = addDefaultFont(*atlas_, 2.0f * kDesignSizePx);
  unsigned char* pixels = nullptr;
  atlas_->GetTexDataAsAlpha8(&pixels, &atlasWidth_, &atlasHeight_);
  alpha_ = pixels;
}

PlotFont::~PlotFont() = default;

const ImFont& PlotFont::font(TextSize size) const {
  return size == TextSize::Title ? *titleFont_ : *labelFont_;
}

int PlotFont::lineHeightPx(TextSize size) const {
  return static_cast<int>(std::lround(font(size).FontSize));
}

template <typename GlyphFn>
void PlotFont::forEachGlyph(TextSize size, std::string_view utf8, GlyphFn visit) const {
  const ImFont& face = font(size);
  const char* cursor = utf8.data();
  const char* end = utf8.data() + utf8.size();
  float penPx = 0.0f;
  while (cursor < end) {
    unsigned int codepoint = 0;
    // Always consumes at least one byte, and maps malformed sequences to U+FFFD.
    cursor += ImTextCharFromUtf8(&codepoint, cursor, end);
    const ImFontGlyph* glyph = face.FindGlyph(static_cast<ImWchar>(codepoint));
    if (glyph == nullptr) continue;
    visit(*glyph, penPx);
    penPx += glyph->AdvanceX;
  }
}

int PlotFont::textWidthPx(TextSize size, std::string_view utf8) const {
  float widthPx = 0.0f;
  forEachGlyph(size, utf8,
               [&](const ImFontGlyph& glyph, float penPx) { widthPx = penPx + glyph.AdvanceX; });
  return static_cast<int>(std::lround(widthPx));
}

template <typename TexelFn>
void PlotFont::drawGlyphs(TextSize size, std::string_view utf8, TexelFn plot) const {
  forEachGlyph(size, utf8, [&](const ImFontGlyph& glyph, float penPx) {
    if (!glyph.Visible) return;
    // With one texel per pixel the glyph's quad and its texel rectangle have the same size.
    const int texelLeft = static_cast<int>(std::lround(glyph.U0 * float(atlasWidth_)));
    const int texelTop = static_cast<int>(std::lround(glyph.V0 * float(atlasHeight_)));
    const int texelRight = static_cast<int>(std::lround(glyph.U1 * float(atlasWidth_)));
    const int texelBottom = static_cast<int>(std::lround(glyph.V1 * float(atlasHeight_)));
    const int alongOrigin = static_cast<int>(std::lround(penPx + glyph.X0));
    const int acrossOrigin = static_cast<int>(std::lround(glyph.Y0));
    for (int v = texelTop; v < texelBottom; ++v) {
      for (int u = texelLeft; u < texelRight; ++u) {
        const unsigned char texel = alpha_[v * atlasWidth_ + u];
        if (texel == 0) continue;
        plot(alongOrigin + (u - texelLeft), acrossOrigin + (v - texelTop), float(texel) / 255.0f);
      }
    }
  });
}

void PlotFont::draw(Canvas& canvas, TextSize size, int leftPx, int topPx, std::string_view utf8,
                    Rgb colour) const {
  drawGlyphs(size, utf8, [&](int alongPx, int acrossPx, float coverage) {
    canvas.blend(leftPx + alongPx, topPx + acrossPx, colour, coverage);
  });
}

void PlotFont::drawUpward(Canvas& canvas, TextSize size, int leftPx, int bottomPx,
                          std::string_view utf8, Rgb colour) const {
  // A quarter turn anticlockwise: along the text is up the image, and down the line box (from
  // its top to its bottom) is right.
  drawGlyphs(size, utf8, [&](int alongPx, int acrossPx, float coverage) {
    canvas.blend(leftPx + acrossPx, bottomPx - alongPx, colour, coverage);
  });
}

}  // namespace bench
