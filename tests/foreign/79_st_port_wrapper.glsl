// Imitates: a Shadertoy shader ported to a standalone WebGL 1 page the common way: the page's
// fragment shader is the Shadertoy code unchanged, with a `precision highp float;` line and the
// two inputs it reads declared above it (`uniform vec3 iResolution; uniform float iTime;`), and
// the porting wrapper at the bottom, `void main() { mainImage(gl_FragColor, gl_FragCoord.xy); }`.
// The Shadertoy part is IQ-style: `float map(vec3 p)`, castRay(), a tetrahedral calcNormal(),
// calcAO(), a soft shadow, setCamera() and a gamma-corrected mainImage, the camera turning with
// iTime.
//
// Host support: sdfwb sees a whole Shadertoy shader (mainImage is there), and must take the
// wrapper's `void main()` out, or treat it as the host's main that calls mainImage, and take the
// declared iResolution and iTime as the inputs it already provides. The entry is `map`.
//
// Why the audit should find it clean: a shape that morphs between a ball (radius 0.45) and a
// box (IQ's exact sdBox, half side 0.33) as mix(ball, box, k), k = 0.5 + 0.5 sin(0.8 iTime),
// spun about y by 0.5 iTime (an isometry), above a thin floor slab (an exact box) joined by
// min(). A convex mix of two 1-Lipschitz fields is 1-Lipschitz (|k grad a + (1 - k) grad b|
// <= 1) and continuous; min keeps both. The slab's top (y = -0.51) lies below the lowest the
// morph reaches (the ball's bottom, y = -0.35), and everything lies within |x|, |z| <= 0.7, so
// the field grows outside; no NaN. iTime is in the map: animated.
// expect: entry=map flags=none animated=yes

precision highp float;

uniform vec3 iResolution;
uniform float iTime;

// ---- Shadertoy code below, unchanged ----

float sdSphere(vec3 p, float r)
{
    return length(p) - r;
}

float sdBox(vec3 p, vec3 b)
{
    vec3 d = abs(p) - b;
    return min(max(d.x, max(d.y, d.z)), 0.0) + length(max(d, 0.0));
}

mat2 rot2(float a)
{
    float c = cos(a), s = sin(a);
    return mat2(c, -s, s, c);
}

float map(vec3 p)
{
    float k = 0.5 + 0.5 * sin(iTime * 0.8);
    vec3 q = p - vec3(0.0, 0.1, 0.0);
    q.xz = rot2(0.5 * iTime) * q.xz;
    float shape = mix(sdSphere(q, 0.45), sdBox(q, vec3(0.33)), k);
    float slab = sdBox(p - vec3(0.0, -0.55, 0.0), vec3(0.7, 0.04, 0.7));
    return min(shape, slab);
}

float castRay(vec3 ro, vec3 rd)
{
    float t = 0.1;
    for (int i = 0; i < 128; i++)
    {
        float h = map(ro + rd * t);
        if (abs(h) < 0.0002 * t) return t;
        t += h;
        if (t > 15.0) break;
    }
    return -1.0;
}

vec3 calcNormal(vec3 pos)
{
    vec2 e = vec2(1.0, -1.0) * 0.5773 * 0.0005;
    return normalize(e.xyy * map(pos + e.xyy) +
                     e.yyx * map(pos + e.yyx) +
                     e.yxy * map(pos + e.yxy) +
                     e.xxx * map(pos + e.xxx));
}

float calcAO(vec3 pos, vec3 nor)
{
    float occ = 0.0;
    float sca = 1.0;
    for (int i = 0; i < 5; i++)
    {
        float h = 0.01 + 0.12 * float(i) / 4.0;
        float d = map(pos + h * nor);
        occ += (h - d) * sca;
        sca *= 0.95;
    }
    return clamp(1.0 - 3.0 * occ, 0.0, 1.0);
}

float calcSoftshadow(vec3 ro, vec3 rd, float tmin, float tmax)
{
    float res = 1.0;
    float t = tmin;
    for (int i = 0; i < 32; i++)
    {
        float h = map(ro + rd * t);
        res = min(res, 8.0 * h / t);
        t += clamp(h, 0.02, 0.1);
        if (res < 0.005 || t > tmax) break;
    }
    return clamp(res, 0.0, 1.0);
}

mat3 setCamera(in vec3 ro, in vec3 ta, float cr)
{
    vec3 cw = normalize(ta - ro);
    vec3 cp = vec3(sin(cr), cos(cr), 0.0);
    vec3 cu = normalize(cross(cw, cp));
    vec3 cv = cross(cu, cw);
    return mat3(cu, cv, cw);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;

    float an = 0.7 + 0.1 * iTime;
    vec3 ro = vec3(3.0 * cos(an), 1.4, 3.0 * sin(an));
    vec3 ta = vec3(0.0, -0.1, 0.0);
    mat3 ca = setCamera(ro, ta, 0.0);
    vec3 rd = ca * normalize(vec3(p, 2.2));

    vec3 col = vec3(0.7, 0.8, 0.95) - 0.4 * rd.y;
    float t = castRay(ro, rd);
    if (t > 0.0)
    {
        vec3 pos = ro + t * rd;
        vec3 nor = calcNormal(pos);
        vec3 lig = normalize(vec3(-0.5, 0.7, 0.4));
        float dif = clamp(dot(nor, lig), 0.0, 1.0) * calcSoftshadow(pos, lig, 0.02, 3.0);
        float occ = calcAO(pos, nor);
        float amb = 0.5 + 0.5 * nor.y;
        vec3 mate = pos.y < -0.5 ? vec3(0.25) : vec3(0.2, 0.45, 0.7);
        col = mate * (2.0 * dif * vec3(1.0, 0.9, 0.7) + amb * occ * vec3(0.35, 0.4, 0.5));
    }

    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}

// ---- porting wrapper ----

void main()
{
    mainImage(gl_FragColor, gl_FragCoord.xy);
}
