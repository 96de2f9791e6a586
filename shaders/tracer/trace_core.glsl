// Sphere tracer core: uniforms, ray set-up, marching, normals. Composed after the SDF and the
// composer's sdfwb_sdf() wrapper around the file's entry point;
// a shading piece, optional feature pieces (ao.glsl, ...) and trace_main.frag follow.
// Feature defines: SDFWB_ANIMATED / SDFWB_USES_TIME (time), SDFWB_OVERRELAX (relaxed steps).

// The march debugger's hooks (probe.glsl defines them; without SDFWB_PROBE they are nothing).
#ifndef SDFWB_PROBE
#define SDFWB_RECORD(kind, t, position, d)
#endif

// The pixel's centre in framebuffer coordinates (gl_FragCoord.xy in the fragment tracer; the
// compute tracer, SDFWB_COMPUTE in trace_main.frag, sets it per invocation).
#ifdef SDFWB_COMPUTE
vec2 sdfwb_computePixel;
#define SDFWB_PIXEL_CENTRE sdfwb_computePixel
#else
#define SDFWB_PIXEL_CENTRE gl_FragCoord.xy
#endif

uniform vec2 sdfwb_resolution;        // framebuffer size in pixels
uniform vec3 sdfwb_cameraPosition;
uniform vec3 sdfwb_cameraRight;       // unit camera basis
uniform vec3 sdfwb_cameraUp;
uniform vec3 sdfwb_cameraForward;
uniform float sdfwb_tanHalfFovY;      // tan(vertical field of view / 2)
uniform float sdfwb_nearPlane;
uniform float sdfwb_farPlane;
uniform int sdfwb_maxSteps;           // step budget per ray
#ifdef SDFWB_STEP_FACTOR
uniform float sdfwb_stepFactor;       // < 1 for fields that are not 1-Lipschitz
#define SDFWB_SCALED(f) ((f) * sdfwb_stepFactor)
#define SDFWB_UNSCALED(d) ((d) / sdfwb_stepFactor)
#else
// Step factor 1 (the default) is a variant of its own: on llvmpipe even one multiply a step costs
// a cheap SDF's frame a few per cent.
#define SDFWB_SCALED(f) (f)
#define SDFWB_UNSCALED(d) (d)
#endif
uniform float sdfwb_epsilonScale;     // hit when |f| < epsilonScale * pixel footprint at t
uniform float sdfwb_boxMargin;        // rays are clipped to [-1-margin, 1+margin]^3
uniform vec3 sdfwb_background;
#ifdef SDFWB_OVERRELAX
uniform float sdfwb_relaxation;       // over-relaxation factor omega in (1, 2)
#endif
#ifdef SDFWB_PLANE_CLIP
uniform vec3 sdfwb_clipNormal;   // the cutting plane; the side it points to is cut away
uniform float sdfwb_clipOffset;
// The traced scene: the shape intersected with the half-space behind the plane (a conservative
// bound), so the cross-section shows.
float sdfwb_sceneMap(vec3 p) { return max(sdfwb_sdf(p), dot(p, sdfwb_clipNormal) - sdfwb_clipOffset); }
#else
float sdfwb_sceneMap(vec3 p) { return sdfwb_sdf(p); }
#endif

#ifdef SDFWB_PLANE_FIELD
// A mesh's own field on the cutting plane, computed once per plane (SdfRenderer, on the CPU
// engine) instead of a whole field's walks per pixel and frame: a square of the plane covering
// the box, texel (i, j) holding f, |f| and the winding number at origin + i * step * u + j * step * v.
uniform sampler2D sdfwb_planeField;
uniform vec3 sdfwb_planeFieldOrigin;
uniform vec3 sdfwb_planeFieldU;        // u / (step * size): a point's texture coordinate along u
uniform vec3 sdfwb_planeFieldV;
uniform float sdfwb_planeFieldHalfTexel; // 0.5 / size: texel centres sit on the grid points

