#version 330 core
// Coverage of the line across its width, faded over one pixel at each edge.
in vec4 g_colour;
in float g_across_px;
flat in float g_half_width;

uniform float u_min_alpha;  // fragments fainter than this are dropped (see Renderer::draw_3d)

out vec4 frag_colour;

void main() {
    float coverage = clamp(g_half_width + 0.5 - abs(g_across_px), 0.0, 1.0);
    float alpha = g_colour.a * coverage;
    // Nearly transparent fringes must not write depth over what comes later.
    if (alpha < u_min_alpha) discard;
    frag_colour = vec4(g_colour.rgb, alpha);
}
