// metropolis: importance sampling towards the zero level set with Metropolis-Hastings, targeting
// pi(x) ~ exp(-|f(x)| / 0.01) on the cube [-1,1]^3: the chain of sampling/metropolis_chain.glsl
// with no weight of its own.

// The chain may hand this sampler |f| for f (on a mesh's own field: no sign to compute).
const bool sdfwb_chainReadsMagnitude = true;

float sdfwb_stateTerm(vec3 p, float f) { return 0.0; }

float sdfwb_logTargetRatio(float fx, float termX, float fy, float termY) { return (abs(fx) - abs(fy)) / sdfwb_kBand; }

bool samplePosition(uint index, out vec3 position) { return sdfwb_metropolisChain(index, position); }
