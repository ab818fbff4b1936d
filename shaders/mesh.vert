#version 330 core
// Lit meshes: positions and normals go to view space, where the lights live.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_model_view;
uniform mat4 u_projection;
uniform mat3 u_normal_matrix;  // inverse transpose of u_model_view's 3x3 part

out vec3 v_position_view;
out vec3 v_normal_view;

void main() {
    vec4 position_view = u_model_view * vec4(a_position, 1.0);
    v_position_view = position_view.xyz;
    v_normal_view = u_normal_matrix * a_normal;
    gl_Position = u_projection * position_view;
}
