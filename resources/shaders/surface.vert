#version 330 core
// The sheet of a spring mesh (a cloth): its triangles between the particles' current positions,
// with the smooth normals the viewport computes for each new snapshot.

layout(location = 0) in vec3 position;  // world, m
layout(location = 1) in vec3 normal;    // world, unit (zero for a lone corner)

uniform mat4 view;
uniform mat4 projection;

out vec3 vPosition;  // view space
out vec3 vNormal;    // view space

void main()
{
    // the view has no scale, so its rotation turns normals as it turns points
    vec4 p = view * vec4(position, 1.0);
    vPosition = p.xyz;
    vNormal = mat3(view) * normal;
    gl_Position = projection * p;
}