// f and the winding number at plane point p. Bilinear f, except across an open mesh's sign jump
// (f from -d to +d without a zero), where interpolating f would draw a zero line that the field
// does not have: there |f| is interpolated and the nearest grid point gives the sign.
vec2 sdfwb_planeFieldAt(vec3 p) {
    vec3 d = p - sdfwb_planeFieldOrigin;
    vec2 uv = vec2(dot(d, sdfwb_planeFieldU), dot(d, sdfwb_planeFieldV)) + sdfwb_planeFieldHalfTexel;
    vec4 field = texture(sdfwb_planeField, uv);
    float f = field.r;
    if (abs(f) < 0.5 * field.g) {
        float nearestSign = texelFetch(sdfwb_planeField, ivec2(uv * vec2(textureSize(sdfwb_planeField, 0))), 0).r;
        f = nearestSign < 0.0 ? -field.g : field.g;
    }
    return vec2(f, field.b);
}
#endif

// Why a ray ended: a hit, or one of three honest kinds of miss.
const int sdfwb_kRayHit = 0;
const int sdfwb_kRayLeftBox = 1;    // passed the far side of the box (or the far plane): nothing there
const int sdfwb_kRayOutOfSteps = 2; // the step budget ran out before |f| fell below the tolerance
const int sdfwb_kRayNotFinite = 3;  // f was NaN or Inf along the ray

struct sdfwb_Hit {
    bool found;
    float t;        // distance along the ray
    int steps;      // steps taken (the budget when it ran out)
    vec3 position;
    int status;     // sdfwb_kRayHit, sdfwb_kRayLeftBox, sdfwb_kRayOutOfSteps or sdfwb_kRayNotFinite
    float value;    // f at position (a hit's; the normal's taps are measured against it)
};

// Angle one pixel spans: hit tolerances and normal steps grow with distance like a pixel's footprint.
float sdfwb_pixelAngle() { return 2.0 * sdfwb_tanHalfFovY / sdfwb_resolution.y; }

vec3 sdfwb_primaryRay(vec2 fragment) {
    vec2 ndc = (fragment / sdfwb_resolution) * 2.0 - 1.0;
    float aspect = sdfwb_resolution.x / sdfwb_resolution.y;
    return normalize(sdfwb_cameraForward + ndc.x * aspect * sdfwb_tanHalfFovY * sdfwb_cameraRight + ndc.y * sdfwb_tanHalfFovY * sdfwb_cameraUp);
}

// The cone pass (SDFWB_CONES): before the picture, one ray per tile of sdfwb_coneTile^2 pixels
// marches a cone that holds every pixel ray of its tile, and stops where the cone comes near the
// surface; its pixels then start marching there (sdfwb_coneStart) instead of at the box. A step
// d - r from a point where the cone's radius is r cannot carry any ray of the cone through the
// surface; the cone takes plain steps d while d >= 2r, which the next point's sphere covers (the
// part of a ray's step that one sphere misses is within r of the next centre, whose sphere has
// radius >= 2r), and its pixels may start r before the point where it stopped. Not in the march
// debugger's program or the step heat map's, which show every step of a pixel's own march.
#ifdef SDFWB_CONES
uniform int sdfwb_coneTile;         // tile size in pixels
uniform bool sdfwb_conePass;        // this draw is the cone pass (one fragment per tile)
uniform sampler2D sdfwb_coneStarts; // the cone pass's result, packed (sdfwb_packConeStart)
uniform float sdfwb_coneRange;      // past every point of the box seen from the camera
#define SDFWB_CONE_PASS sdfwb_conePass

// A cone's radius per unit of t: half the tile's diagonal in the image plane at distance 1 (the
// angle between two rays is at most their points' distance there, since both lie at least 1 away).
float sdfwb_coneSlope() { return 0.7072 * float(sdfwb_coneTile) * sdfwb_pixelAngle(); }

// Where the cone's pixels may start from its march's end: r before a stop or a spent budget;
// past the box (sdfwb_coneRange) when the cone left it; at their own start (0) when the field
// was negative or not finite there (the cone began inside the shape or the field is broken).
float sdfwb_coneEnd(int status, float t, float d) {
    if (status == sdfwb_kRayLeftBox) return sdfwb_coneRange;
    if (status == sdfwb_kRayNotFinite || !(d >= 0.0)) return 0.0;
    return t * (1.0 - sdfwb_coneSlope());
}

