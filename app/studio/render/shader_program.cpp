#include "render/shader_program.hpp"

#include <vector>

#include "render/resources.hpp"

namespace pagor::studio {
namespace {

// The info log of a shader or program, through the matching pair of GL getters.
template <class GetIv, class GetLog>
std::string info_log(GLuint object, GetIv get_iv, GetLog get_log) {
  GLint length = 0;
  get_iv(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  get_log(object, static_cast<GLsizei>(log.size()), nullptr, log.data());
  return log.data();
}

GLuint compile(const Gl& gl, GLenum kind, const std::string& name, std::string& error) {
  const std::string source = resource(name).text();
  const char* text = source.c_str();
  const GLuint shader = gl.CreateShader(kind);
  gl.ShaderSource(shader, 1, &text, nullptr);
  gl.CompileShader(shader);
  GLint ok = 0;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    error = "shader " + name +
            " does not compile: " + info_log(shader, gl.GetShaderiv, gl.GetShaderInfoLog);
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
    error = "program " + vertex_name + " + " + fragment_name +
            " does not link: " + info_log(program, gl.GetProgramiv, gl.GetProgramInfoLog);
    gl.DeleteProgram(program);
    return 0;
  }
  return program;
}

}  // namespace pagor::studio
