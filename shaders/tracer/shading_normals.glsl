// Normals as colours: (x, y, z) in [-1, 1] to RGB in [0, 1].
vec3 sdfwb_shade(vec3 position, vec3 normal, vec3 direction, sdfwb_Hit hit) { return normal * 0.5 + 0.5; }
