float sdf(vec3 p) { return length(p) - 1.0; }
