// Imitates: a whole Shadertoy in the style of The Art of Code (Martijn
// Steinrucken, "BigWings") ray marching tutorials: `#define MAX_STEPS 100`,
// `#define MAX_DIST 100.`, `#define SURF_DIST .01`, `float GetDist(vec3 p)`
// built from his primitives (sdCapsule and sdCylinder between two points,
// sdTorus with a vec2 of radii, sdBox, a sphere) and rotated with a
// `mat2 Rot(float a)`, `float RayMarch(vec3 ro, vec3 rd)` with
// `float dO=0.` and `dO += dS`, GetNormal() as `d - vec3(GetDist(p-e.xyy),
// ...)`, GetLight() with the shadow ray cast by RayMarch again, a light
// circling with iTime. His ground plane (`p.y`) is left out, as an endless
// plane would leave the cube: the shapes stand on a bounded plinth (a flat
// box) instead.
//
// Issue 47, class 1: the distance function is GetDist, not a conventional
// name; sdfwb must find it from RayMarch's loop (called from mainImage and
// from GetLight), where `float dS = GetDist(p)` and `dO += dS` advance the
// ray.
//
// Why the audit should find it clean: every primitive is an exact distance
// (the capsule and the cylinder between points, the torus, the box with
// its inside term, the sphere), the box turns with iTime by a rotation
// (an isometry), and they are joined by min(). The shapes stand on the
// plinth (capsule, torus and cylinder touch its top along a point, a
// circle and a line; the box's bottom face lies on it), so the union has
// concave creases, where the audit's per-axis central differences read at
// most ~1.04, under 1.05. Continuous, finite; everything within
// |x| <= 0.78, -0.62 <= y <= 0.5, |z| <= 0.6, so the field grows outside:
// no flag. iTime in the map (the box) and in the light: animated.
// expect: entry=GetDist flags=none animated=yes

#define MAX_STEPS 100
#define MAX_DIST 100.
#define SURF_DIST .01

mat2 Rot(float a) {
    float s = sin(a), c = cos(a);
    return mat2(c, -s, s, c);
}

float sdCapsule(vec3 p, vec3 a, vec3 b, float r) {
    vec3 ab = b-a;
    vec3 ap = p-a;

    float t = dot(ab, ap) / dot(ab, ab);
    t = clamp(t, 0., 1.);

    vec3 c = a + t*ab;

    return length(p-c)-r;
}

float sdCylinder(vec3 p, vec3 a, vec3 b, float r) {
    vec3 ab = b-a;
    vec3 ap = p-a;

    float t = dot(ab, ap) / dot(ab, ab);
    vec3 c = a + t*ab;

    float x = length(p-c)-r;
    float y = (abs(t-.5)-.5)*length(ab);
    float e = length(max(vec2(x, y), 0.));
    float i = min(max(x, y), 0.);

    return e+i;
}

float sdTorus(vec3 p, vec2 r) {
    float x = length(p.xz)-r.x;
    return length(vec2(x, p.y))-r.y;
}

float sdBox(vec3 p, vec3 s) {
    p = abs(p)-s;
    return length(max(p, 0.))+min(max(p.x, max(p.y, p.z)), 0.);
}

float GetDist(vec3 p) {
    float plinth = sdBox(p-vec3(0, -.56, 0), vec3(.78, .06, .6));

    float sd = length(p-vec3(0, .25, 0))-.25;

    float cd = sdCapsule(p, vec3(-.55, -.38, -.25), vec3(-.2, .05, -.3), .12);

    float td = sdTorus(p-vec3(.45, -.44, -.2), vec2(.2, .06));

    vec3 bp = p-vec3(-.4, -.32, .3);
    bp.xz *= Rot(iTime);
    float bd = sdBox(bp, vec3(.18));

    float cyld = sdCylinder(p, vec3(.1, -.38, .35), vec3(.6, -.38, .25), .12);

    float d = min(sd, plinth);
    d = min(d, cd);
    d = min(d, td);
    d = min(d, bd);
    d = min(d, cyld);

    return d;
}

float RayMarch(vec3 ro, vec3 rd) {
    float dO=0.;

    for(int i=0; i<MAX_STEPS; i++) {
        vec3 p = ro + rd*dO;
        float dS = GetDist(p);
        dO += dS;
        if(dO>MAX_DIST || dS<SURF_DIST) break;
    }

    return dO;
}

vec3 GetNormal(vec3 p) {
    float d = GetDist(p);
    vec2 e = vec2(.001, 0);

    vec3 n = d - vec3(
        GetDist(p-e.xyy),
        GetDist(p-e.yxy),
        GetDist(p-e.yyx));

    return normalize(n);
}

float GetLight(vec3 p) {
    vec3 lightPos = vec3(0, 2.5, -1.5);
    lightPos.xz += vec2(sin(iTime), cos(iTime))*1.5;
    vec3 l = normalize(lightPos-p);
    vec3 n = GetNormal(p);

    float dif = clamp(dot(n, l), 0., 1.);
    float d = RayMarch(p+n*SURF_DIST*2., l);
    if(d<length(lightPos-p)) dif *= .1;

    return dif;
}

void mainImage( out vec4 fragColor, in vec2 fragCoord )
{
    vec2 uv = (fragCoord-.5*iResolution.xy)/iResolution.y;

    vec3 col = vec3(0);

    vec3 ro = vec3(0, .7, -2.8);
    vec3 rd = normalize(vec3(uv.x, uv.y-.25, 1));

    float d = RayMarch(ro, rd);

    if(d<MAX_DIST) {
        vec3 p = ro + rd * d;

        float dif = GetLight(p);
        col = vec3(dif)*.9+.05;
    }

    col = pow(col, vec3(.4545));	// gamma correction

    fragColor = vec4(col,1.0);
}
