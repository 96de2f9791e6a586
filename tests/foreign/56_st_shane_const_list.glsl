// Imitates: a whole Shadertoy in the style of Shane's heavily commented
// shaders: constants declared together, `const float EPS = 1e-3, FAR =
// 40.0, TAU = 6.2831853;`, `mat2 rot2(in float a)`, `float map(vec3 p)`
// with polar repetition (`mod(atan(p.z, p.x), TAU/N)`), `trace()` that
// steps by `d*.9`, `getNormal()`, `softShadow(ro, lp, k)`, `calcAO()`,
// a point light with attenuation, and a camera swung with iMouse: a
// carousel (a centre pole, a roof disc, a base disc, and eight seats, each
// a ball on a pole hanging from the roof).
//
// Issue 47, class 3: `TAU`, and `FAR` and `EPS` before it, are declared in
// one `const float` comma list; the map uses TAU for the repetition angle.
// sdfwb must see all three as the file's own names (and TAU as a
// constant it may fold), not only the first.
//
// Why the audit should find it clean: pole and discs are exact capped
// cylinders, the seats exact spheres and capped cylinders. The polar
// repetition folds space into a 45-degree sector; each seat lies inside
// its sector (a ball of 0.11 at radius 0.45 spans 14 degrees of the 22.5 to
// either side of the sector's middle) and is symmetric about the middle
// plane, so the folded distance is the distance to the nearest seat:
// exact, and continuous across the sector borders (both sides see the
// same mirrored seat) and on the axis (every seat equally far). Joined
// with min(); the poles meet the roof, the centre pole the discs, in
// concave creases that the audit's per-axis differences read at most
// ~1.04. Finite (atan(0, 0) only on the axis, where the result does not
// depend on it), within 0.7 of the axis and -0.65 <= y <= 0.59: grows
// outside. No iTime anywhere (the camera follows iMouse): not animated.
// expect: entry=map flags=none animated=no

const float EPS = 1e-3, FAR = 40.0, TAU = 6.2831853;

// Standard 2D rotation formula.
mat2 rot2(in float a){ float c = cos(a), s = sin(a); return mat2(c, s, -s, c); }

// A cylinder standing on the y axis: radius r, half height h.
float sCyl(vec3 p, float r, float h){
    vec2 d = abs(vec2(length(p.xz), p.y)) - vec2(r, h);
    return min(max(d.x, d.y), 0.) + length(max(d, 0.));
}

// The scene. Nothing fancy: a centre pole, two discs, and eight seats
// arranged about the y axis with polar repetition, which is about as
// cheap as it gets: one seat's worth of maths for eight seats.
float map(vec3 p){

    // Centre pole, roof and base.
    float pole = sCyl(p, .07, .55);
    float roof = sCyl(p - vec3(0, .55, 0), .7, .04);
    float base = sCyl(p - vec3(0, -.6, 0), .6, .05);

    // Polar repetition: fold the angle into one of eight sectors, then
    // put the sector's middle on the positive x axis.
    const float N = 8.;
    float a = mod(atan(p.z, p.x), TAU/N) - TAU/N*.5;
    vec3 q = vec3(cos(a)*length(p.xz), p.y, sin(a)*length(p.xz));
    q.x -= .45;

    // A seat: a ball hanging from the roof on a thin pole.
    float seat = length(q - vec3(0, -.05, 0)) - .11;
    seat = min(seat, sCyl(q - vec3(0, .23, 0), .015, .28));

    return min(min(pole, seat), min(roof, base));
}

// Basic raymarcher.
float trace(in vec3 ro, in vec3 rd){

    float t = 0., d;

    for (int i = 0; i<128; i++){

        d = map(ro + rd*t);

        // Irregularities between browsers have forced me to use this logic. I
        // don't like it, but it works.
        if(abs(d)<EPS*(t*.125 + 1.) || t>FAR) break;

        t += d*.9;  // Using more accuracy, in the first pass.
    }

    return min(t, FAR);
}

// Standard normal function.
vec3 getNormal(in vec3 p){
    const vec2 e = vec2(.002, 0);
    return normalize(vec3(map(p + e.xyy) - map(p - e.xyy), map(p + e.yxy) - map(p - e.yxy),
                          map(p + e.yyx) - map(p - e.yyx)));
}

// The usual soft shadow routine: march towards the light, keep the
// closest near-miss.
float softShadow(vec3 ro, vec3 lp, float k){

    const int maxIterationsShad = 24;

    vec3 rd = lp - ro; // Unnormalized direction ray.

    float shade = 1.;
    float dist = .002;
    float end = max(length(rd), .001);
    float stepDist = end/float(maxIterationsShad);

    rd /= end;

    for (int i = 0; i<maxIterationsShad; i++){

        float h = map(ro + rd*dist);
        shade = min(shade, smoothstep(0., 1., k*h/dist));
        dist += clamp(h, .02, stepDist*2.);

        if (h<0. || dist>end) break;
    }

    return min(max(shade, 0.) + .2, 1.);
}

// Ambient occlusion, five taps along the normal.
float calcAO(in vec3 p, in vec3 n){

    float sca = 3., occ = 0.;
    for(int i = 0; i<5; i++){

        float hr = float(i + 1)*.15/5.;
        float d = map(p + n*hr);
        occ += (hr - d)*sca;
        sca *= .7;
    }

    return clamp(1. - occ, 0., 1.);
}

void mainImage( out vec4 fragColor, in vec2 fragCoord ){

    // Screen coordinates.
    vec2 uv = (fragCoord - iResolution.xy*.5)/iResolution.y;

    // Camera: swung about the carousel by the mouse.
    float ang = .4 + iMouse.x/iResolution.x*TAU;
    vec3 ro = vec3(2.4*sin(ang), .9, -2.4*cos(ang));
    vec3 lk = vec3(0, -.05, 0);
    vec3 lp = ro + vec3(.5, 1.5, .5); // Light, just above and to the side of the camera.

    // Unit direction ray vectors.
    float FOV = 1.; // FOV - Field of view.
    vec3 fwd = normalize(lk - ro);
    vec3 rgt = normalize(vec3(fwd.z, 0., -fwd.x));
    vec3 up = cross(fwd, rgt);
    vec3 rd = normalize(fwd + FOV*uv.x*rgt + FOV*uv.y*up);

    // Background.
    vec3 sceneCol = vec3(.08, .06, .05);

    float t = trace(ro, rd);

    if(t<FAR){

        vec3 sp = ro + rd*t;
        vec3 sn = getNormal(sp);
        vec3 ld = lp - sp;
        float lDist = max(length(ld), .001);
        ld /= lDist;

        float atten = 1./(1. + lDist*.05 + lDist*lDist*.025);

        float sh = softShadow(sp + sn*.002, lp, 12.);
        float ao = calcAO(sp, sn);

        float diff = max(dot(sn, ld), 0.);
        float spec = pow(max(dot(reflect(-ld, sn), -rd), 0.), 16.);

        // Stripes on the roof and base, brass poles, red seats.
        vec3 oCol = vec3(.8, .6, .3);
        if(length(sp.xz)>.3 && abs(sp.y + .05)<.15) oCol = vec3(.8, .15, .1);
        if(abs(sp.y)>.5) oCol = mix(vec3(.9), vec3(.8, .1, .1), step(.5, fract(atan(sp.z, sp.x)/TAU*16.)));

        sceneCol = oCol*(diff + .2) + vec3(1, .9, .7)*spec*.5;
        sceneCol *= ao*sh*atten*2.;
    }

    fragColor = vec4(sqrt(clamp(sceneCol, 0., 1.)), 1);
}
