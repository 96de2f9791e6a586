// Shadertoy / IQ style: a map() with sdTorus, parameters as annotated uniforms that any GLSL
// compiler accepts (the initializer is the default).
uniform float majorRadius = 0.6; // @range 0.2 0.8 @label "Major radius"
uniform float minorRadius = 0.2; // @range 0.02 0.3 @step 0.01
uniform vec3 offset = vec3(0.0); // @range -0.2 0.2
uniform bool capped = false;

float sdTorus(vec3 p, vec2 t) {
    vec2 q = vec2(length(p.xz) - t.x, p.y);
    return length(q) - t.y;
}

float map(vec3 p) {
    float d = sdTorus(p - offset, vec2(majorRadius, minorRadius));
    if (capped) d = max(d, p.x);
    return d;
}
