#include "render/gl.hpp"

#include <cstdio>

namespace pagor::studio {

bool Gl::load(GetProcAddress get, std::string& error) {
#define PAGOR_GL_LOAD(type, name)                           \
  name = reinterpret_cast<type>(get("gl" #name));           \
  if (!name) {                                              \
    error = "OpenGL function gl" #name " is not available"; \
    return false;                                           \
  }
  PAGOR_GL_FUNCTIONS(PAGOR_GL_LOAD)
#undef PAGOR_GL_LOAD
  const auto* version = reinterpret_cast<const char*>(GetString(GL_VERSION));
  int major = 0, minor = 0;
  if (!version || std::sscanf(version, "%d.%d", &major, &minor) != 2) {
    error = "the OpenGL context reports no version";
    return false;
  }
  if (major < 3 || (major == 3 && minor < 3)) {
    error = std::string("OpenGL 3.3 core is needed, the context has ") + version;
    return false;
  }
  return true;
}

std::string Gl::describe() const {
  const auto* version = reinterpret_cast<const char*>(GetString(GL_VERSION));
  const auto* renderer = reinterpret_cast<const char*>(GetString(GL_RENDERER));
  return std::string("OpenGL ") + (version ? version : "?") + ", " + (renderer ? renderer : "?");
}

}  // namespace pagor::studio
