// Imitates: the size-coding competitions on Shadertoy (the [SH16A] and [SH17A] two-tweet entries),
// where a march is written once in a `#define` and used twice, for the view ray and the shadow ray;
// single-letter macros for vec3 and normalize, a `for` written by a macro, the point itself marched
// (`P += T*d`) by a distance an inner loop computes.
//
// Issue 47, a march in a macro: glslang places the loop at the line that uses the macro, whose text
// holds no loop. sdfwb reads the loop from that use's expansion (object-like macros, expanded on
// the same line); the view ray's march, the first, is the field.
//
// Why the audit should find it clean: the union (min) of four balls (radius 0.4 on the x axis at
// -1.5, -0.5, 0.5, 1.5) and the floor y = -1, exact distances all, is exact outside and a bound
// inside; balls have no vertical faces for the floor to cut short (README, 47). Nothing reads iTime.
// expect: entry=mainImage flags=none animated=no

#define V vec3
#define Q normalize
#define L for(int i=0;i<80;i++)
#define M L{T=P.y+1.;for(int k=0;k<4;k++)T=min(T,length(P-V(float(k)-1.5,0,0))-.4);P+=T*d;}

void mainImage(out vec4 f, vec2 u) {
    V r = iResolution, P = V(0, .5, -4), d = Q(V(u - .5 * r.xy, r.y)), l = Q(V(-3, 4, -2)), c;
    float T;
    M
    c = P.y < -.99 ? V(.3 + .2 * mod(floor(P.x) + floor(P.z), 2.)) : V(.9, .5, .2) * (.6 + .4 * P.y / .4);
    d = l;
    P += .02 * l;
    M
    f = vec4(sqrt(c * (T > .01 ? 1. : .4)), 1);
}
