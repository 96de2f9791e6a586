// metropolis_curvature: Metropolis-Hastings towards the zero level set, weighted by absolute mean
// curvature: pi(x) ~ exp(-|f(x)| / 0.01) * (0.2 + min(|H(x)|, 50)), where H = laplacian(f) / 2
// is the mean curvature of the level set through x (exact for a distance field, whose gradient
// has unit length). Curved regions (edges, tips, small features) get more samples; flat regions
// keep some through the 0.2 floor. Chains as in the metropolis pattern.

const float sdfwb_kBand = 0.01;
const uint sdfwb_kSteps = 160u;

float sdfwb_proposalWidth(float distance) { return clamp(0.5 * abs(distance), 0.004, 0.25); }

float sdfwb_absoluteMeanCurvature(vec3 p, float fp) {
    const float h = 0.01;
    float laplacian = (sdfwb_sdf(p + vec3(h, 0.0, 0.0)) + sdfwb_sdf(p - vec3(h, 0.0, 0.0)) + sdfwb_sdf(p + vec3(0.0, h, 0.0)) +
                       sdfwb_sdf(p - vec3(0.0, h, 0.0)) + sdfwb_sdf(p + vec3(0.0, 0.0, h)) + sdfwb_sdf(p - vec3(0.0, 0.0, h)) - 6.0 * fp) / (h * h);
    return min(abs(0.5 * laplacian), 50.0);
}

// log pi(x) up to a constant
float sdfwb_logTarget(vec3 p, float fp) { return -abs(fp) / sdfwb_kBand + log(0.2 + sdfwb_absoluteMeanCurvature(p, fp)); }

bool samplePosition(uint index, out vec3 position) {
    vec3 x = sdfwb_randomInCube(index, 0u);
    float fx = sdfwb_sdf(x);
    float logX = sdfwb_logTarget(x, fx);
    for (uint step = 0u; step < sdfwb_kSteps; ++step) {
        float widthX = sdfwb_proposalWidth(fx);
        vec3 y = x + widthX * sdfwb_randomGaussian3(index, 1u + 2u * step);
        if (any(greaterThan(abs(y), vec3(1.0)))) continue;
        float fy = sdfwb_sdf(y);
        if (isnan(fy) || isinf(fy)) continue;
        float logY = sdfwb_logTarget(y, fy);
        float widthY = sdfwb_proposalWidth(fy);
        float squared = dot(y - x, y - x);
        float logRatio = logY - logX + 3.0 * log(widthX / widthY) - squared / (2.0 * widthY * widthY) +
                         squared / (2.0 * widthX * widthX);
        if (log(max(sdfwb_random01(index, 2u + 2u * step), 1e-30)) < logRatio) {
            x = y;
            fx = fy;
            logX = logY;
        }
    }
    position = x;
    return !isnan(fx);
}
