/* not a sampler */ bool samplePosition(int index, out vec3 position) { return false; }
