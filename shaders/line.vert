#version 330 core
// Thick polylines: vertices go to clip space here; line.geom widens each
// segment into a screen-space quad.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_colour;
layout(location = 2) in float a_width;  // pixels

uniform mat4 u_view_projection;

out VertexData {
    vec4 colour;
    float width;
} v_out;

void main() {
    gl_Position = u_view_projection * vec4(a_position, 1.0);
    v_out.colour = a_colour;
    v_out.width = a_width;
}
