// helper.glsl

float helperDistance(vec3 p) {
    return length(p) - undefinedRadius;
}
