// Imitates: a whole "SDF inspector" Shadertoy: the shape raymarched in
// 3D, and over it, in the lower-left corner, an inset with the y = 0 slice
// of the same map() drawn the way 2D SDF Shadertoys draw fields (inside
// blue, outside orange, bands every 1/20, a white zero contour), the
// contour and a coordinate grid anti-aliased with fwidth(), dFdx() and
// dFdy(). Derivatives exist only in fragment shaders; the map does not use
// them (it is evaluated in sdfwb's compute shaders too), mainImage does.
// `float map(vec3 p)`, IQ-style exact primitives (sdHexPrism,
// sdRoundedCylinder, sdCapsule).
//
// Why the audit should find it clean: the hexagonal prism, the rounded
// cylinder and the capsule are exact distances, and min() of exact
// distances is the exact distance to the union: continuous, |grad| <= 1,
// growing outside the cube (everything lies within |x|, |z| <= 0.8,
// |y| <= 0.65), no NaN. No iTime in the file: not animated.
// expect: entry=map flags=none animated=no

float sdHexPrism(vec3 p, vec2 h)
{
    const vec3 k = vec3(-0.8660254, 0.5, 0.57735);
    p = abs(p);
    p.xy -= 2.0 * min(dot(k.xy, p.xy), 0.0) * k.xy;
    vec2 d = vec2(length(p.xy - vec2(clamp(p.x, -k.z * h.x, k.z * h.x), h.x)) * sign(p.y - h.x),
                  p.z - h.y);
    return min(max(d.x, d.y), 0.0) + length(max(d, 0.0));
}

float sdRoundedCylinder(vec3 p, float ra, float rb, float h)
{
    vec2 d = vec2(length(p.xz) - ra + rb, abs(p.y) - h + rb);
    return min(max(d.x, d.y), 0.0) + length(max(d, 0.0)) - rb;
}

float sdCapsule(vec3 p, vec3 a, vec3 b, float r)
{
    vec3 pa = p - a, ba = b - a;
    float h = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
    return length(pa - ba * h) - r;
}

float map(vec3 p)
{
    // a hexagonal nut lying on its face...
    float nut = sdHexPrism((p - vec3(-0.35, -0.35, 0.1)).xzy, vec2(0.3, 0.12));
    // ...a rounded puck standing beside it...
    float puck = sdRoundedCylinder(p - vec3(0.4, -0.1, -0.2), 0.3, 0.06, 0.35);
    // ...and a bar leaning across both
    float bar = sdCapsule(p, vec3(-0.7, 0.0, 0.5), vec3(0.6, 0.55, 0.3), 0.07);
    return min(nut, min(puck, bar));
}

vec3 calcNormal(vec3 p)
{
    vec2 e = vec2(1.0, -1.0) * 0.0005;
    return normalize(e.xyy * map(p + e.xyy) + e.yyx * map(p + e.yyx) +
                     e.yxy * map(p + e.yxy) + e.xxx * map(p + e.xxx));
}

vec3 fieldColor(float d)
{
    vec3 col = d > 0.0 ? vec3(0.9, 0.6, 0.3) : vec3(0.65, 0.85, 1.0);
    col *= 1.0 - exp(-6.0 * abs(d));
    col *= 0.8 + 0.2 * cos(125.6 * d);
    return col;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    // ---- 3D view ----
    vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(1.9, 1.5, 2.4);
    vec3 ww = normalize(-ro);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    vec3 rd = normalize(p.x * uu + p.y * vv + 2.0 * ww);

    vec3 col = vec3(0.3, 0.32, 0.36) - 0.1 * rd.y;
    float t = 0.0;
    for (int i = 0; i < 128; i++)
    {
        float h = map(ro + rd * t);
        if (h < 0.0005 * t) break;
        t += h;
        if (t > 10.0) break;
    }
    if (t < 10.0)
    {
        vec3 pos = ro + rd * t;
        vec3 nor = calcNormal(pos);
        float dif = clamp(dot(nor, normalize(vec3(0.4, 0.9, 0.3))), 0.0, 1.0);
        col = vec3(0.8, 0.75, 0.7) * (0.2 + 0.8 * dif);
        // mark the slice plane on the surface
        col = mix(col, vec3(1.0, 0.2, 0.1), 1.0 - smoothstep(0.0, 1.5 * fwidth(pos.y), abs(pos.y)));
    }

    // ---- inset: the y = 0 slice ----
    float size = 0.4 * iResolution.y;
    vec2 ip = fragCoord - vec2(10.0);
    if (ip.x > 0.0 && ip.y > 0.0 && ip.x < size && ip.y < size)
    {
        vec2 q = (ip / size) * 2.4 - 1.2;
        float d = map(vec3(q.x, 0.0, -q.y));
        vec3 c = fieldColor(d);

        // the zero contour, one pixel wide whatever the zoom
        float w = fwidth(d);
        c = mix(c, vec3(1.0), 1.0 - smoothstep(0.0, 1.5 * w, abs(d)));

        // grid every 0.25, lines one pixel wide
        vec2 g = q * 4.0;
        vec2 px = vec2(abs(dFdx(g.x)), abs(dFdy(g.y)));
        vec2 line = abs(fract(g - 0.5) - 0.5) / max(px, 1e-4);
        c = mix(c, vec3(0.0), 0.3 * (1.0 - clamp(min(line.x, line.y), 0.0, 1.0)));

        col = c;
    }

    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
