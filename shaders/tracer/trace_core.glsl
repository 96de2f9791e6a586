// Sphere tracer core: uniforms, map(), ray set-up, marching, normals. Composed after the SDF;
// a shading piece, optional feature pieces (ao.glsl, ...) and trace_main.frag follow.
// Feature defines: SDFWB_ANIMATED / SDFWB_USES_TIME (time), SDFWB_OVERRELAX (relaxed steps).

uniform vec2 u_resolution;        // framebuffer size in pixels
uniform vec3 u_cameraPosition;
uniform vec3 u_cameraRight;       // unit camera basis
uniform vec3 u_cameraUp;
uniform vec3 u_cameraForward;
uniform float u_tanHalfFovY;      // tan(vertical field of view / 2)
uniform float u_nearPlane;
uniform float u_farPlane;
uniform int u_maxSteps;           // step budget per ray
uniform float u_stepFactor;       // < 1 for fields that are not 1-Lipschitz
uniform float u_epsilonScale;     // hit when |f| < epsilonScale * pixel footprint at t
uniform float u_boxMargin;        // rays are clipped to [-1-margin, 1+margin]^3
uniform vec3 u_background;
#ifdef SDFWB_OVERRELAX
uniform float u_relaxation;       // over-relaxation factor omega in (1, 2)
#endif
#ifdef SDFWB_USES_TIME
uniform float u_time;
#endif

float map(vec3 p) {
#ifdef SDFWB_ANIMATED
    return sdf(p, u_time);
#else
    return sdf(p);
#endif
}

#ifdef SDFWB_PLANE_CLIP
uniform vec3 u_clipNormal;   // the cutting plane; the side it points to is cut away
uniform float u_clipOffset;
// The traced scene: the shape intersected with the half-space behind the plane (a conservative
// bound), so the cross-section shows.
float sceneMap(vec3 p) { return max(map(p), dot(p, u_clipNormal) - u_clipOffset); }
#else
float sceneMap(vec3 p) { return map(p); }
#endif

// Why a ray ended: a hit, or one of three honest kinds of miss.
const int kRayHit = 0;
const int kRayLeftBox = 1;    // passed the far side of the box (or the far plane): nothing there
const int kRayOutOfSteps = 2; // the step budget ran out before |f| fell below the tolerance
const int kRayNotFinite = 3;  // f was NaN or Inf along the ray

struct Hit {
    bool found;
    float t;        // distance along the ray
    int steps;      // steps taken (the budget when it ran out)
    vec3 position;
    int status;     // kRayHit, kRayLeftBox, kRayOutOfSteps or kRayNotFinite
};

// Ray against the axis-aligned box [-b, b]^3; returns (tNear, tFar), tNear > tFar when missed.
vec2 intersectBox(vec3 origin, vec3 direction, float b) {
    vec3 inverse = 1.0 / direction;
    vec3 t0 = (vec3(-b) - origin) * inverse;
    vec3 t1 = (vec3(b) - origin) * inverse;
    vec3 tMin = min(t0, t1);
    vec3 tMax = max(t0, t1);
    return vec2(max(max(tMin.x, tMin.y), tMin.z), min(min(tMax.x, tMax.y), tMax.z));
}

// Angle one pixel spans: hit tolerances and normal steps grow with distance like a pixel's footprint.
float pixelAngle() { return 2.0 * u_tanHalfFovY / u_resolution.y; }

vec3 primaryRay(vec2 fragment) {
    vec2 ndc = (fragment / u_resolution) * 2.0 - 1.0;
    float aspect = u_resolution.x / u_resolution.y;
    return normalize(u_cameraForward + ndc.x * aspect * u_tanHalfFovY * u_cameraRight + ndc.y * u_tanHalfFovY * u_cameraUp);
}

