// Imitates: a whole Shadertoy that shows off the inputs other than iTime:
// an alarm clock on an endless table, raymarched, with a 2D overlay: an
// analog clock face driven by iDate.w (seconds since midnight), a frame
// time bar from iTimeDelta against 1/iFrameRate, an audio-rate tick from
// iSampleRate, a progress bar from iChannelTime[0], and a thumbnail of
// iChannel0 drawn with the aspect of iChannelResolution[0]. Its
// `float map(vec3 p)` is simple: a table plane (y = -0.9, endless, as
// beginner Shadertoys have it) and exact shapes standing on it.
//
// Why truncated, for an exact field (a known miss, see the README): every
// term is an exact distance (plane, rounded box, torus, spheres, capsule)
// and min() keeps it exact, continuous and 1-Lipschitz, no NaN. But the
// distance to a horizontal plane is the same all along a horizontal line,
// and the audit probes outward from surface points along the normal: from
// the clock's vertical faces (normals exactly horizontal) the field grows
// until the table is nearer than the clock, then stays at the height above
// the table for the rest of the 3 units. The audit reads that as a plateau
// (the field stops growing), on far more than its 5 % of rays. A bounded
// slab instead of the plane would not do it (see 36_st_frame_accumulate).
// No iTime (iDate, iTimeDelta and the rest are not the scene time): not
// animated.
// expect: entry=map flags=truncated animated=no

#define PI 3.14159265

float sdRoundBox(vec3 p, vec3 b, float r)
{
    vec3 q = abs(p) - b + r;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - r;
}

float sdTorus(vec3 p, vec2 t)
{
    return length(vec2(length(p.xz) - t.x, p.y)) - t.y;
}

float sdCapsule(vec3 p, vec3 a, vec3 b, float r)
{
    vec3 pa = p - a, ba = b - a;
    float h = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
    return length(pa - ba * h) - r;
}

float map(vec3 p)
{
    float table = p.y + 0.9;

    // body, standing on the table
    float d = sdRoundBox(p - vec3(0.0, -0.4, 0.0), vec3(0.5, 0.5, 0.22), 0.06);
    // bezel around the dial, on the front face
    d = min(d, sdTorus((p - vec3(0.0, -0.38, 0.22)).xzy, vec2(0.33, 0.035)));
    // bells and the hammer between them
    d = min(d, length(p - vec3(-0.3, 0.22, 0.0)) - 0.15);
    d = min(d, length(p - vec3( 0.3, 0.22, 0.0)) - 0.15);
    d = min(d, sdCapsule(p, vec3(0.0, 0.1, 0.0), vec3(0.0, 0.32, 0.0), 0.035));

    return min(table, d);
}

vec3 calcNormal(vec3 p)
{
    vec2 e = vec2(0.0007, 0.0);
    return normalize(vec3(map(p + e.xyy) - map(p - e.xyy),
                          map(p + e.yxy) - map(p - e.yxy),
                          map(p + e.yyx) - map(p - e.yyx)));
}

float sdSegment(vec2 p, vec2 a, vec2 b)
{
    vec2 pa = p - a, ba = b - a;
    float h = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
    return length(pa - ba * h);
}

// an anti-aliased stroke of a 2D distance, in pixels
float stroke(float d, float width)
{
    return 1.0 - smoothstep(width - 0.75, width + 0.75, d);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    // ---- the scene ----
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(1.5, 0.6, 2.8);
    vec3 ta = vec3(0.0, -0.35, 0.0);
    vec3 ww = normalize(ta - ro);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    vec3 rd = normalize(uv.x * uu + uv.y * vv + 2.2 * ww);

    vec3 col = vec3(0.15, 0.16, 0.2);
    float t = 0.0;
    for (int i = 0; i < 160; i++)
    {
        float h = map(ro + rd * t);
        if (h < 0.0004 * t || t > 15.0) break;
        t += h;
    }
    if (t < 15.0)
    {
        vec3 pos = ro + rd * t;
        vec3 nor = calcNormal(pos);
        vec3 alb = pos.y < -0.885 ? vec3(0.35, 0.22, 0.12) : vec3(0.75, 0.15, 0.12);   // table : clock
        float dif = clamp(dot(nor, normalize(vec3(0.3, 0.8, 0.6))), 0.0, 1.0);
        col = alb * (0.2 + 0.8 * dif);
    }

    // ---- overlay: analog clock from iDate (w = seconds since midnight) ----
    float R = 0.15 * iResolution.y;
    vec2 c = vec2(iResolution.x - R - 12.0, iResolution.y - R - 12.0);
    vec2 q = fragCoord - c;
    float secs = iDate.w;
    float aS = 2.0 * PI * floor(mod(secs, 60.0)) / 60.0;
    float aM = 2.0 * PI * mod(secs / 60.0, 60.0) / 60.0;
    float aH = 2.0 * PI * mod(secs / 3600.0, 12.0) / 12.0;
    float face = length(q) - R;
    col = mix(col, vec3(0.95), 0.85 * (1.0 - smoothstep(-0.75, 0.75, face)));
    col = mix(col, vec3(0.1), stroke(abs(face), 1.5));
    col = mix(col, vec3(0.1), stroke(sdSegment(q, vec2(0.0), 0.5 * R * vec2(sin(aH), cos(aH))), 2.5));
    col = mix(col, vec3(0.1), stroke(sdSegment(q, vec2(0.0), 0.8 * R * vec2(sin(aM), cos(aM))), 1.5));
    col = mix(col, vec3(0.8, 0.1, 0.1), stroke(sdSegment(q, vec2(0.0), 0.9 * R * vec2(sin(aS), cos(aS))), 0.7));

    // ---- frame time: green when iTimeDelta keeps up with iFrameRate ----
    float target = 1.0 / max(iFrameRate, 1.0);
    float load = clamp(iTimeDelta / (2.0 * target), 0.0, 1.0);
    if (fragCoord.y < 6.0 && fragCoord.x < load * iResolution.x)
        col = mix(vec3(0.1, 0.8, 0.2), vec3(0.9, 0.2, 0.1), smoothstep(0.5, 0.6, load));

    // ---- audio: a square wave at 441 Hz, sampled at iSampleRate ----
    float phase = fract(fragCoord.x * 441.0 / iSampleRate);
    if (fragCoord.y > 8.0 && fragCoord.y < 12.0 && phase < 0.5) col = vec3(0.9, 0.8, 0.2);

    // ---- iChannel0: playback position and a thumbnail ----
    float played = fract(iChannelTime[0] / 10.0);
    if (fragCoord.y > 14.0 && fragCoord.y < 18.0 && fragCoord.x < played * iResolution.x) col = vec3(0.3, 0.5, 0.9);
    vec2 res0 = max(iChannelResolution[0].xy, vec2(1.0));
    vec2 thumb = vec2(0.2 * iResolution.y * res0.x / res0.y, 0.2 * iResolution.y);
    vec2 tp = (fragCoord - vec2(10.0, 24.0)) / thumb;
    if (all(greaterThan(tp, vec2(0.0))) && all(lessThan(tp, vec2(1.0))))
        col = texture(iChannel0, tp).rgb;

    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
