#pragma once
/// \file resources.hpp
/// Files embedded into the binary at build time (shaders/, assets/, the UI font), so the studio
/// runs from any working directory.

#include <cstddef>
#include <string>

namespace pagor::studio {

/// Bytes of an embedded file.
struct Resource {
  const unsigned char* data = nullptr;
  std::size_t size = 0;
  std::string text() const { return std::string(reinterpret_cast<const char*>(data), size); }
};

/// An embedded file by name: "points.vert", "points.frag", "imgui.vert", "imgui.frag",
/// "class_colors.json", "ui_font.ttf". Throws std::out_of_range for an unknown name.
Resource resource(const std::string& name);

}  // namespace pagor::studio
