#version 330 core
// Ray-cast spheres: one quad per particle, facing the eye at the particle's centre and just large
// enough to hold the sphere's outline under perspective (under an orthographic projection, whose
// matrix ends in 1, a square as wide as the sphere); the fragment shader finds the sphere.

layout(location = 0) in vec2 corner;  // (±1, ±1)
layout(location = 1) in vec3 centre;  // per particle, world, m
layout(location = 2) in float radius; // per particle, m
layout(location = 3) in vec3 colour;
layout(location = 4) in vec2 marks;   // pinned, selected
layout(location = 5) in vec4 orientation;  // per particle, (w, x, y, z); identity where nothing turns

uniform mat4 view;
uniform mat4 projection;

out vec3 vQuadPoint;  // view space
flat out vec3 vCentre;
flat out float vRadius;
flat out vec3 vColour;
flat out vec2 vMarks;
flat out vec4 vOrientation;

void main()
{
    vec3 c = (view * vec4(centre, 1.0)).xyz;
    float d = length(c);
    vCentre = c;
    vRadius = radius;
    vColour = colour;
    vMarks = marks;
    vOrientation = orientation;

    // nothing to draw when the eye is inside the sphere: a point outside the clip volume
    bool orthographic = projection[3][3] == 1.0;
    if (!(radius > 0.0) || (!orthographic && d <= radius * 1.0001)) {
        vQuadPoint = vec3(0.0);
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0);
        return;
    }

    // parallel rays: the outline is the sphere's own width
    if (orthographic) {
        vQuadPoint = c + vec3(corner * radius, 0.0);
        gl_Position = projection * vec4(vQuadPoint, 1.0);
        return;
    }

    // the tangent cone from the eye is r d / sqrt(d² - r²) wide where it crosses the centre
    vec3 w = c / d;
    vec3 u = normalize(cross(w, abs(w.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
    vec3 v = cross(u, w);
    float halfSize = radius * d / sqrt(d * d - radius * radius);
    vQuadPoint = c + (corner.x * u + corner.y * v) * halfSize;
    gl_Position = projection * vec4(vQuadPoint, 1.0);
}
