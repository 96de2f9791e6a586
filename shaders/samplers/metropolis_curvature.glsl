// metropolis_curvature: Metropolis-Hastings towards the zero level set, weighted by absolute mean
// curvature: pi(x) ~ exp(-|f(x)| / 0.01) * (0.2 + min(|H(x)|, 50)), where H = laplacian(f) / 2
// is the mean curvature of the level set through x (exact for a distance field, whose gradient
// has unit length). Curved regions (edges, tips, small features) get more samples; flat regions
// keep some through the 0.2 floor. The chain is sampling/metropolis_chain.glsl's.

// The chain may hand this sampler |f| for f: on a mesh's own field it then computes no sign where
// the taps below do not need one.
const bool sdfwb_chainReadsMagnitude = true;

const float sdfwb_kCurvatureStep = 0.01; // the taps' distance from the state

// Tap i of the Laplacian's stencil around p: p + h e_x, p - h e_x, p + h e_y, ... (p itself for -1).
vec3 sdfwb_curvatureTap(vec3 p, int i) {
    const float h = sdfwb_kCurvatureStep;
    if (i < 0) return p;
    vec3 along = vec3(i / 2 == 0 ? h : 0.0, i / 2 == 1 ? h : 0.0, i / 2 == 2 ? h : 0.0);
    return i % 2 == 0 ? p + along : p - along;
}

// The Laplacian's numerator: f at the six taps, less 6 f(p) (or all of that negated, which leaves
// |H| as it is). `fp` is f(p), or |f(p)| where the chain reads magnitudes. One loop calls the
// field: each call is a copy of its code in the compiled program.
float sdfwb_tapSum(vec3 p, float fp) {
    float sum = 0.0;
#if defined(SDFWB_CHAIN_MAGNITUDE) && defined(SDFWB_MESH_SURFACE)
    // A distance field changes by at most h from p to a tap: farther than h from the surface no
    // segment p -> tap meets a triangle, so on a closed mesh every tap lies on p's side and the
    // magnitudes' sum is the signed one times p's sign, bit for bit. Nearer, p and the taps take the
    // signed field (sdfwb_meshSdf's values). Each walk starts from p's nearest triangle. On an open
    // mesh the winding number's sign also flips across the sheet that spans a hole, away from every
    // triangle: signed taps read that jump over h^2 as a curvature (up to the cap), magnitudes read
    // none, and the rows differ from the signed chain's.
    bool signs = !(fp > sdfwb_kCurvatureStep * 1.001);
    for (int i = signs ? -1 : 0; i < 6; ++i) {
        vec3 q = sdfwb_curvatureTap(p, i);
        uint triangle = sdfwb_chainTriangle;
        int feature;
        vec3 closest;
        float value = sdfwb_chainNearest(q, triangle, feature, closest);
        if (signs) {
            float inside = sdfwb_meshInside(q, triangle, feature, closest);
            value = isnan(inside) ? inside : (inside > 0.5 ? -value : value);
        }
        if (i < 0)
            fp = value;
        else
            sum += value;
    }
#else
    for (int i = 0; i < 6; ++i) sum += sdfwb_sdf(sdfwb_curvatureTap(p, i));
#endif
    return sum - 6.0 * fp;
}

float sdfwb_absoluteMeanCurvature(vec3 p, float fp) {
    const float h = sdfwb_kCurvatureStep;
    float laplacian = sdfwb_tapSum(p, fp) / (h * h);
    return min(abs(0.5 * laplacian), 50.0);
}

// The state's term: log pi(x) up to a constant.
float sdfwb_stateTerm(vec3 p, float fp) { return -abs(fp) / sdfwb_kBand + log(0.2 + sdfwb_absoluteMeanCurvature(p, fp)); }

float sdfwb_logTargetRatio(float fx, float termX, float fy, float termY) { return termY - termX; }

bool samplePosition(uint index, out vec3 position) { return sdfwb_metropolisChain(index, position); }
