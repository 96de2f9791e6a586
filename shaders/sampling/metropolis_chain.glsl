// The Metropolis-Hastings chain the metropolis samplers share, composed before a sampler that
// calls sdfwb_metropolisChain (SampleCompute looks for the name). Each sample runs its own chain
// (so samples are independent and any chunking gives the same file) on the cube [-1,1]^3, towards
// pi(x) ~ exp(-|f(x)| / sdfwb_kBand) times the sampler's own weight. The Gaussian proposal's width
// follows |f| (wide far from the surface, narrow near it); the Hastings ratio corrects for that,
// so the chain keeps pi as its stationary distribution. The last state is the sample.
//
// The sampler defines:
//   float sdfwb_stateTerm(vec3 p, float f);  a term the chain keeps with each state, computed once
//                                            per state (the log of the sampler's weight, or 0.0)
//   float sdfwb_logTargetRatio(float fx, float termX, float fy, float termY);
//                                            log pi(y) / pi(x) from the two states' values and terms

const float sdfwb_kBand = 0.01; // pi's length scale: most samples lie within a few bands of f = 0
const uint sdfwb_kSteps = 160u; // chain length

float sdfwb_stateTerm(vec3 p, float f);
float sdfwb_logTargetRatio(float fx, float termX, float fy, float termY);

float sdfwb_proposalWidth(float distance) { return clamp(0.5 * abs(distance), 0.004, 0.25); }

#if defined(SDFWB_CHAIN_MAGNITUDE) && defined(SDFWB_MESH_SURFACE)
// A sampler that reads only |f| (it declares sdfwb_chainReadsMagnitude; SampleCompute defines
// SDFWB_CHAIN_MAGNITUDE) on a mesh's own field: |f| is the nearest distance, and no sign is
// computed. Each walk starts bounded by the distance to the last point walked's triangle (the
// last proposal's, taken or not): the same triangle and distance as a walk from the root (ties go
// to the lowest slot). So the chain is the signed field's, except where a sign walk of that one
// would have been cut (a NaN state rejected; on llvmpipe, past its loop budget on large meshes).
float sdfwb_chainValue(vec3 p, inout uint triangle) {
    int feature = 0;
    vec3 closest = p;
    float bound2 = 3.0e38;
    if (triangle == 0xffffffffu) {
        triangle = 0u;
    } else {
        closest = sdfwb_meshClosest(p, sdfwb_meshTriangles[3u * triangle].xyz, sdfwb_meshTriangles[3u * triangle + 1u].xyz,
                                    sdfwb_meshTriangles[3u * triangle + 2u].xyz, feature);
        bound2 = dot(p - closest, p - closest);
    }
    return sqrt(sdfwb_meshNearestWalk(p, bound2, triangle, feature, closest));
}
#else
float sdfwb_chainValue(vec3 p, inout uint triangle) { return sdfwb_sdf(p); }
#endif

bool sdfwb_metropolisChain(uint index, out vec3 position) {
    uint triangle = 0xffffffffu;
    vec3 x = sdfwb_randomInCube(index, 0u);
    float fx = sdfwb_chainValue(x, triangle);
    float termX = sdfwb_stateTerm(x, fx);
    for (uint step = 0u; step < sdfwb_kSteps; ++step) {
        float widthX = sdfwb_proposalWidth(fx);
        vec3 y = x + widthX * sdfwb_randomGaussian3(index, 1u + 2u * step);
        if (any(greaterThan(abs(y), vec3(1.0)))) continue; // outside the support: rejected
        float fy = sdfwb_chainValue(y, triangle);
        if (isnan(fy) || isinf(fy)) continue;
        float termY = sdfwb_stateTerm(y, fy);
        float widthY = sdfwb_proposalWidth(fy);
        float squared = dot(y - x, y - x);
        // log of pi(y) q(x|y) / (pi(x) q(y|x)) for isotropic Gaussians in 3D
        float logRatio = sdfwb_logTargetRatio(fx, termX, fy, termY) + 3.0 * log(widthX / widthY) -
                         squared / (2.0 * widthY * widthY) + squared / (2.0 * widthX * widthX);
        if (log(max(sdfwb_random01(index, 2u + 2u * step), 1e-30)) < logRatio) {
            x = y;
            fx = fy;
            termX = termY;
        }
    }
    position = x;
    return !isnan(fx);
}
