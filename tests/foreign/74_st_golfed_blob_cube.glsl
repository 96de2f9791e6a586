// Imitates: golfed metaball shaders (Reinder Nijhoff's [SH17A] Metaballs and its kind): the point
// marched by a distance computed in a loop nested in the march (a smooth minimum over the balls,
// started from a floor), and the last point used as a direction into a cube map,
// `f = texture(iChannel0, p)`.
//
// Issue 47, two classes at once: the field is the march's own body with its inner loop (a point
// march, `p += r*s`), and iChannel0 is a cube map (read with a vec3), which does not compile as a
// sampler2D.
//
// Why the audit should find it clean: the floor y = -1.5 blended by a polynomial smooth minimum
// (k = 0.25) with three balls (radius 0.35 at x = -0.8, 0, 0.8). A smooth minimum of exact
// distances is 1-Lipschitz and never above the distance: a conservative bound. Nothing reads iTime.
// expect: entry=mainImage flags=none animated=no

void mainImage(out vec4 f, vec2 g) {
    vec3 n = iResolution, r = vec3(g, n.y) / n.y - vec3(.5 * n.x / n.y, .5, 0), p = n - n;
    p.z -= 4.;
    r = normalize(r);
    for (int i = 80; i-- > 0;) {
        float s = p.y + 1.5, b, h;
        for (int j = 0; j < 3; j++)
            b = length(p - vec3(float(j) * .8 - .8, 0, 0)) - .35,
            h = clamp(.5 + .5 * (b - s) / .25, 0., 1.),
            s = mix(b, s, h) - .25 * h * (1. - h);
        p += r * s;
    }
    f = texture(iChannel0, p) * 2. / dot(p, p);
}
