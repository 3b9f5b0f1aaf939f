#version 330 core
// Both sides of the sheet, lit by the head light of the particles (particle_shading.glsl): the side
// its triangles' normals point to in one colour, the other side in another.

#include "particle_shading.glsl"

in vec3 vTowardEye;
in vec3 vNormal;

uniform vec3 frontColour;
uniform vec3 backColour;

out vec4 fragColour;

void main()
{
    // the normal of the side seen; where the smooth normal turns away (near an outline or a
    // fold), or is missing, the one facing the eye
    vec3 towardEye = normalize(vTowardEye);
    float size = length(vNormal);
    vec3 normal = size > 1.0e-6 ? vNormal / size : towardEye;
    if (!gl_FrontFacing)
        normal = -normal;
    float facing = dot(normal, towardEye);
    if (facing < 0.0) {
        vec3 edgeOn = normal - facing * towardEye;
        normal = length(edgeOn) > 1.0e-6 ? normalize(edgeOn) : towardEye;
    }

    vec3 base = gl_FrontFacing ? frontColour : backColour;
    float diffuse = max(dot(normal, kLight), 0.0);
    float specular = pow(max(dot(normal, kHalfway), 0.0), 32.0);
    fragColour = vec4(base * (0.30 + 0.70 * diffuse) + vec3(0.12 * specular), 1.0);
}
