// Imitates: the classic Shadertoy "smooth blobs" scene: a few balls
// orbiting on Lissajous paths driven by Shadertoy's undeclared `iTime`,
// merged with IQ's polynomial smin, `float map(vec3 p)`, plus the usual
// normal() / march() / soft-shadow helpers that sdfwb never calls.
//
// Why the audit should find it clean: balls are exact and the polynomial
// smin is 1-Lipschitz (gradient = convex mix of the two gradients), so
// the field is continuous with |grad| <= 1 at every time. The centres stay
// within 0.45 of the origin and the radii are <= 0.25, so the blobs stay
// in the cube, and the field grows outside.
// expect: entry=map flags=none animated=yes

#define NUM_BALLS 4

float smin(float a, float b, float k)
{
    float h = max(k - abs(a - b), 0.0)/k;
    return min(a, b) - h*h*k*0.25;
}

vec3 ballCenter(int i)
{
    float fi = float(i);
    float t = iTime*(0.6 + 0.15*fi) + fi*1.7;
    return 0.45*vec3(sin(t), sin(1.3*t + fi), cos(0.7*t))*vec3(1.0, 0.8, 0.9);
}

float map(vec3 p)
{
    float d = 1e5;
    for (int i = 0; i < NUM_BALLS; i++)
    {
        float r = 0.17 + 0.02*float(i);
        d = smin(d, length(p - ballCenter(i)) - r, 0.25);
    }
    return d;
}

vec3 normal(vec3 p)
{
    const vec2 e = vec2(1e-3, 0.0);
    return normalize(vec3(map(p + e.xyy) - map(p - e.xyy),
                          map(p + e.yxy) - map(p - e.yxy),
                          map(p + e.yyx) - map(p - e.yyx)));
}

float march(vec3 ro, vec3 rd)
{
    float t = 0.0;
    for (int i = 0; i < 96; i++)
    {
        float h = map(ro + rd*t);
        if (h < 1e-4*t) break;
        t += h;
        if (t > 30.0) return -1.0;
    }
    return t;
}

float softshadow(vec3 ro, vec3 rd, float k)
{
    float res = 1.0;
    float t = 0.02;
    for (int i = 0; i < 48; i++)
    {
        float h = map(ro + rd*t);
        res = min(res, k*h/t);
        t += clamp(h, 0.02, 0.2);
        if (res < 0.005 || t > 5.0) break;
    }
    return clamp(res, 0.0, 1.0);
}
