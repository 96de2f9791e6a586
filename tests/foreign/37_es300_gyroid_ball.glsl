#version 300 es
#extension GL_OES_standard_derivatives : enable
precision highp float;
precision highp int;

// Imitates: a Shadertoy-style shader that went through WebGL ports and
// carries their headers: `#version 300 es`, an #extension line left over
// from WebGL 1 (GL_OES_standard_derivatives), precision statements for
// float and int, texture2D() in the shading (a WebGL 1 habit; GLSL ES 3.00
// and core GLSL call it texture()), dFdx()/dFdy() for a flat-shaded
// normal, and the Shadertoy inputs iTime, iResolution and iChannel0 used
// undeclared. The scene is the usual gyroid sponge cut by a ball, in
// `float map(vec3 p)`, the gyroid turning with iTime.
//
// Why the audit should find it clean: the gyroid g(q) = dot(sin(q),
// cos(q.zxy)) has |grad g| up to sqrt(3) (at q = 0: every partial is 1),
// and the shell term 0.55*|g(s p)|/s - 0.02 has the gradient 0.55*grad g,
// so |grad| <= 0.55*sqrt(3) = 0.95: the author's 0.55 makes it a bound.
// abs() and max() keep that and keep it continuous; the ball term is
// exact and dominates outside the ball (the shell term is at most
// 0.55*1.5/6 = 0.14), so the field grows outside; no NaN. The rotation by
// iTime is an isometry, but it makes the field time-dependent: animated.
// expect: entry=map flags=none animated=yes

#define SCALE 6.0

mat2 rot(float a)
{
    float c = cos(a), s = sin(a);
    return mat2(c, -s, s, c);
}

float gyroid(vec3 p)
{
    return dot(sin(p), cos(p.zxy));
}

float map(vec3 p)
{
    float ball = length(p) - 0.85;
    vec3 q = p;
    q.xz *= rot(0.3 * iTime);
    float shell = 0.55 * abs(gyroid(q * SCALE)) / SCALE - 0.02;
    return max(ball, shell);
}

float march(vec3 ro, vec3 rd)
{
    float t = 0.0;
    for (int i = 0; i < 160; i++)
    {
        float d = map(ro + rd * t);
        if (d < 0.0005) return t;
        t += d;
        if (t > 12.0) break;
    }
    return -1.0;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(0.0, 0.6, 2.6);
    vec3 ta = vec3(0.0);
    vec3 f = normalize(ta - ro);
    vec3 r = normalize(cross(f, vec3(0.0, 1.0, 0.0)));
    vec3 u = cross(r, f);
    vec3 rd = normalize(uv.x * r + uv.y * u + 1.8 * f);

    vec3 col = vec3(0.1, 0.12, 0.15);
    float t = march(ro, rd);
    if (t > 0.0)
    {
        vec3 pos = ro + rd * t;
        // flat normal from screen-space derivatives (needs the extension in WebGL 1)
        vec3 nor = normalize(cross(dFdx(pos), dFdy(pos)));
        if (dot(nor, rd) > 0.0) nor = -nor;
        vec3 lig = normalize(vec3(0.5, 0.8, 0.6));
        float dif = max(dot(nor, lig), 0.0);
        vec3 alb = mix(vec3(0.9, 0.5, 0.2), vec3(0.2, 0.6, 0.9), smoothstep(0.6, 0.85, length(pos)));
        col = alb * (0.15 + 0.85 * dif);
    }

    // film grain from the noise texture, WebGL 1 style
    vec3 grain = texture2D(iChannel0, fragCoord / 256.0).rgb;
    col += (grain - 0.5) * 0.04;

    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
