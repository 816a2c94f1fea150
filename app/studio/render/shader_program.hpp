#pragma once
/// \file shader_program.hpp
/// Compiles and links a vertex/fragment pair from the embedded shaders.

#include <string>

#include "render/gl.hpp"

namespace pagor::studio {

/// Builds a program from two embedded shader names. Returns 0 and fills `error` (with the
/// compiler's log) on failure.
GLuint build_program(const Gl& gl, const std::string& vertex_name, const std::string& fragment_name,
                     std::string& error);

}  // namespace pagor::studio
