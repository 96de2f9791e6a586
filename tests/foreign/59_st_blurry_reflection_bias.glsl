// Imitates: a whole Shadertoy of polished stones that fakes its
// environment with whatever 2D texture is bound to iChannel0, mapped onto
// the sky sphere by longitude and latitude (`atan(rd.z, rd.x)/TAU`,
// `acos(rd.y)/PI`): the backdrop reads it sharp with plain
// `texture(iChannel0, uv)`, and the stones' glossy reflection reads it
// blurred with the bias form, `texture(iChannel0, uv, 4.0)` (four mips
// coarser: the poor man's rough reflection). `float map(vec3 p)` stacks a
// cairn of rounded pebbles and a ball, blended; `#define PI`/`TAU`, a
// Fresnel mix, AO, a camera orbiting with iMouse.
//
// Issue 47, class 5 only: texture()'s bias argument, in the blurryEnv()
// helper that mainImage calls. Bias exists only in fragment shaders;
// sdfwb's sampler is a compute shader and must still compile the file
// (mainImage and its helpers are compiled, never called). The map reads
// no texture.
//
// Why the audit should find it clean: each pebble is an exact rounded
// cylinder (a rounded 2D box revolved about the axis), each slightly
// tilted by a rotation (an isometry); the ball is an exact sphere; all are
// joined with IQ's polynomial smooth min (gradient a convex mix: |grad| <=
// 1, continuous; it also rounds the creases where the stones meet).
// Finite; within 0.61 of the axis and -0.68 <= y <= 0.35, growing
// outside: no flag. No iTime: not animated.
// expect: entry=map flags=none animated=no

#define PI 3.14159265
#define TAU 6.28318531

mat2 rot(float a)
{
    float c = cos(a), s = sin(a);
    return mat2(c, s, -s, c);
}

float smin(float a, float b, float k)
{
    float h = clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
    return mix(b, a, h) - k * h * (1.0 - h);
}

// a pebble: a disc of radius r, half height h, edges rounded by rb
float pebble(vec3 p, float r, float h, float rb)
{
    vec2 d = vec2(length(p.xz) - r + rb, abs(p.y) - h + rb);
    return min(max(d.x, d.y), 0.0) + length(max(d, 0.0)) - rb;
}

float map(vec3 p)
{
    vec3 q = p - vec3(0.0, -0.55, 0.0);
    q.xy *= rot(0.05);
    float d = pebble(q, 0.6, 0.09, 0.07);

    q = p - vec3(0.03, -0.35, 0.02);
    q.yz *= rot(-0.08);
    d = smin(d, pebble(q, 0.46, 0.085, 0.06), 0.04);

    q = p - vec3(-0.02, -0.17, -0.01);
    q.xy *= rot(0.1);
    d = smin(d, pebble(q, 0.34, 0.075, 0.05), 0.04);

    q = p - vec3(0.01, -0.02, 0.02);
    q.yz *= rot(0.12);
    d = smin(d, pebble(q, 0.24, 0.065, 0.04), 0.04);

    d = smin(d, length(p - vec3(0.0, 0.2, 0.0)) - 0.15, 0.04);
    return d;
}

vec3 calcNormal(vec3 p)
{
    const vec2 k = vec2(1.0, -1.0);
    const float h = 0.0005;
    return normalize(k.xyy * map(p + k.xyy * h) + k.yyx * map(p + k.yyx * h) +
                     k.yxy * map(p + k.yxy * h) + k.xxx * map(p + k.xxx * h));
}

float intersect(vec3 ro, vec3 rd)
{
    float t = 0.0;
    for (int i = 0; i < 128; i++)
    {
        float h = map(ro + rd * t);
        if (h < 0.0003) return t;
        t += h;
        if (t > 6.0) break;
    }
    return -1.0;
}

float calcAO(vec3 p, vec3 n)
{
    float occ = 0.0;
    float sca = 1.0;
    for (int i = 0; i < 5; i++)
    {
        float h = 0.02 + 0.04 * float(i);
        occ += (h - map(p + n * h)) * sca;
        sca *= 0.8;
    }
    return clamp(1.0 - 3.0 * occ, 0.0, 1.0);
}

vec2 skyUV(vec3 rd)
{
    return vec2(atan(rd.z, rd.x) / TAU + 0.5, acos(clamp(rd.y, -1.0, 1.0)) / PI);
}

vec3 env(vec3 rd)
{
    return texture(iChannel0, skyUV(rd)).rgb;
}

vec3 blurryEnv(vec3 rd)
{
    return texture(iChannel0, skyUV(rd), 4.0).rgb;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec2 mo = iMouse.xy / iResolution.xy;

    float an = 2.0 + TAU * mo.x;
    vec3 ro = vec3(2.4 * cos(an), 0.6 + mo.y, 2.4 * sin(an));
    vec3 ta = vec3(0.0, -0.15, 0.0);
    vec3 ww = normalize(ta - ro);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    vec3 rd = normalize(uv.x * uu + uv.y * vv + 2.0 * ww);

    vec3 col = env(rd) * 0.8;

    float t = intersect(ro, rd);
    if (t > 0.0)
    {
        vec3 p = ro + rd * t;
        vec3 n = calcNormal(p);
        vec3 r = reflect(rd, n);
        float occ = calcAO(p, n);

        vec3 stone = vec3(0.25, 0.24, 0.23) * (0.4 + 0.6 * occ);
        float dif = clamp(dot(n, normalize(vec3(0.3, 1.0, 0.2))), 0.0, 1.0);
        float fre = 0.04 + 0.96 * pow(clamp(1.0 + dot(rd, n), 0.0, 1.0), 5.0);

        col = stone * (0.3 + 0.9 * dif);
        col += fre * occ * blurryEnv(r);
    }

    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
