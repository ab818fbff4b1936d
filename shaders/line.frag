#version 330 core
in vec4 g_colour;
out vec4 frag_colour;

void main() { frag_colour = g_colour; }
