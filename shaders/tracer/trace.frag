// Sphere tracer. Composed after the user's SDF; features are switched by defines:
//   SDFWB_ANIMATED      sdf(vec3, float) is called with u_time
//   SDFWB_USES_TIME     the SDF needs time (also set for the G3D scene-time uniform)
//   SDFWB_SHADING_*     exactly one shading mode (NORMALS for now)

in vec2 v_ndc;
out vec4 o_color;

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
uniform float u_epsilonScale;     // hit when f < epsilonScale * pixel footprint at t
uniform float u_boxMargin;        // rays are clipped to [-1-margin, 1+margin]^3
uniform vec3 u_background;
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

// Ray against the axis-aligned box [-b, b]^3; returns (tNear, tFar), tNear > tFar when missed.
vec2 intersectBox(vec3 origin, vec3 direction, float b) {
    vec3 inverse = 1.0 / direction;
    vec3 t0 = (vec3(-b) - origin) * inverse;
    vec3 t1 = (vec3(b) - origin) * inverse;
    vec3 tMin = min(t0, t1);
    vec3 tMax = max(t0, t1);
    return vec2(max(max(tMin.x, tMin.y), tMin.z), min(min(tMax.x, tMax.y), tMax.z));
}

// Tetrahedral 4-tap gradient; h matched to the hit distance by the caller.
vec3 gradientAt(vec3 p, float h) {
    const vec2 k = vec2(1.0, -1.0);
    return k.xyy * map(p + k.xyy * h) + k.yyx * map(p + k.yyx * h) +
           k.yxy * map(p + k.yxy * h) + k.xxx * map(p + k.xxx * h);
}

void main() {
    vec2 pixel = gl_FragCoord.xy;
    vec2 ndc = (pixel / u_resolution) * 2.0 - 1.0;
    float aspect = u_resolution.x / u_resolution.y;
    vec3 direction = normalize(u_cameraForward + ndc.x * aspect * u_tanHalfFovY * u_cameraRight +
                               ndc.y * u_tanHalfFovY * u_cameraUp);
    vec3 origin = u_cameraPosition;
    // Angle one pixel spans: the hit tolerance grows with distance like the pixel footprint.
    float pixelAngle = 2.0 * u_tanHalfFovY / u_resolution.y;

    vec2 span = intersectBox(origin, direction, 1.0 + u_boxMargin);
    float t = max(span.x, u_nearPlane);
    float tEnd = min(span.y, u_farPlane);
    bool hit = false;
    int steps = 0;
    if (t <= tEnd) {
        for (; steps < u_maxSteps; ++steps) {
            float d = map(origin + t * direction);
            float epsilon = u_epsilonScale * pixelAngle * t;
            if (abs(d) < epsilon) { hit = true; break; }
            t += d * u_stepFactor;
            if (t > tEnd || isnan(d)) break;
        }
    }

    if (!hit) {
        o_color = vec4(u_background, 1.0);
        return;
    }
    vec3 position = origin + t * direction;
    float h = max(pixelAngle * t, 1e-5);
    vec3 gradient = gradientAt(position, h);
    float gradientLength = length(gradient);
    vec3 normal = gradientLength > 0.0 ? gradient / gradientLength : -direction;
#ifdef SDFWB_SHADING_NORMALS
    o_color = vec4(normal * 0.5 + 0.5, 1.0);
#else
    o_color = vec4(vec3(max(dot(normal, -direction), 0.0)), 1.0);
#endif
}
