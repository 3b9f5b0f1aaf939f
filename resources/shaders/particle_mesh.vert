#version 330 core
// Mesh spheres: one unit sphere, instanced, moved and scaled per particle.

layout(location = 0) in vec3 vertex;  // on the unit sphere, so also its normal
layout(location = 1) in vec3 centre;  // per particle, world, m
layout(location = 2) in float radius; // per particle, m
layout(location = 3) in vec3 colour;
layout(location = 4) in vec2 marks;   // pinned, selected
layout(location = 5) in vec4 orientation;  // per particle, (w, x, y, z); identity where nothing turns

uniform mat4 view;
uniform mat4 projection;

out vec3 vNormal;  // view space
flat out vec3 vTowardEye;
flat out vec3 vColour;
flat out vec2 vMarks;
flat out vec4 vOrientation;

void main()
{
    // the view has no scale, so its rotation turns normals as it turns points
    vec3 c = (view * vec4(centre, 1.0)).xyz;
    vNormal = mat3(view) * vertex;
    // orthographic (the matrix ends in 1): the eye is along +z from everywhere
    vTowardEye = projection[3][3] == 1.0 ? vec3(0.0, 0.0, 1.0) : normalize(-c);
    vColour = colour;
    vMarks = marks;
    vOrientation = orientation;
    gl_Position = projection * vec4(c + vNormal * radius, 1.0);
}
