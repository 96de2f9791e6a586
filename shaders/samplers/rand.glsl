// rand: points uniformly at random in the cube [-1,1]^3.
bool samplePosition(uint index, out vec3 position) {
    position = sdfwb_randomInCube(index, 0u);
    return true;
}