// 24 bits of t / range in the colour channels, rounded down (a start is never later than the
// cone allowed): what a framebuffer of any colour format holds.
vec4 sdfwb_packConeStart(float t) {
    uint code = uint(clamp(t / sdfwb_coneRange, 0.0, 1.0) * 16777215.0);
    code = code > 0u ? code - 1u : 0u;
    return vec4(float(code >> 16u), float((code >> 8u) & 255u), float(code & 255u), 255.0) / 255.0;
}

// Where this pixel's march may start: its tile's cone start (past its box when the cone left it).
float sdfwb_coneStart() {
    uvec3 bytes = uvec3(texelFetch(sdfwb_coneStarts, ivec2(SDFWB_PIXEL_CENTRE) / sdfwb_coneTile, 0).rgb * 255.0 + 0.5);
    uint code = (bytes.r << 16u) | (bytes.g << 8u) | bytes.b;
    return code >= 16777214u ? 1e30 : float(code) * (sdfwb_coneRange / 16777215.0);
}
#else
#define SDFWB_CONE_PASS false
#endif

// One ray's march: s counts from the box entry point (far from the origin, a camera at 1e4,
// the ray parameter t is ~1e4 and float32 cannot add steps below ~1e-3 to it), and the state of
// over-relaxed sphere tracing (step omega * d while consecutive unbounding spheres overlap; when
// they do not, the step may have passed the surface: go back and continue with omega = 1).
struct sdfwb_March {
    float tStart;      // t at the box entry
    vec3 entry;        // the entry point
    float s;           // distance marched from the entry
    float sEnd;        // where the ray leaves the box (or passes the far plane)
    float footprint;   // hit when |d| < footprint * t
    float omega;
    float previousRadius;
    float stepLength;
};

// Clips the ray to the box and the near and far planes; false when nothing of it is left.
// In the cone pass a "hit" is a value below twice the cone's radius, and the box grows by twice
// the cone's widest radius in it: the cone enters the grown box before any of its rays enter the
// box, and once it has left it all of them have, even in the last step, which its sphere covers
// only to within one radius of where it lands.
bool sdfwb_startMarch(vec3 origin, vec3 direction, out sdfwb_March march) {
    float box = 1.0 + sdfwb_boxMargin;
    float tFrom = sdfwb_nearPlane;
    march.footprint = sdfwb_epsilonScale * sdfwb_pixelAngle();
#ifdef SDFWB_OVERRELAX
    march.omega = sdfwb_relaxation;
#else
    march.omega = 1.0;
#endif
#ifdef SDFWB_CONES
    if (sdfwb_conePass) {
        march.footprint = 2.0 * sdfwb_coneSlope();
        box += 2.0 * sdfwb_coneSlope() * sdfwb_coneRange;
        march.omega = 1.0;
    } else {
        tFrom = max(tFrom, sdfwb_coneStart());
    }
#endif
    vec2 span = sdfwb_intersectBox(origin, direction, box);
    march.tStart = max(span.x, tFrom);
    float tEnd = min(span.y, sdfwb_farPlane);
    march.entry = origin + march.tStart * direction;
    march.s = 0.0;
    march.sEnd = tEnd - march.tStart;
    march.previousRadius = 0.0;
    march.stepLength = 0.0;
    return march.tStart <= tEnd;
}

// What one evaluation of the march did with the scaled value d at entry + s * direction.
const int sdfwb_kMarchStep = 0;
const int sdfwb_kMarchRelaxedStep = 1;
const int sdfwb_kMarchFallback = 2; // the relaxed step went too far: s went back, omega is 1 now
const int sdfwb_kMarchHit = 3;      // |d| is below the footprint: s stays

int sdfwb_marchStep(inout sdfwb_March march, float d) {
    float radius = abs(d);
#ifdef SDFWB_OVERRELAX
    // Fall back when the spheres do not overlap, or when the step crossed the surface (d < 0).
    if (march.omega > 1.0 && (radius + march.previousRadius < march.stepLength || d < 0.0)) {
        march.s -= march.stepLength - march.stepLength / march.omega; // undo the relaxed part of the last step
        march.omega = 1.0;
        march.previousRadius = 0.0;
        march.stepLength = 0.0;
        return sdfwb_kMarchFallback;
    }
#endif
    if (radius < march.footprint * (march.tStart + march.s)) return sdfwb_kMarchHit;
#ifdef SDFWB_OVERRELAX
    int kind = march.omega > 1.0 ? sdfwb_kMarchRelaxedStep : sdfwb_kMarchStep;
    march.stepLength = d * march.omega;
    march.previousRadius = radius;
    march.s += march.stepLength;
    return kind;
#else
    march.s += d;
    return sdfwb_kMarchStep;
#endif
}

