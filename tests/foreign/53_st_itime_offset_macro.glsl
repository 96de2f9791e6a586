// Imitates: a whole Shadertoy whose author moved its clock with a macro
// that wraps the input in its own name, `#define iTime (iTime - 25. + mx)`,
// a habit from long demo-style shaders: the part they were working on
// started 25 s in, and `mx` (a file-scope const here, the phase the loop
// should start at) lets them scrub without touching the rest of the
// code. Inside the macro's own expansion iTime is not expanded again
// (GLSL's preprocessor, like C's, does not recurse), so it reads
// Shadertoy's input. The scene: a Newton's cradle (five balls on V-shaped
// strings from two top bars, the end balls swinging in turn, posts and a
// base), `float map(vec3 p)` with a `pendulum()` helper, calcNormal(),
// calcAO(), a soft shadow and a fixed camera.
//
// Issue 47, class 2: a macro named after a Shadertoy input, defined in
// terms of that input. sdfwb must neither define iTime as a macro of its
// own over it nor skip declaring the input the macro's body reads; the map
// reads iTime only through the macro.
//
// Why the audit should find it clean: balls are exact spheres, strings,
// bars and posts exact capsules, the base an exact box; each pendulum is
// turned about its pivot line by a rotation (an isometry), and the pieces
// are joined with min(). At rest the balls touch their neighbours at one
// point and the strings meet the bars, so the union has concave creases
// (per-axis central differences there read at most ~1.04, under 1.05).
// Continuous, finite; the swing is at most 0.45 rad, so the end balls
// reach |x| <= 0.76; the rest stays within |x| <= 0.75 (the base), and
// all within -0.6 <= y <= 0.58, |z| <= 0.35: the field grows outside.
// iTime in the map (through the macro): animated.
// expect: entry=map flags=none animated=yes

// the phase to start from (scrub here)
const float mx = 1.6;
#define iTime (iTime - 25. + mx)

#define PIVOT_Y 0.55
#define LEN 0.6
#define BALL_R 0.1

mat2 rot(float a)
{
    float c = cos(a), s = sin(a);
    return mat2(c, s, -s, c);
}

float sdCapsule(vec3 p, vec3 a, vec3 b, float r)
{
    vec3 pa = p - a, ba = b - a;
    float h = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
    return length(pa - ba * h) - r;
}

float sdBox(vec3 p, vec3 b)
{
    vec3 q = abs(p) - b;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

// one pendulum hanging from the pivot line at x, swung by angle a
float pendulum(vec3 p, float x, float a)
{
    p -= vec3(x, PIVOT_Y, 0.0);
    p.xy *= rot(a);
    vec3 c = vec3(0.0, -LEN, 0.0);
    float d = length(p - c) - BALL_R;
    d = min(d, sdCapsule(p, vec3(0.0, 0.0, -0.25), c, 0.008));
    d = min(d, sdCapsule(p, vec3(0.0, 0.0, 0.25), c, 0.008));
    return d;
}

float map(vec3 p)
{
    // the swing: the left ball out while s < 0, the right one while s > 0
    float s = sin(3.0 * iTime);
    float aL = 0.45 * min(s, 0.0);
    float aR = 0.45 * max(s, 0.0);

    float d = pendulum(p, -0.4, aL);
    d = min(d, pendulum(p, -0.2, 0.0));
    d = min(d, pendulum(p, 0.0, 0.0));
    d = min(d, pendulum(p, 0.2, 0.0));
    d = min(d, pendulum(p, 0.4, aR));

    // frame: two top bars, four posts, the base
    d = min(d, sdCapsule(p, vec3(-0.65, PIVOT_Y, -0.25), vec3(0.65, PIVOT_Y, -0.25), 0.025));
    d = min(d, sdCapsule(p, vec3(-0.65, PIVOT_Y, 0.25), vec3(0.65, PIVOT_Y, 0.25), 0.025));
    vec3 q = vec3(abs(p.x), p.y, abs(p.z));
    d = min(d, sdCapsule(q, vec3(0.65, PIVOT_Y, 0.25), vec3(0.65, -0.5, 0.25), 0.025));
    d = min(d, sdBox(p - vec3(0.0, -0.55, 0.0), vec3(0.75, 0.05, 0.35)));
    return d;
}

vec3 calcNormal(vec3 p)
{
    const vec2 k = vec2(1.0, -1.0);
    const float h = 0.0005;
    return normalize(k.xyy * map(p + k.xyy * h) + k.yyx * map(p + k.yyx * h) +
                     k.yxy * map(p + k.yxy * h) + k.xxx * map(p + k.xxx * h));
}

float softShadow(vec3 ro, vec3 rd)
{
    float res = 1.0;
    float t = 0.01;
    for (int i = 0; i < 48; i++)
    {
        float h = map(ro + rd * t);
        res = min(res, 12.0 * h / t);
        t += clamp(h, 0.005, 0.1);
        if (res < 0.002 || t > 2.5) break;
    }
    return clamp(res, 0.0, 1.0);
}

float calcAO(vec3 p, vec3 n)
{
    float occ = 0.0;
    for (int i = 1; i <= 5; i++)
    {
        float h = 0.02 * float(i);
        occ += (h - map(p + n * h)) / float(i);
    }
    return clamp(1.0 - 4.0 * occ, 0.0, 1.0);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;

    vec3 ro = vec3(0.9, 0.45, 2.3);
    vec3 ta = vec3(0.0, 0.0, 0.0);
    vec3 ww = normalize(ta - ro);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    vec3 rd = normalize(uv.x * uu + uv.y * vv + 2.0 * ww);

    vec3 col = vec3(0.75, 0.78, 0.8) - 0.2 * uv.y;

    float t = 0.0;
    for (int i = 0; i < 200; i++)
    {
        float h = map(ro + rd * t);
        if (h < 0.0002 || t > 6.0) break;
        t += h;
    }

    if (t < 6.0)
    {
        vec3 p = ro + rd * t;
        vec3 n = calcNormal(p);
        vec3 l = normalize(vec3(-0.5, 0.8, 0.6));
        float dif = clamp(dot(n, l), 0.0, 1.0) * softShadow(p + n * 0.002, l);
        float spe = pow(clamp(dot(reflect(rd, n), l), 0.0, 1.0), 64.0);
        float occ = calcAO(p, n);

        // chrome balls and bars, a dark wooden base
        vec3 alb = (p.y < -0.49) ? vec3(0.2, 0.1, 0.05) : vec3(0.6, 0.62, 0.65);
        col = alb * (0.25 * occ + 0.9 * dif) + spe * dif;
    }

    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
