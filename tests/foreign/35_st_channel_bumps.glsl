// Imitates: a whole Shadertoy that bumps a shape with the noise texture
// bound to iChannel0 (Shadertoy's "RGBA Noise Medium", 256x256): an
// asteroid with a ring, `float map(vec3 p)` reading two octaves of the
// texture with textureLod(iChannel0, uv, 0.0) (the explicit LOD every
// texture read inside a loop wants), a marcher that only moves half the
// distance ("the bumps break the bound"), texture() again for colour in
// the shading, and a camera turning with iTime.
//
// Why non-conservative, although the bumps are only 0.015 high: the
// texture is linearly filtered, so between two texel centres (1/256 apart
// in uv) the value runs linearly from one random texel to the next; the
// slope of the value in uv is (difference of neighbours) x 256, and two
// independent uniform values differ by 1/3 on average and by up to 1.
// With uv = 0.25 * p.xz, the first octave (weight 0.5 x 0.02 = 0.01) has a
// slope of 0.01 x 0.25 x 256 = 0.64 per unit of difference, the second
// (0.005, uv doubled) the same 0.64: |grad| of the bumps is ~0.2 at a
// typical point and reaches ~1.5 where neighbouring texels differ most,
// added to the sphere's |grad| = 1 in varying directions (the bumps depend
// on x and z only, so this holds everywhere in the cube): the 99.9th
// percentile of |grad f| is ~1.3-1.4. To stay 1-Lipschitz the bumps would
// have to be ~30 times flatter. (The kinks at texel borders also read as
// rounding noise of ~3e-4 to the audit's noise-floor estimate, which takes
// ~0.05 off its Lipschitz estimate: the margin over 1.05 stays large.)
// Continuous (bilinear filtering; hardware weight rounding makes steps of
// ~1e-5, far below what the audit calls a jump), finite, and growing
// outside (the sphere term dominates away from the surface): no other
// flag. The map does not read iTime, but mainImage does, so the file is
// animated.
// expect: entry=map flags=non-conservative animated=yes

#define STEPS 220
#define FAR 20.0

mat2 rot(float a)
{
    float c = cos(a), s = sin(a);
    return mat2(c, s, -s, c);
}

// two octaves of texture noise, seen from above
float bumps(vec3 p)
{
    vec2 uv = p.xz * 0.25 + vec2(0.31, 0.17);
    float n = 0.5 * textureLod(iChannel0, uv, 0.0).x;
    n += 0.25 * textureLod(iChannel0, uv * 2.0 + 0.5, 0.0).y;
    return n;
}

float sdTorus(vec3 p, vec2 t)
{
    vec2 q = vec2(length(p.xz) - t.x, p.y);
    return length(q) - t.y;
}

float map(vec3 p)
{
    // the rock
    float rock = length(p) - 0.62;
    rock -= 0.02 * bumps(p);

    // its ring, tilted
    vec3 q = p;
    q.xy *= rot(0.35);
    float ring = sdTorus(q, vec2(0.85, 0.025));

    return min(rock, ring);
}

vec3 normal(vec3 p)
{
    vec2 e = vec2(0.001, 0.0);
    return normalize(vec3(map(p + e.xyy) - map(p - e.xyy),
                          map(p + e.yxy) - map(p - e.yxy),
                          map(p + e.yyx) - map(p - e.yyx)));
}

float march(vec3 ro, vec3 rd)
{
    float t = 0.0;
    for (int i = 0; i < STEPS; i++)
    {
        float d = map(ro + rd * t);
        if (abs(d) < 0.0005 * t || t > FAR) break;
        t += 0.5 * d;   // the bumps break the bound: under-step
    }
    return t;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = (fragCoord - 0.5 * iResolution.xy) / iResolution.y;

    float a = 0.2 * iTime;
    vec3 ro = vec3(2.8 * sin(a), 1.1, 2.8 * cos(a));
    vec3 fw = normalize(-ro);
    vec3 rt = normalize(cross(fw, vec3(0.0, 1.0, 0.0)));
    vec3 up = cross(rt, fw);
    vec3 rd = normalize(uv.x * rt + uv.y * up + 1.6 * fw);

    vec3 col = vec3(0.02, 0.02, 0.05);   // space

    float t = march(ro, rd);
    if (t < FAR)
    {
        vec3 p = ro + rd * t;
        vec3 n = normal(p);
        vec3 sun = normalize(vec3(0.8, 0.4, 0.3));
        float dif = max(dot(n, sun), 0.0);
        vec3 grain = texture(iChannel0, p.xz * 0.5).rgb;
        vec3 base = length(p) < 0.75 ? mix(vec3(0.45, 0.38, 0.3), vec3(0.6, 0.55, 0.5), grain.x)
                                      : vec3(0.8, 0.75, 0.6);
        col = base * (0.05 + dif);
    }

    col = pow(col, vec3(0.4545));
    fragColor = vec4(col, 1.0);
}
