// Imitates: a whole Shadertoy that fights banding and aliasing the way
// many do: the march starts each ray a random fraction of a step along,
// `t = hash(gl_FragCoord.xy) * 0.1`, inside the trace() helper (the
// classic fract(sin(dot(...))*43758.5453) hash), and the backdrop is the
// noise texture bound to iChannel0 read with a large negative LOD bias,
// `texture(iChannel0, rd.xy*.5+.5, -100.)`, to force the sharpest mip.
// The subject: a twisted square column with rounded edges, turning
// slowly with iTime, `float map(vec3 p)`, marched at 0.7 of the distance
// because the twist makes the field steep.
//
// Issue 47, classes 4 and 5: gl_FragCoord read in a helper (trace(), which
// mainImage calls) and texture() with its third, bias argument in another
// (background()). Both exist only in fragment shaders; sdfwb's sampler is
// a compute shader and must still compile the file (mainImage and its
// helpers are compiled, never called). The map reads neither.
//
// Why non-conservative: twisting space about the y axis by k = 3 radians
// per unit of height moves a point at distance rho from the axis sideways
// by k rho per unit of y, so the field's gradient gains a vertical part,
// k rho times the part of the box's gradient along the turn. Straight out
// from a face's middle that part is 0; at the column's vertical edges
// (rho ~ 0.3, the gradient half along the turn) |grad f| ~ 1.1; beyond
// the ends, where the nearest point is on an edge of the end face and the
// gradient leans along the turn at rho ~ 0.6, it reaches ~1.3. Over the
// cube |grad f| exceeds 1.05 at ~40 % of the points and its 99.9th
// percentile is ~1.3, at every iTime (time only turns the column).
// Rotations and the rounded box are continuous and finite, and the
// twisted box grows outside as the box does (a twist keeps rho and y): no
// other flag. iTime in the map: animated.
// expect: entry=map flags=non-conservative animated=yes

mat2 rot(float a)
{
    float c = cos(a), s = sin(a);
    return mat2(c, s, -s, c);
}

float hash(vec2 p)
{
    return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453);
}

float sdRoundBox(vec3 p, vec3 b, float r)
{
    vec3 q = abs(p) - b + r;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - r;
}

float map(vec3 p)
{
    p.xz *= rot(3.0 * p.y + 0.5 * iTime);
    return sdRoundBox(p, vec3(0.22, 0.62, 0.22), 0.04);
}

float trace(vec3 ro, vec3 rd)
{
    // start a random fraction of a step along: banding becomes fine noise
    float t = hash(gl_FragCoord.xy) * 0.1;
    for (int i = 0; i < 160; i++)
    {
        float d = map(ro + rd * t);
        if (abs(d) < 0.0005 || t > 8.0) break;
        t += d * 0.7;
    }
    return t;
}

vec3 calcNormal(vec3 p)
{
    vec2 e = vec2(0.001, 0.0);
    return normalize(vec3(map(p + e.xyy) - map(p - e.xyy),
                          map(p + e.yxy) - map(p - e.yxy),
                          map(p + e.yyx) - map(p - e.yyx)));
}

vec3 background(vec3 rd)
{
    // the channel's texels, as sharp as they come
    vec3 tex = texture(iChannel0, rd.xy * .5 + .5, -100.).rgb;
    return mix(vec3(0.05, 0.06, 0.1), vec3(0.15, 0.2, 0.3), tex.r) * (0.6 + 0.4 * rd.y);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = (fragCoord - 0.5 * iResolution.xy) / iResolution.y;

    vec3 ro = vec3(0.0, 0.35, -2.7);
    vec3 rd = normalize(vec3(uv, 1.5));
    rd.yz *= rot(0.12);

    vec3 col = background(rd);

    float t = trace(ro, rd);
    if (t < 8.0)
    {
        vec3 p = ro + rd * t;
        vec3 n = calcNormal(p);
        vec3 l = normalize(vec3(0.7, 0.6, -0.5));
        float dif = max(dot(n, l), 0.0);
        float amb = 0.5 + 0.5 * n.y;
        float spe = pow(max(dot(reflect(rd, n), l), 0.0), 20.0);
        vec3 alb = 0.5 + 0.45 * cos(6.2831 * (0.3 * p.y + vec3(0.0, 0.15, 0.3)));
        col = alb * (0.9 * dif + 0.2 * amb) + 0.4 * spe;
    }

    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
