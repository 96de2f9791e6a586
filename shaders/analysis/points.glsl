// Points given by the caller (not a user pattern): sample i is the i-th point of the run's input
// array (SampleUniforms::inputPoints), uploaded chunk by chunk. The audit uses it to probe where
// it chooses: outward from the surface, across a suspected jump.
layout(std430, binding = SDFWB_BINDING_INPUTS) readonly buffer sdfwb_Inputs { float sdfwb_inputs[]; };

bool samplePosition(uint index, out vec3 position) {
    uint local = index - sdfwb_chunkFirst;
    position = vec3(sdfwb_inputs[3u * local], sdfwb_inputs[3u * local + 1u], sdfwb_inputs[3u * local + 2u]);
    return true;
}
