#include "render/ui_font.hpp"

#include "render/resources.hpp"

namespace pagor::studio {

const ImWchar* ui_glyph_ranges() {
  static const ImWchar ranges[] = {0x0020, 0x00FF,  // Latin-1: ASCII and the degree sign
                                   0x0370, 0x03FF,  // Greek: epsilon, mu, sigma, Delta, Sigma
                                   0x2190, 0x21FF,  // arrows
                                   0};
  return ranges;
}

bool load_ui_font(float size, std::string& error) {
  const Resource font = resource("ui_font.ttf");
  ImFontConfig cfg;
  cfg.FontDataOwnedByAtlas = false;
  if (!ImGui::GetIO().Fonts->AddFontFromMemoryTTF(const_cast<unsigned char*>(font.data),
                                                  static_cast<int>(font.size), size, &cfg,
                                                  ui_glyph_ranges())) {
    error = "cannot load the embedded UI font";
    return false;
  }
  return true;
}

}  // namespace pagor::studio
