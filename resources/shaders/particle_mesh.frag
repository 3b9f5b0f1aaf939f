#version 330 core
// Mesh spheres: per-fragment normals, so the facets show only at the outline.

#include "particle_shading.glsl"

in vec3 vNormal;
flat in vec3 vTowardEye;
flat in vec3 vColour;
flat in vec2 vMarks;
flat in vec4 vOrientation;

uniform mat4 view;
uniform bool patterned;  // the balls turn: their pattern is drawn

out vec4 fragColour;

void main()
{
    vec3 normal = normalize(vNormal);
    vec3 base = patterned ? patternOn(vColour, normal, vOrientation, mat3(view)) : vColour;
    fragColour = vec4(shadeParticle(normal, vTowardEye, base, vMarks), 1.0);
}
