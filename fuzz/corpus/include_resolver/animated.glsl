float sdf(vec3 p, float time) {
    return length(p) - 0.5 - 0.1 * sin(time);
}
