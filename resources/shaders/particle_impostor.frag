#version 330 core
// Ray-cast spheres: the ray from the eye through this fragment (orthographic: the ray along -z
// through it) meets the sphere, or the fragment is dropped; the depth written is the sphere's. The outline is smoothed with alpha to coverage when
// the framebuffer is multisampled.

#include "particle_shading.glsl"

in vec3 vQuadPoint;
flat in vec3 vCentre;
flat in float vRadius;
flat in vec3 vColour;
flat in vec2 vMarks;
flat in vec4 vOrientation;

uniform mat4 projection;
uniform mat4 view;
uniform bool patterned;  // the balls turn: their pattern is drawn
uniform bool smoothEdges;  // with alpha to coverage

out vec4 fragColour;

void main()
{
    // the ray's closest approach to the centre, computed without cancellation for small spheres
    bool orthographic = projection[3][3] == 1.0;
    vec3 origin = orthographic ? vec3(vQuadPoint.xy, 0.0) : vec3(0.0);
    vec3 dir = orthographic ? vec3(0.0, 0.0, -1.0) : normalize(vQuadPoint);
    vec3 toCentre = vCentre - origin;
    float along = dot(dir, toCentre);
    vec3 offset = dir * along - toCentre;  // centre to the closest point
    float miss = length(offset);

    // coverage of this pixel by the outline, in pixels
    float edge = (vRadius - miss) / max(fwidth(miss), 1.0e-9);
    float coverage = smoothEdges ? clamp(edge + 0.5, 0.0, 1.0) : float(edge >= 0.0);
    if (coverage <= 0.0)
        discard;

    // the near hit (on the outline for the partly covered pixels outside it)
    float depthIn = sqrt(max(vRadius * vRadius - miss * miss, 0.0));
    vec3 hit = origin + dir * (along - depthIn);
    vec3 normal = normalize(offset - dir * depthIn);

    vec4 clip = projection * vec4(hit, 1.0);
    gl_FragDepth = 0.5 * (clip.z / clip.w) + 0.5;
    vec3 towardEye = orthographic ? vec3(0.0, 0.0, 1.0) : normalize(-vCentre);
    vec3 base = patterned ? patternOn(vColour, normal, vOrientation, mat3(view)) : vColour;
    fragColour = vec4(shadeParticle(normal, towardEye, base, vMarks), coverage);
}