// The refining steps after a hit: up to two more plain steps from the value the march stopped at,
// each evaluated where it lands and kept only when |f| shrank there: for a field steeper than the
// step factor assumes (or a broken one) a step would overshoot, and the hit stays where it was,
// within its tolerance. For exact fields each kept step takes the error down by 1 - cos of the
// angle between the ray and the surface's normal (the tests in tests/renderer/test_hit_error_gl.cpp
// bound what the two leave). A second step left unevaluated would cost nothing, but on fields
// that are not linear along the ray (fractals) it lands where |f| may exceed the tolerance.
const int sdfwb_kRefiningSteps = 2;
bool sdfwb_refineKeeps(float d, float next) { return abs(next) < abs(d); }

#ifdef SDFWB_PROBE
// The march debugger's event for what a march evaluation did.
int sdfwb_probeKindOf(int event) {
    return event == sdfwb_kMarchHit ? sdfwb_kProbeHit
         : event == sdfwb_kMarchFallback ? sdfwb_kProbeFallback
         : event == sdfwb_kMarchRelaxedStep ? sdfwb_kProbeRelaxedStep : sdfwb_kProbeStep;
}
#endif

sdfwb_Hit sdfwb_marchRay(vec3 origin, vec3 direction) {
    sdfwb_Hit hit = sdfwb_Hit(false, 0.0, 0, origin, sdfwb_kRayLeftBox, 0.0);
    sdfwb_March march;
    if (!sdfwb_startMarch(origin, direction, march)) {
        SDFWB_RECORD(sdfwb_kProbeMissedBox, march.tStart, march.entry, 0.0);
        return hit;
    }
    float d = 0.0; // the last value: at a hit, f where the march stopped
#if !defined(SDFWB_PROBE) && !defined(SDFWB_OVERRELAX)
    // The plain march as tight as the textbook loop (on llvmpipe every operation a step carries
    // costs each pixel): one test stops at a hit and at NaN (which fails every comparison), the
    // loop's own condition at the box's end (where a step of +Inf goes), and why the ray ended is
    // told once after the loop (a step of -Inf leaves s at -Inf: not finite either).
    int step = 0;
    for (; step < sdfwb_maxSteps && march.s <= march.sEnd; ++step) {
        d = SDFWB_SCALED(sdfwb_sceneMap(march.entry + march.s * direction));
        if (!(abs(d) >= march.footprint * (march.tStart + march.s))) break;
        march.s += d;
    }
    const bool stopped = step < sdfwb_maxSteps && march.s <= march.sEnd; // by the test, not the loop
    hit.steps = stopped ? step + 1 : step;
    if (isnan(d) || isinf(d) || isinf(march.s))
        hit.status = sdfwb_kRayNotFinite;
    else
        hit.status = stopped ? sdfwb_kRayHit : march.s > march.sEnd ? sdfwb_kRayLeftBox : sdfwb_kRayOutOfSteps;
    hit.found = hit.status == sdfwb_kRayHit;
#else
    hit.status = sdfwb_kRayOutOfSteps;
    for (int step = 0; step < sdfwb_maxSteps; ++step) {
        hit.steps = step + 1;
        float t = march.tStart + march.s;
        vec3 at = march.entry + march.s * direction;
        d = SDFWB_SCALED(sdfwb_sceneMap(at));
        if (isnan(d) || isinf(d)) {
            SDFWB_RECORD(sdfwb_kProbeNotFinite, t, at, d);
            hit.status = sdfwb_kRayNotFinite;
            break;
        }
        int event = sdfwb_marchStep(march, d);
        SDFWB_RECORD(sdfwb_probeKindOf(event), t, at, d);
        if (event == sdfwb_kMarchHit) {
            hit.found = true;
            break;
        }
        if (event == sdfwb_kMarchFallback) continue;
        if (march.s > march.sEnd) {
            SDFWB_RECORD(sdfwb_kProbeLeftBox, march.tStart + march.s, march.entry + march.s * direction, 0.0);
            hit.status = sdfwb_kRayLeftBox;
            break;
        }
    }
#endif
#ifdef SDFWB_PROBE
    if (hit.status == sdfwb_kRayOutOfSteps && !hit.found)
        SDFWB_RECORD(sdfwb_kProbeOutOfSteps, march.tStart + march.s, march.entry + march.s * direction, 0.0);
#endif
    hit.value = d;
    if (hit.found && !SDFWB_CONE_PASS) {
        hit.status = sdfwb_kRayHit;
        float value = d;
        for (int k = 0; k < sdfwb_kRefiningSteps; ++k) {
            float next = SDFWB_SCALED(sdfwb_sceneMap(march.entry + (march.s + value) * direction));
            const bool keep = sdfwb_refineKeeps(value, next);
            SDFWB_RECORD(keep ? sdfwb_kProbeRefineKept : sdfwb_kProbeRefineUndone, march.tStart + march.s + value,
                         march.entry + (march.s + value) * direction, next);
            if (!keep) break;
            march.s += value;
            value = next;
        }
        hit.value = SDFWB_UNSCALED(value);
    }
    hit.t = march.tStart + march.s;
    hit.position = march.entry + march.s * direction;
    return hit;
}

