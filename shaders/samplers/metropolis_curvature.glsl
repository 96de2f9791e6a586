// metropolis_curvature: Metropolis-Hastings towards the zero level set, weighted by absolute mean
// curvature: pi(x) ~ exp(-|f(x)| / 0.01) * (0.2 + min(|H(x)|, 50)), where H = laplacian(f) / 2
// is the mean curvature of the level set through x (exact for a distance field, whose gradient
// has unit length). Curved regions (edges, tips, small features) get more samples; flat regions
// keep some through the 0.2 floor. The chain is sampling/metropolis_chain.glsl's.

float sdfwb_absoluteMeanCurvature(vec3 p, float fp) {
    const float h = 0.01;
    float laplacian = (sdfwb_sdf(p + vec3(h, 0.0, 0.0)) + sdfwb_sdf(p - vec3(h, 0.0, 0.0)) + sdfwb_sdf(p + vec3(0.0, h, 0.0)) +
                       sdfwb_sdf(p - vec3(0.0, h, 0.0)) + sdfwb_sdf(p + vec3(0.0, 0.0, h)) + sdfwb_sdf(p - vec3(0.0, 0.0, h)) - 6.0 * fp) / (h * h);
    return min(abs(0.5 * laplacian), 50.0);
}

// The state's term: log pi(x) up to a constant.
float sdfwb_stateTerm(vec3 p, float fp) { return -abs(fp) / sdfwb_kBand + log(0.2 + sdfwb_absoluteMeanCurvature(p, fp)); }

float sdfwb_logTargetRatio(float fx, float termX, float fy, float termY) { return termY - termX; }

bool samplePosition(uint index, out vec3 position) { return sdfwb_metropolisChain(index, position); }
