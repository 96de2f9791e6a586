// metropolis_curvature: Metropolis-Hastings towards the zero level set, weighted by absolute mean
// curvature: pi(x) ~ exp(-|f(x)| / 0.01) * (0.2 + min(|H(x)|, 50)), where H = laplacian(f) / 2
// is the mean curvature of the level set through x (exact for a distance field, whose gradient
// has unit length). Curved regions (edges, tips, small features) get more samples; flat regions
// keep some through the 0.2 floor. Chains as in the metropolis pattern.

const float kBand = 0.01;
const uint kSteps = 160u;

float proposalWidth(float distance) { return clamp(0.5 * abs(distance), 0.004, 0.25); }

float absoluteMeanCurvature(vec3 p, float fp) {
    const float h = 0.01;
    float laplacian = (map(p + vec3(h, 0.0, 0.0)) + map(p - vec3(h, 0.0, 0.0)) + map(p + vec3(0.0, h, 0.0)) +
                       map(p - vec3(0.0, h, 0.0)) + map(p + vec3(0.0, 0.0, h)) + map(p - vec3(0.0, 0.0, h)) - 6.0 * fp) / (h * h);
    return min(abs(0.5 * laplacian), 50.0);
}

// log pi(x) up to a constant
float logTarget(vec3 p, float fp) { return -abs(fp) / kBand + log(0.2 + absoluteMeanCurvature(p, fp)); }

bool samplePosition(uint index, out vec3 position) {
    vec3 x = randomInCube(index, 0u);
    float fx = map(x);
    float logX = logTarget(x, fx);
    for (uint step = 0u; step < kSteps; ++step) {
        float widthX = proposalWidth(fx);
        vec3 y = x + widthX * randomGaussian3(index, 1u + 2u * step);
        if (any(greaterThan(abs(y), vec3(1.0)))) continue;
        float fy = map(y);
        if (isnan(fy) || isinf(fy)) continue;
        float logY = logTarget(y, fy);
        float widthY = proposalWidth(fy);
        float squared = dot(y - x, y - x);
        float logRatio = logY - logX + 3.0 * log(widthX / widthY) - squared / (2.0 * widthY * widthY) +
                         squared / (2.0 * widthX * widthX);
        if (log(max(random01(index, 2u + 2u * step), 1e-30)) < logRatio) {
            x = y;
            fx = fy;
            logX = logY;
        }
    }
    position = x;
    return !isnan(fx);
}