// Loop bounds the driver cannot see as constants: a loop with a constant count is unrolled, and
// every copy inlines the whole SDF again. With these, each site below holds one copy, so a heavy
// SDF costs the driver's code generation (on llvmpipe at the first frame) a fraction of the time.
// The tiniest SDFs (SDFWB_UNROLLED_TAPS) cost it next to nothing either way and draw faster with
// the taps unrolled (their directions become constants).
#ifdef SDFWB_UNROLLED_TAPS
const int sdfwb_gradientTaps = 4;
#else
uniform int sdfwb_gradientTaps = 4;
#endif
uniform int sdfwb_thinRetakes = 5; // times the normal's taps are taken again with a smaller step

// Tetrahedral 4-tap gradient with step h; raw (not normalised).
vec3 sdfwb_gradientAt(vec3 p, float h) {
    vec3 sum = vec3(0.0);
    for (int i = 0; i < sdfwb_gradientTaps; ++i) sum += sdfwb_tetrahedronTap(i) * sdfwb_sceneMap(p + sdfwb_tetrahedronTap(i) * h);
    return sum / (4.0 * h);
}

// The normal's first step at a hit at distance t (a pixel's footprint) and its floor (float noise).
vec2 sdfwb_normalSteps(vec3 p, float t) {
    float floorStep = 1e-5 * max(1.0, length(p));
    return vec2(max(sdfwb_pixelAngle() * t, floorStep), floorStep);
}

// The unit normal from a raw gradient; facing the ray when the gradient vanished or overflowed.
vec3 sdfwb_unitNormal(vec3 gradient, vec3 direction) {
    float length2 = dot(gradient, gradient);
    return length2 > 0.0 && !isinf(length2) ? gradient * inversesqrt(length2) : -direction;
}

// Whether four taps (their values' sum and their weighted sum) around a point where f = value
// straddled a feature thinner than their step. The taps sum to zero, so for a field that is
// linear across them their mean is f at the centre; a surface's curvature adds a term in h^2.
// Around a sheet thinner than the step every tap lands outside it: the mean rises by about
// h |grad f| while the weighted sum (the gradient) cancels. The test compares the rise with the
// weighted sum, so it does not depend on the field's slope or on how far from the surface the hit
// stopped; for a sphere of radius R it holds once h > R / 2.
bool sdfwb_straddled(float valueSum, vec3 weightedSum, float value) {
    float rise = valueSum - 4.0 * value;
    return rise > 0.0 && rise * rise > 0.25 * dot(weightedSum, weightedSum);
}

