float sdf(vec3 p) {
    float r = 0.5;
    return length(p) - radius;
}
