#version 330 core
// Round markers: one point per marker, expanded to a square in marker.geom.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_fill;
layout(location = 2) in vec4 a_outline;
layout(location = 3) in vec2 a_size;  // x: radius, y: outline width, pixels

uniform mat4 u_view_projection;

out MarkerData {
    vec4 fill;
    vec4 outline;
    vec2 size;
} v_out;

void main() {
    gl_Position = u_view_projection * vec4(a_position, 1.0);
    v_out.fill = a_fill;
    v_out.outline = a_outline;
    v_out.size = a_size;
}