// Normal with a step matched to the hit distance (a pixel's footprint), never below float noise.
// A feature thinner than the step (a paper-thin shell, a blade) would let the taps straddle it:
// their differences cancel and the gradient points anywhere. When the taps show it
// (sdfwb_straddled, against `value`, f at p), they are taken again with an eightfold smaller step
// (at most five times, to 1/32768 of the footprint, never below the float floor).
vec3 sdfwb_normalAt(vec3 p, float t, float value, vec3 direction) {
    vec2 steps = sdfwb_normalSteps(p, t);
    float h = steps.x;
    vec3 sum = vec3(0.0);
    for (int retake = 0; retake <= sdfwb_thinRetakes; ++retake) {
        sum = vec3(0.0);
        float valueSum = 0.0;
        for (int i = 0; i < sdfwb_gradientTaps; ++i) {
            float f = sdfwb_sceneMap(p + sdfwb_tetrahedronTap(i) * h);
            sum += sdfwb_tetrahedronTap(i) * f;
            valueSum += f;
        }
        if (!(h > steps.y && sdfwb_straddled(valueSum, sum, value))) break;
        h = max(h * 0.125, steps.y);
    }
    return sdfwb_unitNormal(sum, direction); // the direction of the gradient sum / (4 h)
}

// The march, the refining step and the normal's taps (retaken with a smaller step when they
// straddled a thin feature) as one loop around one call of the SDF: what sdfwb_marchRay()
// followed by sdfwb_normalAt() computes (the same steps, hit, refinement and taps), but the driver
// inlines the SDF once instead of three times, so a heavy SDF's first frame waits a third as long
// for code generation. Lanes that hit early take their taps while their neighbours still march. The march debugger and the
// statistics output use the separate functions, which record every event.
const int sdfwb_kPhaseMarch = 0;
const int sdfwb_kPhaseTaps = 1;
const int sdfwb_kPhaseRefine = 2;

sdfwb_Hit sdfwb_traceWithNormal(vec3 origin, vec3 direction, out vec3 normal) {
    sdfwb_Hit hit = sdfwb_Hit(false, 0.0, 0, origin, sdfwb_kRayLeftBox, 0.0);
    normal = -direction;
    sdfwb_March march;
    if (!sdfwb_startMarch(origin, direction, march)) return hit;
    hit.status = sdfwb_kRayOutOfSteps;
    int phase = sdfwb_kPhaseMarch;
    int count = 0;          // taps taken
    int retakes = 0;        // times the taps were taken again with a smaller step
    int refined = 0;        // refining steps kept
    float valueSum = 0.0;   // the sum of the taps' values
    float hitValue = 0.0;   // the scaled f where the march stopped
    vec2 steps = vec2(0.0); // the normal's step and its floor
    vec3 sum = vec3(0.0);
    int budget = sdfwb_maxSteps + sdfwb_kRefiningSteps + sdfwb_gradientTaps * (1 + sdfwb_thinRetakes);
    for (int iteration = 0; iteration < budget; ++iteration) {
        vec3 at = phase == sdfwb_kPhaseMarch    ? march.entry + march.s * direction
                  : phase == sdfwb_kPhaseRefine ? march.entry + (march.s + hitValue) * direction
                                                : hit.position + sdfwb_tetrahedronTap(count) * steps.x;
        float f = sdfwb_sceneMap(at);
        if (phase == sdfwb_kPhaseMarch) {
            hit.steps += 1;
            float d = SDFWB_SCALED(f);
            if (isnan(d) || isinf(d)) {
                hit.status = sdfwb_kRayNotFinite;
                break;
            }
            int event = sdfwb_marchStep(march, d);
            hit.value = d;
            if (event == sdfwb_kMarchHit) {
                hit.status = sdfwb_kRayHit;
                if (SDFWB_CONE_PASS) break; // where the cone stops: no refinement, no normal
                hit.found = true;
                hitValue = d;
                phase = sdfwb_kPhaseRefine;
                continue;
            }
            if (event != sdfwb_kMarchFallback && march.s > march.sEnd) {
                hit.status = sdfwb_kRayLeftBox;
                break;
            }
            if (hit.steps >= sdfwb_maxSteps) break;
        } else if (phase == sdfwb_kPhaseRefine) {
            bool keep = sdfwb_refineKeeps(hitValue, SDFWB_SCALED(f));
            if (keep) {
                march.s += hitValue;
                hitValue = SDFWB_SCALED(f);
                if (++refined < sdfwb_kRefiningSteps) continue; // the next refining step
            }
            hit.value = SDFWB_UNSCALED(hitValue);
            hit.t = march.tStart + march.s;
            hit.position = march.entry + march.s * direction;
            steps = sdfwb_normalSteps(hit.position, hit.t);
            phase = sdfwb_kPhaseTaps;
            count = 0;
        } else {
            sum += sdfwb_tetrahedronTap(count) * f;
            valueSum += f;
            if (++count >= sdfwb_gradientTaps) {
                if (sdfwb_straddled(valueSum, sum, hit.value) && retakes < sdfwb_thinRetakes && steps.x > steps.y) {
                    steps.x = max(steps.x * 0.125, steps.y);
                    sum = vec3(0.0);
                    valueSum = 0.0;
                    count = 0;
                    ++retakes;
                } else {
                    normal = sdfwb_unitNormal(sum, direction); // the direction of sum / (4 h)
                    break;
                }
            }
        }
    }
    if (!hit.found) {
        hit.t = march.tStart + march.s;
        hit.position = march.entry + march.s * direction;
    }
    return hit;
}

