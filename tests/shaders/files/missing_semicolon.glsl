// A statement without its ';' (line 3).
float sdf(vec3 p) {
    float radius = 0.5

    return length(p) - radius;
}
