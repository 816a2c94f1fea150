#include "render/headless.hpp"

#include <dlfcn.h>
#include "render/gl.hpp"

#include <string>

#include "pagor/errors.hpp"

namespace pagor::studio {
namespace {

constexpr int kOsmesaFormat = 0x22;       // OSMESA_FORMAT
constexpr int kOsmesaRgba = 0x1908;       // OSMESA_RGBA (GL_RGBA)
constexpr int kOsmesaDepthBits = 0x30;    // OSMESA_DEPTH_BITS
constexpr int kOsmesaProfile = 0x33;      // OSMESA_PROFILE
constexpr int kOsmesaCoreProfile = 0x34;  // OSMESA_CORE_PROFILE
constexpr int kOsmesaMajor = 0x36;        // OSMESA_CONTEXT_MAJOR_VERSION
constexpr int kOsmesaMinor = 0x37;        // OSMESA_CONTEXT_MINOR_VERSION

struct OsMesa {
  void* lib = nullptr;
  void* (*create)(const int*, void*) = nullptr;
  unsigned char (*make_current)(void*, void*, unsigned int, int, int) = nullptr;
  void (*destroy)(void*) = nullptr;
  void* (*get_proc)(const char*) = nullptr;
};

const OsMesa& osmesa() {
  static const OsMesa lib = [] {
    OsMesa m;
    m.lib = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
    if (!m.lib) throw Error(std::string("cannot load OSMesa (install libosmesa6): ") + dlerror());
    m.create = reinterpret_cast<decltype(m.create)>(dlsym(m.lib, "OSMesaCreateContextAttribs"));
    m.make_current = reinterpret_cast<decltype(m.make_current)>(dlsym(m.lib, "OSMesaMakeCurrent"));
    m.destroy = reinterpret_cast<decltype(m.destroy)>(dlsym(m.lib, "OSMesaDestroyContext"));
    m.get_proc = reinterpret_cast<decltype(m.get_proc)>(dlsym(m.lib, "OSMesaGetProcAddress"));
    if (!m.create || !m.make_current || !m.destroy || !m.get_proc)
      throw Error("libOSMesa.so.8 lacks the OSMesa 11.2 context API");
    return m;
  }();
  return lib;
}

void check_size(int width, int height) {
  if (width < kMinWidth || height < kMinHeight || width > kMaxSide || height > kMaxSide)
    throw Error("image size " + std::to_string(width) + "x" + std::to_string(height) +
                " is outside " + std::to_string(kMinWidth) + "x" + std::to_string(kMinHeight) +
                " .. " + std::to_string(kMaxSide) + "x" + std::to_string(kMaxSide));
}

}  // namespace

HeadlessContext::HeadlessContext(int width, int height) {
  check_size(width, height);
  const OsMesa& m = osmesa();
  const int attribs[] = {kOsmesaFormat,
                         kOsmesaRgba,
                         kOsmesaDepthBits,
                         24,
                         kOsmesaProfile,
                         kOsmesaCoreProfile,
                         kOsmesaMajor,
                         3,
                         kOsmesaMinor,
                         3,
                         0};
  ctx_ = m.create(attribs, nullptr);
  if (!ctx_) throw Error("OSMesa could not create an OpenGL 3.3 core context");
  resize(width, height);
}

HeadlessContext::~HeadlessContext() {
  if (ctx_) osmesa().destroy(ctx_);
}

void HeadlessContext::resize(int width, int height) {
  check_size(width, height);
  buffer_.assign(static_cast<std::size_t>(width) * height * 4, 0);
  if (!osmesa().make_current(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, width, height))
    throw Error("OSMesaMakeCurrent failed");
  width_ = width;
  height_ = height;
}

void* HeadlessContext::proc(const char* name) {
  return osmesa().get_proc(name);
}

}  // namespace pagor::studio
