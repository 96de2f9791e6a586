// Imitates: "half sphere / half cube" Shadertoys that pick one of two
// SDFs with an if on a coordinate, the cut sweeping with Shadertoy's
// undeclared `iTime`; `vec2 map(vec3 p)` with a material id, sdSphere/sdBox
// in IQ's form, and a march() + normal() pair that sdfwb never calls.
//
// Why discontinuous: on the moving plane x = s (s = 0.3 sin(iTime), always
// inside the cube) the left side uses the ball of radius 0.5 and the right
// side the box of half size 0.4. On the plane near the x axis the two
// values differ by 0.1 (|s| - 0.5 against |s| - 0.4), and they agree only
// on curves, so the field jumps across most of that plane at any time.
// Each half is exact and finite, and the field grows outside.
// expect: entry=map flags=discontinuous animated=yes

float sdSphere(vec3 p, float r)
{
    return length(p) - r;
}

float sdBox(vec3 p, vec3 b)
{
    vec3 q = abs(p) - b;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

vec2 map(vec3 p)
{
    float split = 0.3*sin(iTime);
    if (p.x < split)
        return vec2(sdSphere(p, 0.5), 1.0);
    else
        return vec2(sdBox(p, vec3(0.4)), 2.0);
}

float march(vec3 ro, vec3 rd)
{
    float t = 0.0;
    for (int i = 0; i < 100; i++) {
        float d = map(ro + rd*t).x;
        if (d < 0.001 || t > 20.0) break;
        t += d;
    }
    return t;
}

vec3 normal(vec3 p)
{
    vec2 e = vec2(0.001, 0.0);
    return normalize(vec3(map(p + e.xyy).x - map(p - e.xyy).x,
                          map(p + e.yxy).x - map(p - e.yxy).x,
                          map(p + e.yyx).x - map(p - e.yyx).x));
}
