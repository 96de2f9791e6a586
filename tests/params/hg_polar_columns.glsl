// hg_sdf style: pModPolar repetition of columns around the Y axis; the count is an int parameter.
uniform int columns = 6;       // @range 3 12 @label "Columns"
uniform float ringRadius = 0.55; // @range 0.3 0.7
uniform float columnRadius = 0.1; // @range 0.03 0.15 @log

#define PI 3.14159265

float pModPolar(inout vec2 p, float repetitions) {
    float angle = 2.0 * PI / repetitions;
    float a = atan(p.y, p.x) + angle / 2.0;
    float r = length(p);
    float c = floor(a / angle);
    a = mod(a, angle) - angle / 2.0;
    p = vec2(cos(a), sin(a)) * r;
    if (abs(c) >= (repetitions / 2.0)) c = abs(c);
    return c;
}

float fCylinder(vec3 p, float r, float height) {
    float d = length(p.xz) - r;
    return max(d, abs(p.y) - height);
}

float scene(vec3 p) {
    pModPolar(p.xz, float(columns));
    p.x -= ringRadius;
    return fCylinder(p, columnRadius, 0.6);
}
