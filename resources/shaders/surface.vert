#version 330 core
// The sheet of a spring mesh (a cloth): its triangles between the particles' current positions,
// with the smooth normals the viewport computes for each new snapshot.

layout(location = 0) in vec3 position;  // world, m
layout(location = 1) in vec3 normal;    // world, unit (zero for a lone corner)

uniform mat4 view;
uniform mat4 projection;

out vec3 vTowardEye;  // view space, not unit
out vec3 vNormal;     // view space

void main()
{
    // the view has no scale, so its rotation turns normals as it turns points
    vec4 p = view * vec4(position, 1.0);
    // orthographic (the matrix ends in 1): the eye is along +z from everywhere
    vTowardEye = projection[3][3] == 1.0 ? vec3(0.0, 0.0, 1.0) : -p.xyz;
    vNormal = mat3(view) * normal;
    gl_Position = projection * p;
}
