#version 330 core
// Unlit lines and triangles with a colour per vertex: springs, the grid, the axes, the planes.

layout(location = 0) in vec3 position;  // world, m
layout(location = 1) in vec4 colour;

uniform mat4 viewProjection;

out vec4 vColour;

void main()
{
    vColour = colour;
    gl_Position = viewProjection * vec4(position, 1.0);
}
