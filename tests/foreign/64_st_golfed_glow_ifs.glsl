// Imitates: a golfed "twigl"-style glow shader as they circulate on Shadertoy: one-letter names,
// every float declared in the for loop's header, the camera at the origin (`vec3 p = g * d;`
// then `p.z -= 3.;` and a turn by iTime), three folds of an IFS (a lattice of 8 x 8 x 8 balls)
// inside the step, and the step and the field in one statement, `g += e = ...`. Colour piles up by exp(-e * e) each step; no
// surface is ever shaded.
//
// Issue 47, the field written inline in the golfed style: the counter is g, the point p, the
// field what g grows by. The statements right after `vec3 p = g * d;` that only move and turn p
// place the camera, so the point is set after them: the fractal sits at the origin, not 3 units
// in front of it.
//
// Why the audit should find it clean: the folds (abs, then a uniform scale by 2 and a shift) are
// undone in scale by dividing the ball's distance by s, the product of the scales, and abs() only
// brings points nearer, so the step is a conservative bound: 1-Lipschitz, below the distance.
// iTime turns the scene.
// expect: entry=mainImage flags=none animated=yes

mat2 rot(float a) { float c = cos(a), s = sin(a); return mat2(c, -s, s, c); }

void mainImage(out vec4 O, vec2 C) {
    O = vec4(0);
    vec3 r = iResolution, d = normalize(vec3((C - .5 * r.xy) / r.y, 1));
    for (float i = 0., g = 0., e, s; ++i < 90.;) {
        vec3 p = g * d;
        p.z -= 3.;
        p.xz *= rot(iTime * .3);
        s = 1.;
        for (int j = 0; j++ < 3; p = abs(p) * 2. - vec3(.8, .7, .8)) s *= 2.;
        g += e = (length(p) - .6) / s;
        O.rgb += .015 * vec3(1, .6, .3) / exp(e * e * 3e3);
    }
}
