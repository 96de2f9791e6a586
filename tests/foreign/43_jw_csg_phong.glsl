/**
 * Imitates: a whole Shadertoy in the style of Jamie Wong's ray marching
 * tutorial, pasted unmodified: the doc-comment blocks, MAX_MARCHING_STEPS /
 * MIN_DIST / MAX_DIST / EPSILON constants, intersectSDF() / unionSDF() /
 * differenceSDF(), boxSDF(), sphereSDF(), cylinderSDF(), a rotateY()
 * matrix turning the shape with iTime, `float sceneSDF(vec3 samplePoint)`,
 * shortestDistanceToSurface(), rayDirection(fieldOfView, size, fragCoord),
 * estimateNormal(), phongContribForLight() / phongIllumination() and a
 * viewMatrix(eye, center, up) returning mat3.
 *
 * Why the audit should find it clean: the box, sphere and capped
 * cylinders are exact; intersection (max), union (min) and difference
 * (max with the negated distance) of exact distances are 1-Lipschitz,
 * continuous bounds; the rotation by iTime is an isometry; the uniform
 * scale (sphereSDF(p / 1.2) * 1.2) multiplies back what it divides. All
 * of it within 0.8 of the origin, so the field grows outside the cube; no
 * NaN. sceneSDF reads iTime: animated.
 */
// expect: entry=sceneSDF flags=none animated=yes

const int MAX_MARCHING_STEPS = 255;
const float MIN_DIST = 0.0;
const float MAX_DIST = 100.0;
const float EPSILON = 0.0001;

/**
 * A rotation about the y axis by theta radians.
 */
mat3 rotateY(float theta) {
    float c = cos(theta);
    float s = sin(theta);
    return mat3(
        vec3(c, 0, s),
        vec3(0, 1, 0),
        vec3(-s, 0, c)
    );
}

/**
 * CSG on distances: the points inside both shapes.
 */
float intersectSDF(float distA, float distB) {
    return max(distA, distB);
}

/**
 * CSG on distances: the points inside either shape.
 */
float unionSDF(float distA, float distB) {
    return min(distA, distB);
}

/**
 * CSG on distances: the points inside A but not inside B.
 */
float differenceSDF(float distA, float distB) {
    return max(distA, -distB);
}

/**
 * A box around the origin; halfSize is half its width, height and depth.
 */
float boxSDF(vec3 p, vec3 halfSize) {
    vec3 q = abs(p) - halfSize;
    // outside: how far past the faces, edges or corner we are
    float outside = length(max(q, 0.0));
    // inside: the nearest face, as a negative number
    float inside = min(max(q.x, max(q.y, q.z)), 0.0);
    return outside + inside;
}

/**
 * The unit sphere around the origin.
 */
float sphereSDF(vec3 p) {
    return length(p) - 1.0;
}

/**
 * A capped cylinder around the z axis: length h (end to end), radius r.
 */
float cylinderSDF(vec3 p, float h, float r) {
    vec2 q = vec2(length(p.xy) - r, abs(p.z) - 0.5 * h);
    float inside = min(max(q.x, q.y), 0.0);
    float outside = length(max(q, 0.0));
    return inside + outside;
}

/**
 * The whole scene: negative inside, positive outside, and the magnitude
 * says how far the nearest surface is.
 */
float sceneSDF(vec3 samplePoint) {
    samplePoint = rotateY(iTime / 2.0) * samplePoint;

    // three rods through the middle, one per axis
    float rodZ = cylinderSDF(samplePoint, 1.6, 0.2);
    float rodX = cylinderSDF(rotateY(radians(90.0)) * samplePoint, 1.6, 0.2);
    float rodY = cylinderSDF(samplePoint.zxy, 1.6, 0.2);

    // a cube with its corners rounded off by a ball (scaled: 0.6 instead of 1)
    float cube = boxSDF(samplePoint, vec3(0.45));
    float ball = sphereSDF(samplePoint / 0.6) * 0.6;

    float rounded = intersectSDF(cube, ball);
    float rods = unionSDF(rodZ, unionSDF(rodX, rodY));
    return differenceSDF(rounded, rods);
}

/**
 * March from the eye along dir; the distance of the first surface point
 * between start and end, or end when there is none.
 */
float shortestDistanceToSurface(vec3 eye, vec3 dir, float start, float end) {
    float depth = start;
    for (int i = 0; i < MAX_MARCHING_STEPS; i++) {
        float dist = sceneSDF(eye + depth * dir);
        if (dist < EPSILON) return depth;
        depth += dist;
        if (depth >= end) return end;
    }
    return end;
}

