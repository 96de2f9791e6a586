// Returns a vec3 where a float is due (line 4).
float sdf(vec3 p) {
    vec3 q = abs(p);
    return q - vec3(0.5);
}
