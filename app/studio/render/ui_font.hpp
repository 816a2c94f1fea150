#pragma once
/// \file ui_font.hpp
/// The UI font (the embedded DejaVu Sans) and the one table of the glyphs it is loaded with, so
/// that the studio and the plot pictures (`pagor sweep --plot`) draw the same characters.

#include <imgui.h>

#include <string>

namespace pagor::studio {

/// Size of the UI font [px].
constexpr float kUiFontSize = 15.0f;

/// The glyphs the UI font is loaded with, as ImGui ranges (first, last code point; 0-terminated):
/// Latin-1 (the degree sign), Greek (epsilon, mu, sigma, Delta, Sigma) and arrows. Labels write
/// them as UTF-8 escapes ("\xce\xb5" epsilon, "\xce\xbc" mu, "\xc2\xb0" degree); a character
/// outside these ranges shows as '?'.
const ImWchar* ui_glyph_ranges();

/// Loads the embedded UI font into the current ImGui context at `size` [px] with the glyphs of
/// ui_glyph_ranges(). False with `error` on failure.
bool load_ui_font(float size, std::string& error);

}  // namespace pagor::studio
