// Imitates: a tweet-sized shader for glslCanvas / The Book of Shaders editor (`uniform float
// u_time; uniform vec2 u_resolution;`, `void main()` writing gl_FragColor), golfed the way such
// one-liners are: no distance function and no float for the distance, the point marched by the
// field written in the step itself (`p += d * (FIELD);`), the field read from a turned copy of the
// point (`o = p; o.yz *= mat2(...)`), the colour from how far p got and from u_time.
//
// Host support: main() is Shadertoy's mainImage, u_time and u_resolution Shadertoy's inputs. The
// field is the step's float factor, a product's second operand here: the body up to the step, run
// once at the point given, then that factor (entry=mainImage, as for the inline fields 63-71).
//
// Why the audit should find it clean: the factor is IQ's torus (radii 0.6 and 0.2) of the point
// turned by a rotation (0.8, 0.6; -0.6, 0.8 is orthonormal), an exact distance; it sits inside the
// cube. Animated all the same (as 78): u_time is in the text, though only the colour reads it.
// expect: entry=mainImage flags=none animated=yes

#ifdef GL_ES
precision highp float;
#endif

uniform float u_time;
uniform vec2 u_resolution;

void main() {
    vec3 d = normalize(vec3(gl_FragCoord.xy - .5 * u_resolution, u_resolution.y)), p = vec3(0, 0, -2.5), o;
    for (int i = 0; i < 48; ++i) {
        o = p;
        o.yz *= mat2(.8, .6, -.6, .8);
        p += d * (length(vec2(length(o.xz) - .6, o.y)) - .2);
    }
    gl_FragColor = vec4((sin(p + u_time) * .5 + .5) / (1. + length(p)), 1);
}
