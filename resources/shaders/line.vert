#version 330 core
// Lines of a width in pixels (core-profile OpenGL draws GL_LINES 1 pixel wide at most): each line
// is one instance, and its four vertices are the corners of a quad around it on screen, half the
// width to either side and half the width past either end, so that lines meet without gaps.

layout(location = 0) in vec2 corner;  // x: 0 at end a, 1 at end b; y: -1 or 1, the side
layout(location = 1) in vec3 endA;    // per line, world, m
layout(location = 2) in vec4 colour;  // per line
layout(location = 3) in vec3 endB;    // per line, world, m

uniform mat4 viewProjection;
uniform vec2 pixels;      // the framebuffer's size
uniform float width;      // px
uniform float wideWidth;  // px, for the instances from wideFrom on (the highlighted springs)
uniform int wideFrom;

out vec4 vColour;

void main()
{
    vColour = colour;
    vec4 a = viewProjection * vec4(endA, 1.0);
    vec4 b = viewProjection * vec4(endB, 1.0);

    // only the part in front of the near plane (z >= -w); nothing when the whole line is behind
    float inA = a.z + a.w;
    float inB = b.z + b.w;
    if (inA < 0.0 && inB < 0.0) {
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0);
        return;
    }
    if (inA < 0.0)
        a = mix(a, b, inA / (inA - inB));
    else if (inB < 0.0)
        b = mix(b, a, inB / (inB - inA));

    // along and across the line on screen, in pixels
    vec2 halfPixels = 0.5 * pixels;
    vec2 along = b.xy / b.w * halfPixels - a.xy / a.w * halfPixels;
    float span = length(along);
    vec2 direction = span > 1.0e-6 ? along / span : vec2(1.0, 0.0);
    vec2 across = vec2(-direction.y, direction.x);

    float w = gl_InstanceID >= wideFrom ? wideWidth : width;
    vec4 p = corner.x < 0.5 ? a : b;
    vec2 offset = (across * corner.y + direction * (corner.x < 0.5 ? -1.0 : 1.0)) * 0.5 * w;
    p.xy += offset / halfPixels * p.w;
    gl_Position = p;
}
