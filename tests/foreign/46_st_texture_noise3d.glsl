// Imitates: a WebGL 1 era Shadertoy built on the classic texture-based 3D
// value noise: one bilinear fetch from iChannel0 gives two z-slices at
// once, because on Shadertoy's "RGBA Noise" textures the green channel is
// the red channel shifted by (37, 17) texels, so the lookup at
// cell.xy + (37, 17) * cell.z reads slice z in one channel and slice z + 1
// in the other. texture2DLod() (the WebGL 1 name) in the noise, texture2D()
// in the shading, three octaves of fbm bumping a ball in
// `float map(vec3 p)`, and a marcher that under-steps.
//
// Why it is continuous: sdfwb's iChannel noise is arranged like
// Shadertoy's (renderer/NoiseTexture.h: green is red moved by (37, 17)
// texels), so what one cell reads as slice z + 1 (red) is what the next
// cell reads as its slice z (green): no jump on the planes z = k /
// frequency. (With independent channels it jumped there by ~0.03: this
// file caught that.) Why non-conservative: the noise is smooth but steep:
// each octave adds 0.15 x weight x frequency x (slope of the smoothed
// bilinear value, ~0.5 typical, up to ~2.5) ~ 0.13 typical and ~0.6 at
// most, three octaves in independent directions, so |grad f| reaches
// ~1.4 at the 99.9th percentile. Finite, and the ball term grows outside
// (the bumps are within +-0.075): no plateau, no NaN. No iTime: not
// animated.
// expect: entry=map flags=non-conservative animated=no

float texNoise(in vec3 x)
{
    vec3 cell = floor(x);
    vec3 w = fract(x);
    w = w * w * (3.0 - 2.0 * w);
    // slice z in green, slice z+1 in red (37,17 texels on)
    vec2 st = cell.xy + cell.z * vec2(37.0, 17.0) + w.xy;
    vec2 lohi = texture2DLod(iChannel0, (st + 0.5) / 256.0, 0.0).yx;
    return mix(lohi.x, lohi.y, w.z);
}

float fbm(in vec3 p)
{
    float f = 0.5 * texNoise(p);
    p *= 2.02;
    f += 0.25 * texNoise(p);
    p *= 2.03;
    f += 0.125 * texNoise(p);
    return f / 0.875;
}

float map(in vec3 p)
{
    float d = length(p) - 0.62;
    return d + 0.15 * (fbm(3.0 * p) - 0.5);
}

vec3 calcNormal(in vec3 p)
{
    vec2 e = vec2(0.002, 0.0);
    return normalize(vec3(map(p + e.xyy) - map(p - e.xyy),
                          map(p + e.yxy) - map(p - e.yxy),
                          map(p + e.yyx) - map(p - e.yyx)));
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 p = (-iResolution.xy + 2.0 * fragCoord) / iResolution.y;

    vec3 ro = vec3(1.4, 0.9, 2.2);
    vec3 ww = normalize(-ro);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = normalize(cross(uu, ww));
    vec3 rd = normalize(p.x * uu + p.y * vv + 2.0 * ww);

    float t = 0.0;
    for (int i = 0; i < 200; i++)
    {
        float h = map(ro + rd * t);
        if (abs(h) < 0.0005 || t > 8.0) break;
        t += 0.5 * h;
    }

    vec3 col = vec3(0.6, 0.7, 0.8) - 0.4 * rd.y;
    if (t < 8.0)
    {
        vec3 pos = ro + rd * t;
        vec3 nor = calcNormal(pos);
        float dif = clamp(dot(nor, normalize(vec3(0.6, 0.7, 0.2))), 0.0, 1.0);
        vec3 mate = 0.4 + 0.3 * texture2D(iChannel0, 0.3 * pos.xz).xyz;
        col = mate * (0.2 + dif * vec3(1.1, 1.0, 0.8));
    }
    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