#ifdef SDFWB_MESH_RAYCAST
// The picture of a mesh's own field (SDFWB_MESH_RAYCAST: not the march debugger, the heat map or
// the statistics output, which show a march): the field's zero set is the triangles, so one walk
// of the hierarchy finds the hit (sdfwb_meshRaycast) where a sphere tracer evaluates the whole
// field, nearest triangle and sign, at every step. The normal is the field's gradient there, the
// face's unit normal, turned to the ray (a face seen from behind through an open mesh's hole
// shades as its front). With the cutting plane clipping the shape, a ray entering the kept
// half-space inside the shape (the field's sign where it enters) hits the cut face there.
// An open mesh's sign jumps across its holes without a zero: a sphere tracer stops at that jump
// as if it were a surface, this walk sees the triangles behind it (the plane shows the jump).
sdfwb_Hit sdfwb_meshTrace(vec3 origin, vec3 direction, out vec3 normal) {
    sdfwb_Hit hit = sdfwb_Hit(false, 0.0, 0, origin, sdfwb_kRayLeftBox, 0.0);
    normal = -direction;
    sdfwb_March march;
    if (!sdfwb_startMarch(origin, direction, march)) return hit;
    hit.steps = 1;
    float tFrom = march.tStart;
    float tTo = march.tStart + march.sEnd;
#ifdef SDFWB_PLANE_CLIP
    // The kept half-space is dot(p, n) <= offset.
    float along = dot(direction, sdfwb_clipNormal);
    float startSide = dot(origin, sdfwb_clipNormal) - sdfwb_clipOffset;
    if (along == 0.0) {
        if (startSide > 0.0) tTo = -1.0; // parallel to the plane, on the cut side
    } else {
        float tPlane = -startSide / along;
        if (along > 0.0) {
            tTo = min(tTo, tPlane);
        } else if (tPlane > tFrom) {
            tFrom = tPlane;
#ifdef SDFWB_PLANE_FIELD
            float entered = sdfwb_planeFieldAt(origin + tFrom * direction).x;
#else
            float entered = sdfwb_sdf(origin + tFrom * direction);
#endif
            if (tFrom <= tTo && entered < 0.0) {
                hit.found = true;
                hit.status = sdfwb_kRayHit;
                hit.t = tFrom;
                hit.position = origin + tFrom * direction;
                normal = sdfwb_clipNormal;
                return hit;
            }
        }
    }
    if (tFrom > tTo) {
        hit.t = max(tTo, march.tStart);
        hit.position = origin + hit.t * direction;
        return hit;
    }
#endif
    uint triangle;
    float t = sdfwb_meshRaycast(origin, direction, tFrom, tTo, triangle);
    if (isnan(t)) {
        hit.status = sdfwb_kRayNotFinite;
        return hit;
    }
    hit.t = t;
    hit.position = origin + t * direction;
    if (triangle == 0xffffffffu) return hit;
    hit.found = true;
    hit.status = sdfwb_kRayHit;
    vec3 a = sdfwb_meshTriangles[3u * triangle].xyz;
    vec3 n = cross(sdfwb_meshTriangles[3u * triangle + 1u].xyz - a, sdfwb_meshTriangles[3u * triangle + 2u].xyz - a);
    normal = sdfwb_unitNormal(dot(n, direction) > 0.0 ? -n : n, direction);
    return hit;
}
#endif
