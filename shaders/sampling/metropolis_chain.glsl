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

// llvmpipe ends every loop of an invocation once all its loops together have run 65,535
// iterations, without an error: a chain whose field walks a mesh's hierarchy seven times a step
// (metropolis_curvature) ran out after 41 steps on spot. There SampleCompute runs each chunk's
// chains in passes of a few steps: a pass takes the states the last one stored and stores its own;
// the last pass places the rows. The same program and the same states bit for bit as one pass that
// is not cut. A chain cut anyway (a loop stopped before its pass's last step) is a NaN row.
#define SDFWB_CHAIN_PASSES 1
layout(std430, binding = SDFWB_BINDING_CHAIN) buffer sdfwb_ChainStates { uvec4 sdfwb_chainStates[]; }; // two a row, as bits
uniform int sdfwb_chainFrom = -1;             // this pass's steps: from (-1: the first state) ...
uniform int sdfwb_chainTo = int(sdfwb_kSteps); // ... up to, not including, this one

float sdfwb_stateTerm(vec3 p, float f);
float sdfwb_logTargetRatio(float fx, float termX, float fy, float termY);

float sdfwb_proposalWidth(float distance) { return clamp(0.5 * abs(distance), 0.004, 0.25); }

#if defined(SDFWB_CHAIN_MAGNITUDE) && defined(SDFWB_MESH_SURFACE)
// A sampler that reads only |f| (it declares sdfwb_chainReadsMagnitude; SampleCompute defines
// SDFWB_CHAIN_MAGNITUDE) on a mesh's own field: |f| is the nearest distance, and no sign is
// computed. Each walk starts bounded by the distance to a triangle near p (the last proposal's,
// taken or not, in the chain): the same triangle and distance as a walk from the root (ties go
// to the lowest slot). So the chain is the signed field's, except where a sign walk of that one
// would have been cut (a NaN state rejected; on llvmpipe, past its loop budget on large meshes).
float sdfwb_chainNearest(vec3 p, inout uint triangle, out int feature, out vec3 closest) {
    feature = 0;
    closest = p;
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

uint sdfwb_chainTriangle = 0xffffffffu; // the nearest triangle of the last point the chain walked
uint sdfwb_chainHint() { return sdfwb_chainTriangle; }
void sdfwb_setChainHint(uint triangle) { sdfwb_chainTriangle = triangle; }

float sdfwb_chainValue(vec3 p) {
    int feature;
    vec3 closest;
    return sdfwb_chainNearest(p, sdfwb_chainTriangle, feature, closest);
}
#else
float sdfwb_chainValue(vec3 p) { return sdfwb_sdf(p); }
uint sdfwb_chainHint() { return 0u; }
void sdfwb_setChainHint(uint triangle) {}
#endif

// Every walk of the field is compiled once for each place that calls it (GLSL has no calls at run
// time; a mesh's walks make a large program, which llvmpipe's first dispatch compiles for seconds):
// the first state and the proposals share one call of the field and of the sampler's term.
bool sdfwb_metropolisChain(uint index, out vec3 position) {
    uint row = 2u * (index - sdfwb_chunkFirst);
    vec3 x;
    float fx = 0.0;
    float termX = 0.0;
    float widthX = 0.0;
    int step = sdfwb_chainFrom;
    bool cutBefore = false;
    if (step < 0) {
        x = sdfwb_randomInCube(index, 0u);
    } else {
        uvec4 state = sdfwb_chainStates[row];
        uvec4 more = sdfwb_chainStates[row + 1u];
        x = uintBitsToFloat(state.xyz);
        fx = uintBitsToFloat(state.w);
        termX = uintBitsToFloat(more.x);
        widthX = uintBitsToFloat(more.y);
        sdfwb_setChainHint(more.z);
        cutBefore = more.w != 0u;
        if (cutBefore) step = sdfwb_chainTo + 1;
    }
    // One iteration past the pass's last step sets `finished`: llvmpipe checks its budget at the end
    // of an iteration, so a budget spent in the last step's walks ends the loop before it.
    bool finished = false;
    for (; step <= sdfwb_chainTo; ++step) {
        if (step == sdfwb_chainTo) {
            finished = true;
            continue;
        }
        vec3 y = x;
        if (step >= 0) {
            y = x + widthX * sdfwb_randomGaussian3(index, uint(1 + 2 * step));
            if (any(greaterThan(abs(y), vec3(1.0)))) continue; // outside the support: rejected
        }
        float fy = sdfwb_chainValue(y);
        if (step >= 0 && (isnan(fy) || isinf(fy))) continue;
        float termY = sdfwb_stateTerm(y, fy);
        if (step < 0) { // the first state
            fx = fy;
            termX = termY;
            widthX = sdfwb_proposalWidth(fx);
            continue;
        }
        float widthY = sdfwb_proposalWidth(fy);
        float squared = dot(y - x, y - x);
        // log of pi(y) q(x|y) / (pi(x) q(y|x)) for isotropic Gaussians in 3D
        float logRatio = sdfwb_logTargetRatio(fx, termX, fy, termY) + 3.0 * log(widthX / widthY) -
                         squared / (2.0 * widthY * widthY) + squared / (2.0 * widthX * widthX);
        if (log(max(sdfwb_random01(index, uint(2 + 2 * step)), 1e-30)) < logRatio) {
            x = y;
            fx = fy;
            termX = termY;
            widthX = widthY;
        }
    }
    // The loop ends early only where the driver cut it (or an earlier pass did).
    bool cut = cutBefore || !finished;
    position = x;
    if (sdfwb_chainTo < int(sdfwb_kSteps)) { // a pass before the last
        sdfwb_chainStates[row] = uvec4(floatBitsToUint(x), floatBitsToUint(fx));
        sdfwb_chainStates[row + 1u] = uvec4(floatBitsToUint(termX), floatBitsToUint(widthX), sdfwb_chainHint(), cut ? 1u : 0u);
        return false;
    }
    return !cut && !isnan(fx);
}
