// A tiny built-in 5x7 bitmap font for the legends (digits, capitals, a few signs), so that
// pictures can carry their numeric scale without a font library. Internal to tspline_render.

#ifndef TSPLINE_RENDER_FONT_H
#define TSPLINE_RENDER_FONT_H

#include "render.h"

#include <string>

namespace tspline::render::internal {

constexpr int glyph_width = 5, glyph_height = 7, glyph_advance = 6;

// Width and height in pixels of `text` drawn at integer `scale`.
int text_width(const std::string& text, int scale);
inline int text_height(int scale) {
  return glyph_height * scale;
}

// Draws `text` with its top-left corner at (x, y); lowercase letters other than 'e' are drawn
// as capitals, unknown characters as blanks. Pixels outside the image are clipped.
void draw_text(Image& image, int x, int y, const std::string& text, int scale, Rgb colour);

} // namespace tspline::render::internal

#endif // TSPLINE_RENDER_FONT_H
