#version 330 core
// Disc with an outline ring; both edges fade over one pixel (analytic
// anti-aliasing, independent of the multisample count).
in vec2 g_offset_px;
flat in vec4 g_fill;
flat in vec4 g_outline;
flat in vec2 g_size;

uniform float u_min_alpha;  // fragments fainter than this are dropped (see Renderer::draw_3d)

out vec4 frag_colour;

void main() {
    float r = length(g_offset_px);
    float outer = clamp(g_size.x + 0.5 - r, 0.0, 1.0);
    float inner = g_size.y > 0.0 ? clamp(g_size.x - g_size.y + 0.5 - r, 0.0, 1.0) : 1.0;
    vec4 colour = mix(g_outline, g_fill, inner);
    colour.a *= outer;
    // Fully transparent corners must not write depth.
    if (colour.a < u_min_alpha) discard;
    frag_colour = colour;
}
