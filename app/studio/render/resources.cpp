#include "render/resources.hpp"

#include <stdexcept>

// Each file is included by the assembler (.incbin), which keeps the build fast and the binary
// exact; paths come from CMake as PAGOR_RES_<name> definitions.
#define PAGOR_STR2(x) #x
#define PAGOR_STR(x) PAGOR_STR2(x)
#define PAGOR_EMBED(sym, path)                      \
  __asm__(                                          \
      ".section .rodata\n"                          \
      ".balign 16\n"                                \
      ".global pagor_res_" #sym                     \
      "\n"                                          \
      "pagor_res_" #sym                             \
      ":\n"                                         \
      ".incbin \"" path                             \
      "\"\n"                                        \
      ".global pagor_res_" #sym                     \
      "_end\n"                                      \
      "pagor_res_" #sym                             \
      "_end:\n"                                     \
      ".byte 0\n"                                   \
      ".previous\n");                               \
  extern "C" const unsigned char pagor_res_##sym[]; \
  extern "C" const unsigned char pagor_res_##sym##_end[];

PAGOR_EMBED(points_vert, PAGOR_STR(PAGOR_RES_points_vert))
PAGOR_EMBED(points_frag, PAGOR_STR(PAGOR_RES_points_frag))
PAGOR_EMBED(imgui_vert, PAGOR_STR(PAGOR_RES_imgui_vert))
PAGOR_EMBED(imgui_frag, PAGOR_STR(PAGOR_RES_imgui_frag))
PAGOR_EMBED(class_colors, PAGOR_STR(PAGOR_RES_class_colors))
PAGOR_EMBED(ui_font, PAGOR_STR(PAGOR_RES_ui_font))

namespace pagor::studio {

Resource resource(const std::string& name) {
  const auto make = [](const unsigned char* b, const unsigned char* e) {
    return Resource{b, static_cast<std::size_t>(e - b)};
  };
  if (name == "points.vert") return make(pagor_res_points_vert, pagor_res_points_vert_end);
  if (name == "points.frag") return make(pagor_res_points_frag, pagor_res_points_frag_end);
  if (name == "imgui.vert") return make(pagor_res_imgui_vert, pagor_res_imgui_vert_end);
  if (name == "imgui.frag") return make(pagor_res_imgui_frag, pagor_res_imgui_frag_end);
  if (name == "class_colors.json") return make(pagor_res_class_colors, pagor_res_class_colors_end);
  if (name == "ui_font.ttf") return make(pagor_res_ui_font, pagor_res_ui_font_end);
  throw std::out_of_range("no embedded resource '" + name + "'");
}

}  // namespace pagor::studio
