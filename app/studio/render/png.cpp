#include "render/png.hpp"

#include <stb/stb_image_write.h>

#include <algorithm>

#include "pagor/errors.hpp"
#include "pagor/io/atomic_file.hpp"

namespace pagor::studio {
namespace {

void append_bytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<std::size_t>(size));
}

}  // namespace

std::vector<unsigned char> read_framebuffer_rgba(const Gl& gl, int width, int height) {
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * height * 4);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  // GL rows go bottom-up; PNG rows top-down. Opaque alpha.
  std::vector<unsigned char> rgba(pixels.size());
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  for (int y = 0; y < height; ++y)
    std::copy_n(pixels.data() + static_cast<std::size_t>(height - 1 - y) * row, row,
                rgba.data() + y * row);
  for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
  return rgba;
}

void write_png(const std::string& path, const std::vector<unsigned char>& rgba, int width,
               int height) {
  // Encoded in memory, then written atomically.
  std::string png;
  if (!stbi_write_png_to_func(append_bytes, &png, width, height, 4, rgba.data(), width * 4))
    throw InputError(path + ": cannot encode the PNG");
  write_file_atomic(path, png);
}

void write_framebuffer_png(const Gl& gl, const std::string& path, int width, int height) {
  write_png(path, read_framebuffer_rgba(gl, width, height), width, height);
}

}  // namespace pagor::studio
