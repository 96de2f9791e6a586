// Imitates: a whole "product shot" Shadertoy finished the careful way:
// linear lighting, a soft key and a fill light, IQ-style soft shadow and
// AO, gamma, a vignette, and a last `dither()` against banding that adds
// +-0.5/255 of noise from a sine-free hash seeded by the pixel, read from
// `gl_FragCoord.xy` inside the helper rather than passed down from
// mainImage's fragCoord (hash12 in the style of Dave Hoskins' "Hash
// without Sine", with its own constants). The subject: a mug (a capped
// cylinder hollowed from the top, a half-torus handle), `float map(vec3
// p)`, a fixed three-quarter camera.
//
// Issue 47, class 4: gl_FragCoord is read in a helper (dither()) that
// mainImage calls, never in the map. It exists only in fragment shaders:
// sdfwb's sampler, a compute shader, must still compile the file, whose
// mainImage it compiles but never calls.
//
// Why the audit should find it clean: the body is max(outer, -inner) of
// two exact capped cylinders (a subtraction: a lower bound, |grad| <= 1,
// continuous), the handle an exact torus cut to its outer half by
// max(torus, -x) (an intersection with a half space: the same), joined by
// min(). Its cut face lies inside the mug's wall, so the seam is hidden;
// the creases (the rim, the handle's roots) read at most ~1.04 to the
// audit's per-axis differences. Inside the cup the field is the distance
// to the walls, which is flat along the axis for a while (the medial
// axis), then falls towards the rim: no plateau to the end of a probe.
// Finite; within -0.42 <= x <= 0.64, -0.5 <= y <= 0.4, |z| <= 0.42,
// growing outside: no flag. No iTime: not animated.
// expect: entry=map flags=none animated=no

float sdCappedCylinder(vec3 p, float r, float h)
{
    vec2 d = abs(vec2(length(p.xz), p.y)) - vec2(r, h);
    return min(max(d.x, d.y), 0.0) + length(max(d, 0.0));
}

float map(vec3 p)
{
    // the body: a cylinder, hollowed from the top (floor 0.08, wall 0.06)
    float outer = sdCappedCylinder(p - vec3(0.0, -0.05, 0.0), 0.42, 0.45);
    float inner = sdCappedCylinder(p - vec3(0.0, 0.1, 0.0), 0.36, 0.52);
    float body = max(outer, -inner);

    // the handle: the outer half of a torus standing in the xy plane,
    // rooted inside the wall
    vec3 q = p - vec3(0.39, -0.05, 0.0);
    float handle = length(vec2(length(q.xy) - 0.2, q.z)) - 0.045;
    handle = max(handle, -q.x);

    return min(body, handle);
}

vec3 calcNormal(vec3 p)
{
    vec2 e = vec2(1.0, -1.0) * 0.5773 * 0.0005;
    return normalize(e.xyy * map(p + e.xyy) + e.yyx * map(p + e.yyx) +
                     e.yxy * map(p + e.yxy) + e.xxx * map(p + e.xxx));
}

float raymarch(vec3 ro, vec3 rd)
{
    float t = 0.0;
    for (int i = 0; i < 200; i++)
    {
        float h = map(ro + rd * t);
        if (abs(h) < 0.0001 * (1.0 + t)) return t;
        t += h;
        if (t > 10.0) break;
    }
    return -1.0;
}

float softShadow(vec3 ro, vec3 rd, float k)
{
    float res = 1.0;
    float t = 0.01;
    for (int i = 0; i < 64; i++)
    {
        float h = map(ro + rd * t);
        res = min(res, k * h / t);
        t += clamp(h, 0.005, 0.08);
        if (res < 0.001 || t > 3.0) break;
    }
    res = clamp(res, 0.0, 1.0);
    return res * res * (3.0 - 2.0 * res);
}

float calcAO(vec3 p, vec3 n)
{
    float occ = 0.0, sca = 1.0;
    for (int i = 0; i < 5; i++)
    {
        float h = 0.01 + 0.1 * float(i) / 4.0;
        occ += (h - map(p + h * n)) * sca;
        sca *= 0.9;
    }
    return clamp(1.0 - 2.5 * occ, 0.0, 1.0);
}

// sine-free hash, 2 in 1 out
float hash12(vec2 p)
{
    vec3 p3 = fract(vec3(p.xyx) * 0.1127);
    p3 += dot(p3, p3.yzx + 19.19);
    return fract((p3.x + p3.y) * p3.z);
}

// +-half a step of 8-bit noise, against banding in the dark gradients
vec3 dither(vec3 col)
{
    return col + (hash12(gl_FragCoord.xy) - 0.5) / 255.0;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;

    vec3 ro = vec3(1.5, 1.1, 2.1);
    vec3 ta = vec3(0.05, -0.1, 0.0);
    vec3 ww = normalize(ta - ro);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    vec3 rd = normalize(uv.x * uu + uv.y * vv + 2.5 * ww);

    // a studio sweep: light above, dark below
    vec3 col = mix(vec3(0.03, 0.035, 0.04), vec3(0.22, 0.23, 0.25), smoothstep(-0.6, 0.8, rd.y));

    float t = raymarch(ro, rd);
    if (t > 0.0)
    {
        vec3 p = ro + rd * t;
        vec3 n = calcNormal(p);
        float occ = calcAO(p, n);

        vec3 key = normalize(vec3(-0.6, 0.8, 0.5));
        vec3 fil = normalize(vec3(0.8, 0.2, -0.3));
        float dk = clamp(dot(n, key), 0.0, 1.0) * softShadow(p + 0.002 * n, key, 10.0);
        float df = clamp(dot(n, fil), 0.0, 1.0);
        float sk = pow(clamp(dot(reflect(rd, n), key), 0.0, 1.0), 48.0);
        float fre = pow(clamp(1.0 + dot(n, rd), 0.0, 1.0), 4.0);

        // glazed ceramic, darker inside
        vec3 alb = vec3(0.55, 0.12, 0.08);
        if (length(p.xz) < 0.361 && p.y > -0.43) alb = vec3(0.7, 0.65, 0.55);

        vec3 lin = 1.6 * dk * vec3(1.0, 0.95, 0.85) + 0.35 * df * vec3(0.6, 0.7, 0.9) + 0.15 * occ;
        col = alb * lin + (0.6 * sk * dk + 0.1 * fre * occ) * vec3(1.0);
    }

    // gamma, vignette, dither
    col = pow(col, vec3(0.4545));
    vec2 q = fragCoord / iResolution.xy;
    col *= 0.5 + 0.5 * pow(16.0 * q.x * q.y * (1.0 - q.x) * (1.0 - q.y), 0.15);
    fragColor = vec4(dither(col), 1.0);
}
