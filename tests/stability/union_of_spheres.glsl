// min() of two exact spheres: exact outside, an underestimate inside the overlap (conservative).
float sdf(vec3 p) { return min(length(p - vec3(0.3, 0.0, 0.0)) - 0.4, length(p + vec3(0.3, 0.0, 0.0)) - 0.4); }
