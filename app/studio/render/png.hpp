#pragma once
/// \file png.hpp
/// The one way the studio writes pictures: the default framebuffer read back and written as a PNG
/// through the atomic writer (screenshots, plot exports, `pagor sweep --plot`).

#include <string>
#include <vector>

#include "render/gl.hpp"

namespace pagor::studio {

/// The lower-left `width` x `height` pixels of the default framebuffer as RGBA, rows top-down
/// (as a PNG stores them), alpha opaque. Needs a current GL context; call after the frame is drawn
/// (and glFinish'ed).
std::vector<unsigned char> read_framebuffer_rgba(const Gl& gl, int width, int height);

/// Encodes RGBA pixels (rows top-down) as PNG and writes them atomically: a failed write keeps
/// the previous file. Throws pagor::InputError naming `path`.
void write_png(const std::string& path, const std::vector<unsigned char>& rgba, int width,
               int height);

/// The lower-left `width` x `height` pixels of the default framebuffer written to `path` as PNG.
/// Throws pagor::InputError naming `path`.
void write_framebuffer_png(const Gl& gl, const std::string& path, int width, int height);

}  // namespace pagor::studio
