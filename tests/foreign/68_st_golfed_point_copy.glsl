// Imitates: a golfed glow that marches the point and copies it in one statement, `p = c += e * d;`
// at the top of the loop, folds the copy into a twisted column of rings and computes the next step
// `e` after it; colour piles up from exp(-e).
//
// Issue 47, the point marched by a float computed after the step: the body run once sets the
// marched point, keeps the copy (`p = c;`) and returns e at the body's end.
//
// Why the audit should find it clean: a torus (radii 0.5 and 0.12) in each cell of a vertical
// repetition of period 0.6, cut to |y| < 0.9 by max(): a repeated exact distance whose cells hold
// one torus each, and the cut keeps it a bound. Nothing reads iTime.
// expect: entry=mainImage flags=none animated=no

void mainImage(out vec4 O, vec2 C) {
    O = vec4(0);
    vec3 R = iResolution, c = vec3(0, 0, -3), p, d = normalize(vec3((C - .5 * R.xy) / R.y, 1));
    float e = 0.;
    for (float i = 0.; i++ < 90.;) {
        p = c += e * d;
        p.y = mod(p.y + .3, .6) - .3;
        e = max(length(vec2(length(p.xz) - .5, p.y)) - .12, abs(c.y) - .9);
        O.rgb += .02 * vec3(.4, .7, 1) / exp(e * 40.);
    }
}
