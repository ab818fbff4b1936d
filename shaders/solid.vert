#version 330 core
// Unlit filled triangles with per-vertex colour (panel backgrounds, fills).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_colour;

uniform mat4 u_view_projection;

out vec4 v_colour;

void main() {
    gl_Position = u_view_projection * vec4(a_position, 1.0);
    v_colour = a_colour;
}
