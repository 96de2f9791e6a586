// Point-cloud overlay: each sample as a round dot coloured by its gradient's direction (x, y, z
// as red, green, blue, mapped from [-1, 1] to [0, 1], as in the paper's Figure 15); a zero or
// non-finite gradient is grey.
in vec3 sdfwb_world;
in vec3 sdfwb_gradient;
out vec4 sdfwb_color;

void main() {
    vec2 offset = gl_PointCoord * 2.0 - 1.0;
    if (dot(offset, offset) > 1.0) discard;
    float length2 = dot(sdfwb_gradient, sdfwb_gradient);
    vec3 color = length2 > 1e-20 ? 0.5 + 0.5 * sdfwb_gradient * inversesqrt(length2) : vec3(0.6);
    sdfwb_color = vec4(color, 1.0);
}
