#include "shader_program.hpp"

#include <vector>

#include "resources.hpp"

namespace pagor::studio {
namespace {

GLuint compile(const Gl& gl, GLenum kind, const std::string& name, std::string& error) {
  const std::string source = resource(name).text();
  const char* text = source.c_str();
  const GLuint shader = gl.CreateShader(kind);
  gl.ShaderSource(shader, 1, &text, nullptr);
  gl.CompileShader(shader);
  GLint ok = 0;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    gl.GetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    error = "shader " + name + " does not compile: " + log.data();
    gl.DeleteShader(shader);
    return 0;
  }
  return shader;
}

}  // namespace

GLuint build_program(const Gl& gl, const std::string& vertex_name, const std::string& fragment_name,
                     std::string& error) {
  const GLuint vs = compile(gl, GL_VERTEX_SHADER, vertex_name, error);
  if (!vs) return 0;
  const GLuint fs = compile(gl, GL_FRAGMENT_SHADER, fragment_name, error);
  if (!fs) {
    gl.DeleteShader(vs);
    return 0;
  }
  const GLuint program = gl.CreateProgram();
  gl.AttachShader(program, vs);
  gl.AttachShader(program, fs);
  gl.LinkProgram(program);
  gl.DeleteShader(vs);
  gl.DeleteShader(fs);
  GLint ok = 0;
  gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    gl.GetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    gl.GetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
    error = "program " + vertex_name + " + " + fragment_name + " does not link: " + log.data();
    gl.DeleteProgram(program);
    return 0;
  }
  return program;
}

}  // namespace pagor::studio
