// Defines a helper but no sdf().
float sphere(vec3 p) { return length(p) - 0.5; }
