#version 330 core
// Mesh spheres: per-fragment normals, so the facets show only at the outline.

#include "particle_shading.glsl"

in vec3 vNormal;
flat in vec3 vTowardEye;
flat in vec3 vColour;
flat in vec2 vMarks;

out vec4 fragColour;

void main()
{
    fragColour = vec4(shadeParticle(normalize(vNormal), vTowardEye, vColour, vMarks), 1.0);
}