Hit traceRay(vec3 origin, vec3 direction) {
    Hit hit = Hit(false, 0.0, 0, origin, kRayLeftBox);
    vec2 span = intersectBox(origin, direction, 1.0 + u_boxMargin);
    float tStart = max(span.x, u_nearPlane);
    float tEnd = min(span.y, u_farPlane);
    if (tStart > tEnd) return hit;
    // March from the box entry point: far from the origin (a camera at 1e4) the ray parameter t
    // is ~1e4 and float32 cannot add steps below ~1e-3 to it; s counts from the entry instead.
    vec3 entry = origin + tStart * direction;
    float s = 0.0;
    float sEnd = tEnd - tStart;
    float footprint = u_epsilonScale * pixelAngle();
#ifdef SDFWB_OVERRELAX
    // Over-relaxed sphere tracing: step omega * d while consecutive unbounding spheres overlap;
    // when they do not, the step may have passed the surface: go back and continue with omega = 1.
    float omega = u_relaxation;
    float previousRadius = 0.0;
    float stepLength = 0.0;
#endif
    hit.status = kRayOutOfSteps;
    for (int step = 0; step < u_maxSteps; ++step) {
        hit.steps = step + 1;
        float d = sceneMap(entry + s * direction) * u_stepFactor;
        if (isnan(d) || isinf(d)) { hit.status = kRayNotFinite; break; }
        float radius = abs(d);
#ifdef SDFWB_OVERRELAX
        // Fall back when the spheres do not overlap, or when the step crossed the surface (d < 0).
        if (omega > 1.0 && (radius + previousRadius < stepLength || d < 0.0)) {
            s -= stepLength - stepLength / omega;  // undo the relaxed part of the last step
            omega = 1.0;
            previousRadius = 0.0;
            stepLength = 0.0;
            continue;
        }
        if (radius < footprint * (tStart + s)) { hit.found = true; break; }
        stepLength = d * omega;
        previousRadius = radius;
        s += stepLength;
#else
        if (radius < footprint * (tStart + s)) { hit.found = true; break; }
        s += d;
#endif
        if (s > sEnd) { hit.status = kRayLeftBox; break; }
    }
    if (hit.found) {
        hit.status = kRayHit;
        // Refine: up to two more plain steps shrink |f| well below the footprint for exact
        // fields. A step is kept only when |f| shrinks: for a field steeper than the step factor
        // assumes (or a broken one) the step would overshoot, and the hit stays where it was.
        float d = sceneMap(entry + s * direction) * u_stepFactor;
        for (int k = 0; k < 2; ++k) {
            float next = sceneMap(entry + (s + d) * direction) * u_stepFactor;
            if (!(abs(next) < abs(d))) break;
            s += d;
            d = next;
        }
    }
    hit.t = tStart + s;
    hit.position = entry + s * direction;
    return hit;
}

// Tetrahedral 4-tap gradient with step h; raw (not normalised).
vec3 gradientAt(vec3 p, float h) {
    const vec2 k = vec2(1.0, -1.0);
    return (k.xyy * sceneMap(p + k.xyy * h) + k.yyx * sceneMap(p + k.yyx * h) + k.yxy * sceneMap(p + k.yxy * h) +
            k.xxx * sceneMap(p + k.xxx * h)) / (4.0 * h);
}

// Normal with a step matched to the hit distance (a pixel's footprint), never below float noise.
// A feature thinner than the step (a paper-thin shell, a blade) would let the taps straddle it:
// their differences cancel and the gradient points anywhere. A probe 2h further along the ray
// tells: inside a solid at least that thick f is negative there; if it is not, the step shrinks
// eightfold (at most five times, to 1/32768 of the footprint, never below the float floor).
vec3 normalAt(vec3 p, float t, vec3 direction) {
    float floorStep = 1e-5 * max(1.0, length(p));
    float h = max(pixelAngle() * t, floorStep);
    for (int k = 0; k < 5 && h > floorStep; ++k) {
        if (sceneMap(p + 2.0 * h * direction) < 0.0) break;
        h = max(h * 0.125, floorStep);
    }
    vec3 gradient = gradientAt(p, h);
    float length2 = dot(gradient, gradient);
    return length2 > 0.0 && !isinf(length2) ? gradient * inversesqrt(length2) : -direction;
}
