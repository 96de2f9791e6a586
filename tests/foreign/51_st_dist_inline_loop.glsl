// Imitates: a whole beginner's first-raymarcher Shadertoy, everything in
// mainImage: `float dist(vec3 p)` (a ball with animated sine ripples), the
// march written straight into mainImage as a bare `for` loop with
// `t += dist(ro + rd*t);` and no early exit, the hit decided afterwards
// (`if (dist(p) < .01)`), a `getNormal()` by central differences, diffuse,
// Blinn specular and a Fresnel-ish rim, and the usual
// `(fragCoord - .5*iResolution.xy)/iResolution.y` with a fixed camera.
//
// Issue 47, class 1: the distance function is `dist`, not a conventional
// name, and no helper holds the march: sdfwb must find it from the loop in
// mainImage itself, where `t += dist(ro + rd*t)` advances the ray.
//
// Why non-conservative: the ripple term 0.07 sin(24x + 2 iTime) sin(24y)
// sin(24z) has partial derivatives up to 0.07 x 24 = 1.68; its gradient's
// length is ~1 at a typical point of the cube (rms over the phases) and
// 1.68 at most, added to the ball's unit gradient in all directions, so
// |grad f| (up to ~2.7) exceeds 1.05 over most of the cube, at every
// iTime (the phase only shifts the ripples): the 99.9th percentile is
// ~2.5. (The author's marcher overshoots and shows it as specks;
// beginners live with it.) Smooth, finite, and the ball's term grows
// outside (the ripples are at most 0.07 high and the ball's radius
// 0.55 + 0.07 fits the cube): no other flag. iTime in the map: animated.
// expect: entry=dist flags=non-conservative animated=yes

float dist(vec3 p) {
    float d = length(p) - .55;
    d += .07 * sin(24. * p.x + iTime * 2.) * sin(24. * p.y) * sin(24. * p.z);
    return d;
}

vec3 getNormal(vec3 p) {
    vec2 e = vec2(.001, 0.);
    return normalize(vec3(
        dist(p + e.xyy) - dist(p - e.xyy),
        dist(p + e.yxy) - dist(p - e.yxy),
        dist(p + e.yyx) - dist(p - e.yyx)));
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (fragCoord - .5 * iResolution.xy) / iResolution.y;

    vec3 ro = vec3(0., 0., -2.5);
    vec3 rd = normalize(vec3(uv, 1.4));

    // march!
    float t = 0.;
    for (int i = 0; i < 90; i++) {
        t += dist(ro + rd * t);
    }

    vec3 col = vec3(.1, .12, .2) * (1. - .5 * length(uv));

    vec3 p = ro + rd * t;
    if (dist(p) < .01) {
        vec3 n = getNormal(p);
        vec3 light = normalize(vec3(1., 1., -1.));
        float diff = max(dot(n, light), 0.);
        vec3 h = normalize(light - rd);
        float spec = pow(max(dot(n, h), 0.), 32.);
        float fres = pow(1. + dot(rd, n), 3.);
        col = vec3(.9, .3, .5) * (diff * .8 + .15) + spec * .6 + fres * vec3(.3, .5, 1.);
    }

    col = pow(col, vec3(.4545));
    fragColor = vec4(col, 1.);
}
