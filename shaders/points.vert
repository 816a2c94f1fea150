#version 330 core
// Points and lines of the 3D view: clouds, landmarks and correspondences.
uniform mat4 u_mvp;
uniform float u_point_size;
uniform int u_use_uniform_color;
uniform vec4 u_color;
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_color;
out vec4 v_color;

void main() {
  gl_Position = u_mvp * vec4(a_position, 1.0);
  gl_PointSize = u_point_size;
  v_color = u_use_uniform_color != 0 ? u_color : a_color;
}