/**
 * The view-space direction through a pixel: the camera looks down -z.
 *
 * fieldOfView: vertical, in degrees
 * size: the image size in pixels
 * fragCoord: the pixel
 */
vec3 rayDirection(float fieldOfView, vec2 size, vec2 fragCoord) {
    vec2 xy = fragCoord - 0.5 * size;
    float z = size.y / tan(radians(fieldOfView) / 2.0);
    return normalize(vec3(xy, -z));
}

/**
 * The surface normal: the normalised gradient of the SDF, by central differences.
 */
vec3 estimateNormal(vec3 p) {
    vec3 dx = vec3(EPSILON, 0.0, 0.0);
    vec3 dy = vec3(0.0, EPSILON, 0.0);
    vec3 dz = vec3(0.0, 0.0, EPSILON);
    return normalize(vec3(
        sceneSDF(p + dx) - sceneSDF(p - dx),
        sceneSDF(p + dy) - sceneSDF(p - dy),
        sceneSDF(p + dz) - sceneSDF(p - dz)
    ));
}

/**
 * What one point light adds at p (Phong: diffuse plus specular).
 *
 * k_d, k_s: diffuse and specular colours
 * alpha: shininess
 * p, eye: the lit point and the camera
 * lightPos, lightIntensity: the light
 */
vec3 phongContribForLight(vec3 k_d, vec3 k_s, float alpha, vec3 p, vec3 eye,
                          vec3 lightPos, vec3 lightIntensity) {
    vec3 N = estimateNormal(p);
    vec3 L = normalize(lightPos - p);
    vec3 V = normalize(eye - p);
    vec3 R = normalize(reflect(-L, N));

    float dotLN = dot(L, N);
    float dotRV = dot(R, V);

    if (dotLN < 0.0) {
        // the light is behind the surface
        return vec3(0.0);
    }
    if (dotRV < 0.0) {
        // the highlight points away from us: diffuse only
        return lightIntensity * (k_d * dotLN);
    }
    return lightIntensity * (k_d * dotLN + k_s * pow(dotRV, alpha));
}

/**
 * Ambient light plus two moving point lights.
 *
 * k_a, k_d, k_s: ambient, diffuse and specular colours
 * alpha: shininess
 * p, eye: the lit point and the camera
 */
vec3 phongIllumination(vec3 k_a, vec3 k_d, vec3 k_s, float alpha, vec3 p, vec3 eye) {
    const vec3 ambientLight = vec3(0.5);
    vec3 color = ambientLight * k_a;

    vec3 light1Pos = vec3(4.0 * sin(iTime), 2.0, 4.0 * cos(iTime));
    color += phongContribForLight(k_d, k_s, alpha, p, eye, light1Pos, vec3(0.4));

    vec3 light2Pos = vec3(2.0 * sin(0.37 * iTime), 2.0 * cos(0.37 * iTime), 2.0);
    color += phongContribForLight(k_d, k_s, alpha, p, eye, light2Pos, vec3(0.4));

    return color;
}

/**
 * The rotation that takes view-space directions (camera looking down -z)
 * to world space, for a camera at eye looking at center.
 */
mat3 viewMatrix(vec3 eye, vec3 center, vec3 up) {
    vec3 f = normalize(center - eye);
    vec3 s = normalize(cross(f, up));
    vec3 u = cross(s, f);
    return mat3(s, u, -f);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 viewDir = rayDirection(45.0, iResolution.xy, fragCoord);
    vec3 eye = vec3(4.0, 3.0 + sin(0.25 * iTime), 5.0);

    mat3 viewToWorld = viewMatrix(eye, vec3(0.0), vec3(0.0, 1.0, 0.0));
    vec3 worldDir = viewToWorld * viewDir;

    float dist = shortestDistanceToSurface(eye, worldDir, MIN_DIST, MAX_DIST);

    if (dist > MAX_DIST - EPSILON) {
        // nothing here: transparent black
        fragColor = vec4(0.0);
        return;
    }

    vec3 p = eye + dist * worldDir;

    // colour the surface by its normal
    vec3 K_a = 0.5 * (estimateNormal(p) + 1.0);
    vec3 K_d = K_a;
    vec3 K_s = vec3(1.0);
    float shininess = 10.0;

    vec3 color = phongIllumination(K_a, K_d, K_s, shininess, p, eye);
    fragColor = vec4(color, 1.0);
}
