// Shading shared by both ways of drawing particles (inserted where a particle fragment shader says
// #include "particle_shading.glsl"). Everything is in view space: the eye looks down -z.

// a head light a little above and to the left of the eye
const vec3 kLight = normalize(vec3(-0.35, 0.45, 1.0));
const vec3 kHalfway = normalize(kLight + vec3(0.0, 0.0, 1.0));

// normal: unit surface normal; towardEye: unit vector from the sphere's centre to the eye;
// marks.x: pinned, marks.y: selected
vec3 shadeParticle(vec3 normal, vec3 towardEye, vec3 base, vec2 marks)
{
    // ambient, diffuse and a small white highlight
    float diffuse = max(dot(normal, kLight), 0.0);
    float specular = pow(max(dot(normal, kHalfway), 0.0), 48.0);
    vec3 colour = base * (0.28 + 0.72 * diffuse) + vec3(0.30 * specular);

    // 0 at the middle of the disc the sphere covers on screen, 1 at its outline
    float facing = clamp(dot(normal, towardEye), 0.0, 1.0);
    float rim = sqrt(1.0 - facing * facing);
    float blur = max(fwidth(rim), 1.0e-4);

    // pinned: a dark ring half way out
    if (marks.x > 0.5) {
        float ring = smoothstep(0.52 - blur, 0.52 + blur, rim) * (1.0 - smoothstep(0.70 - blur, 0.70 + blur, rim));
        colour = mix(colour, colour * 0.22, ring);
    }

    // selected: a bright rim at the outline
    if (marks.y > 0.5)
        colour = mix(colour, vec3(1.0), smoothstep(0.80, 0.96, rim));
    return colour;
}

// a turning ball's pattern (the scene can turn: the orientations are drawn): white caps about the
// body's y axis with the ball's own colour as a band between them, as a striped pool ball, and a
// dark spot where the body's x axis comes out, so that rolling and sliding look different.
// viewNormal: unit, view space; q: the ball's orientation (w, x, y, z); viewRotation: the view's
vec3 patternOn(vec3 base, vec3 viewNormal, vec4 q, mat3 viewRotation)
{
    vec3 world = transpose(viewRotation) * viewNormal;
    // into the body: rotated by q's conjugate, v + 2 u × (u × v + w v) with u = -q.xyz
    vec3 u = -q.yzw;
    vec3 body = world + 2.0 * cross(u, cross(u, world) + q.x * world);
    float blur = max(fwidth(body.y), 1.0e-4);
    float cap = smoothstep(0.45 - blur, 0.45 + blur, abs(body.y));
    vec3 colour = mix(base, vec3(0.92), cap);
    float spot = smoothstep(0.93 - blur, 0.93 + blur, body.x);
    return mix(colour, vec3(0.08), spot);
}
