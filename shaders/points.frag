#version 330 core
// Round points when asked (landmarks), square otherwise (dense clouds, cheaper).
uniform int u_round;
in vec4 v_color;
out vec4 frag_color;

void main() {
  if (u_round != 0) {
    vec2 c = gl_PointCoord * 2.0 - 1.0;
    float r2 = dot(c, c);
    if (r2 > 1.0) discard;
    // A dark rim makes overlapping landmarks readable.
    frag_color = r2 > 0.6 ? vec4(v_color.rgb * 0.35, v_color.a) : v_color;
  } else {
    frag_color = v_color;
  }
}
