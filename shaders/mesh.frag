#version 330 core
// Blinn-Phong with a key light, a weaker fill light from the other side and a
// sky/ground ambient term, computed in (nearly) linear light and written back
// as sRGB (the framebuffer is plain RGBA8 holding sRGB values). Gamma 2 stands
// in for the exact sRGB curve: llvmpipe runs this for every covered pixel on
// the CPU, and pow() per channel doubled the cost of a translucent sphere.
in vec3 v_position_view;
in vec3 v_normal_view;

uniform vec4 u_colour;          // sRGB + alpha
uniform float u_specular;
uniform float u_shininess;
uniform float u_rim;            // extra opacity towards the silhouette
uniform vec3 u_key_direction;   // view space, towards the light, unit length
uniform vec3 u_key_colour;
uniform vec3 u_fill_direction;
uniform vec3 u_fill_colour;
uniform vec3 u_sky_colour;      // ambient from above (view-space +y)
uniform vec3 u_ground_colour;   // ambient from below
uniform int u_lit;              // 0: the colour unlit, only the rim term

out vec4 frag_colour;

vec3 srgb_to_linear(vec3 c) { return c * c; }
vec3 linear_to_srgb(vec3 c) { return sqrt(clamp(c, 0.0, 1.0)); }

void main() {
    vec3 n = normalize(v_normal_view);
    if (u_lit == 0) {
        float grazing = 1.0 - abs(dot(n, normalize(-v_position_view)));
        frag_colour = vec4(u_colour.rgb, clamp(u_colour.a * (1.0 + u_rim * grazing * grazing), 0.0, 1.0));
        return;
    }
    // Back faces (seen through a translucent shell) are lit as the side we see.
    if (!gl_FrontFacing) n = -n;
    vec3 to_eye = normalize(-v_position_view);
    vec3 base = srgb_to_linear(u_colour.rgb);

    vec3 ambient = mix(u_ground_colour, u_sky_colour, 0.5 + 0.5 * n.y);
    vec3 diffuse = u_key_colour * max(dot(n, u_key_direction), 0.0)
                 + u_fill_colour * max(dot(n, u_fill_direction), 0.0);
    // A material without a highlight (large translucent shells) skips the pow().
    float highlight = 0.0;
    if (u_specular > 0.0) {
        vec3 half_vector = normalize(u_key_direction + to_eye);
        highlight = pow(max(dot(n, half_vector), 0.0), u_shininess) * step(0.0, dot(n, u_key_direction));
    }
    vec3 colour = base * (ambient + diffuse) + u_specular * highlight * u_key_colour;

    float facing = abs(dot(n, to_eye));
    float grazing = 1.0 - facing;
    float alpha = clamp(u_colour.a * (1.0 + u_rim * grazing * grazing), 0.0, 1.0);
    frag_colour = vec4(linear_to_srgb(colour), alpha);
}
