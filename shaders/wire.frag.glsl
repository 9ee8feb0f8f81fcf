#version 330 core
uniform vec4 colour;
out vec4 fragColour;
void main() { fragColour = colour; }
