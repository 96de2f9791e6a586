/*
 * Imitates: Jamie Wong's "Ray Marching and Signed Distance Functions"
 * tutorial shaders: `float sceneSDF(vec3 samplePoint)`, intersectSDF /
 * unionSDF / differenceSDF helpers, const MAX_MARCHING_STEPS / EPSILON,
 * estimateNormal() and shortestDistanceToSurface() (never called by
 * sdfwb) -- plus a "make it march faster" hack seen in forks: multiply the
 * distance by 1.9 and cap each step at 0.5.
 *
 * Why non-conservative AND truncated: 1.9 * d has |grad| = 1.9 wherever
 * the cap is not active (everywhere within ~0.26 of the surface, inside
 * included), far above 1.05. The cap min(0.5, ...) makes a flat plateau
 * (|grad| = 0) from ~0.26 outside the surface on, i.e. most of the outside
 * region out to distance 3. The underlying CSG (a cube minus a sphere) is
 * continuous and finite, so no other flag.
 */
// expect: entry=sceneSDF flags=non-conservative,truncated animated=no

const int MAX_MARCHING_STEPS = 255;
const float MIN_DIST = 0.0;
const float MAX_DIST = 100.0;
const float EPSILON = 0.0001;

float intersectSDF(float distA, float distB) {
    return max(distA, distB);
}

float unionSDF(float distA, float distB) {
    return min(distA, distB);
}

float differenceSDF(float distA, float distB) {
    return max(distA, -distB);
}

/**
 * Axis-aligned cube around the origin; halfSize holds the half extents.
 */
float cubeSDF(vec3 p, vec3 halfSize) {
    vec3 d = abs(p) - halfSize;
    float insideDistance = min(max(d.x, max(d.y, d.z)), 0.0);
    float outsideDistance = length(max(d, 0.0));
    return insideDistance + outsideDistance;
}

/**
 * Ball of radius r around the origin.
 */
float sphereSDF(vec3 p, float r) {
    return length(p) - r;
}

/**
 * The whole scene: a cube with a spherical hollow.
 */
float sceneSDF(vec3 samplePoint) {
    float sphereDist = sphereSDF(samplePoint, 0.75);
    float cubeDist = cubeSDF(samplePoint, vec3(0.6));
    float d = differenceSDF(cubeDist, sphereDist);
    // faster marching (!)
    return min(0.5, 1.9 * d);
}

/**
 * Sphere-trace from the eye along the ray; answers the depth of the first
 * hit, or `end` when nothing is hit before it.
 */
float shortestDistanceToSurface(vec3 eye, vec3 marchingDirection, float start, float end) {
    float depth = start;
    for (int i = 0; i < MAX_MARCHING_STEPS; i++) {
        float dist = sceneSDF(eye + depth * marchingDirection);
        if (dist < EPSILON) {
            return depth;
        }
        depth += dist;
        if (depth >= end) {
            return end;
        }
    }
    return end;
}

/**
 * Surface normal at p from central differences of the scene's field.
 */
vec3 estimateNormal(vec3 p) {
    return normalize(vec3(
        sceneSDF(vec3(p.x + EPSILON, p.y, p.z)) - sceneSDF(vec3(p.x - EPSILON, p.y, p.z)),
        sceneSDF(vec3(p.x, p.y + EPSILON, p.z)) - sceneSDF(vec3(p.x, p.y - EPSILON, p.z)),
        sceneSDF(vec3(p.x, p.y, p.z  + EPSILON)) - sceneSDF(vec3(p.x, p.y, p.z - EPSILON))
    ));
}
