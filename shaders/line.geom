#version 330 core
// One segment (p1 -> p2) with its neighbours p0 and p3 becomes a quad of the
// requested width in pixels. Both ends are mitred along the bisector of the
// joint, so consecutive quads share an edge exactly: no gaps, no overlaps (an
// overlap would blend twice and darken translucent lines at every joint).
layout(lines_adjacency) in;
layout(triangle_strip, max_vertices = 4) out;

uniform vec2 u_viewport_size;  // pixels

in VertexData {
    vec4 colour;
    float width;
} v_in[];

out vec4 g_colour;
out float g_across_px;       // signed distance from the centre line, pixels
flat out float g_half_width; // pixels

const float min_w = 1e-5;

vec2 to_pixels(vec4 clip) { return clip.xy / clip.w * 0.5 * u_viewport_size; }

// Unit offset direction at joint `p` between incoming `d_in` and outgoing
// `d_out` (unit, or zero at an end), scaled so the quad keeps its width;
// the scale is limited so a hairpin turn does not shoot a spike.
vec2 miter(vec2 d_in, vec2 d_out, vec2 normal) {
    vec2 tangent = d_in + d_out;
    if (dot(tangent, tangent) < 1e-6) return normal;
    tangent = normalize(tangent);
    vec2 m = vec2(-tangent.y, tangent.x);
    return m / max(dot(m, normal), 0.5);
}

// The quad reaches one pixel beyond the line on each side; line.frag fades
// the edge over that pixel (anti-aliasing that works without multisampling).
const float feather = 1.0;

void emit(vec4 clip, vec2 miter_px, float half_width, float side, vec4 colour) {
    float reach = half_width + feather;
    gl_Position = clip + vec4(side * miter_px * reach / (0.5 * u_viewport_size) * clip.w, 0.0, 0.0);
    g_colour = colour;
    g_across_px = side * reach;
    g_half_width = half_width;
    EmitVertex();
}

void main() {
    vec4 c0 = gl_in[0].gl_Position, c1 = gl_in[1].gl_Position;
    vec4 c2 = gl_in[2].gl_Position, c3 = gl_in[3].gl_Position;
    if (c1.w < min_w || c2.w < min_w) return;  // behind the camera
    vec2 p1 = to_pixels(c1), p2 = to_pixels(c2);
    vec2 d = p2 - p1;
    float len = length(d);
    if (len < 1e-4) return;
    d /= len;
    vec2 normal = vec2(-d.y, d.x);

    vec2 d_in = vec2(0.0), d_out = vec2(0.0);
    if (c0.w >= min_w) {
        vec2 e = p1 - to_pixels(c0);
        if (dot(e, e) > 1e-8) d_in = normalize(e);
    }
    if (c3.w >= min_w) {
        vec2 e = to_pixels(c3) - p2;
        if (dot(e, e) > 1e-8) d_out = normalize(e);
    }
    vec2 m1 = miter(d_in, d, normal);
    vec2 m2 = miter(d, d_out, normal);

    // Lines thinner than a pixel are drawn one pixel wide and fainter, which
    // reads the same but survives multisampling without breaking up.
    vec4 colour1 = v_in[1].colour, colour2 = v_in[2].colour;
    float w1 = v_in[1].width, w2 = v_in[2].width;
    if (w1 < 1.0) { colour1.a *= w1; w1 = 1.0; }
    if (w2 < 1.0) { colour2.a *= w2; w2 = 1.0; }

    // The flat half width is the provoking (last) vertex's; widths rarely differ
    // along a segment, and when they do the edge fade stays within a pixel.
    emit(c1, m1, 0.5 * w1, 1.0, colour1);
    emit(c1, m1, 0.5 * w1, -1.0, colour1);
    emit(c2, m2, 0.5 * w2, 1.0, colour2);
    emit(c2, m2, 0.5 * w2, -1.0, colour2);
    EndPrimitive();
}
