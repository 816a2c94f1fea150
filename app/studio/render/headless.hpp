#pragma once
/// \file headless.hpp
/// An offscreen OpenGL 3.3 core context through OSMesa, opened at run time (so the window build
/// never loads OSMesa's gl* symbols beside GLX's). Used by `--headless` and the driven-UI tests.

#include <vector>

namespace pagor::studio {

/// Smallest and largest window or image side the studio accepts [px].
constexpr int kMinWidth = 320, kMinHeight = 240, kMaxSide = 8192;

class HeadlessContext {
 public:
  /// Creates the context with a `width` x `height` RGBA colour buffer and makes it current.
  /// Throws pagor::Error when OSMesa is missing or the size is outside the accepted range.
  HeadlessContext(int width, int height);
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  /// Reallocates the colour buffer (the default framebuffer) at a new size.
  void resize(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }
  /// GL function lookup for Gl::load.
  static void* proc(const char* name);

 private:
  void* ctx_ = nullptr;
  std::vector<unsigned char> buffer_;
  int width_ = 0, height_ = 0;
};

}  // namespace pagor::studio
