const float pi = 3.14159;
float sdf(vec3 p) { return length(p) - 0.5 * pi / pi; }
