// metropolis: importance sampling towards the zero level set with Metropolis-Hastings. Each
// sample runs its own chain (so samples are independent and any chunking gives the same file)
// targeting pi(x) ~ exp(-|f(x)| / 0.01) on the cube [-1,1]^3. The Gaussian proposal's width
// follows |f| (wide far from the surface, narrow near it); the Hastings ratio corrects for that,
// so the chain still has pi as its stationary distribution.

const float sdfwb_kBand = 0.01;   // pi's length scale: most samples lie within a few bands of f = 0
const uint sdfwb_kSteps = 160u;   // chain length: the last state is the sample

float sdfwb_proposalWidth(float distance) { return clamp(0.5 * abs(distance), 0.004, 0.25); }

bool samplePosition(uint index, out vec3 position) {
    vec3 x = sdfwb_randomInCube(index, 0u);
    float fx = sdfwb_sdf(x);
    for (uint step = 0u; step < sdfwb_kSteps; ++step) {
        float widthX = sdfwb_proposalWidth(fx);
        vec3 y = x + widthX * sdfwb_randomGaussian3(index, 1u + 2u * step);
        if (any(greaterThan(abs(y), vec3(1.0)))) continue;  // outside the support: rejected
        float fy = sdfwb_sdf(y);
        if (isnan(fy) || isinf(fy)) continue;
        float widthY = sdfwb_proposalWidth(fy);
        float squared = dot(y - x, y - x);
        // log of pi(y) q(x|y) / (pi(x) q(y|x)) for isotropic Gaussians in 3D
        float logRatio = (abs(fx) - abs(fy)) / sdfwb_kBand + 3.0 * log(widthX / widthY) -
                         squared / (2.0 * widthY * widthY) + squared / (2.0 * widthX * widthX);
        if (log(max(sdfwb_random01(index, 2u + 2u * step), 1e-30)) < logRatio) {
            x = y;
            fx = fy;
        }
    }
    position = x;
    return !isnan(fx);
}
