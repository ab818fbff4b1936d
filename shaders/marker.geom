#version 330 core
// A square one pixel larger than the disc on every side, so the fragment
// shader has room to fade the edge smoothly.
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

uniform vec2 u_viewport_size;

in MarkerData {
    vec4 fill;
    vec4 outline;
    vec2 size;
} v_in[];

out vec2 g_offset_px;  // from the marker centre
flat out vec4 g_fill;
flat out vec4 g_outline;
flat out vec2 g_size;

void main() {
    vec4 centre = gl_in[0].gl_Position;
    if (centre.w < 1e-5) return;
    float extent = v_in[0].size.x + 1.0;
    for (int i = 0; i < 4; ++i) {
        vec2 corner = vec2((i & 1) == 0 ? -1.0 : 1.0, (i & 2) == 0 ? -1.0 : 1.0) * extent;
        gl_Position = centre + vec4(corner / (0.5 * u_viewport_size) * centre.w, 0.0, 0.0);
        g_offset_px = corner;
        g_fill = v_in[0].fill;
        g_outline = v_in[0].outline;
        g_size = v_in[0].size;
        EmitVertex();
    }
    EndPrimitive();
}
