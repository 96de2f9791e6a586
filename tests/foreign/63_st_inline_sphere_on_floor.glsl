// Imitates: a beginner's whole Shadertoy from a raymarching tutorial, with no distance function at
// all: mainImage builds a look-at camera, marches `vec3 p = ro + rd * t;` with the scene written
// inline (a ball on a floor slab, joined by min), stops at `d < 0.001`, and shades by the
// distance travelled.
//
// Issue 47, the field written inline: no function of a point to open. The march's own loop says
// what the field is: `t` grows by `d`, which the loop computes from `p`, which it computes from
// `t`. sdfwb runs the loop's body once with p set to the point asked for.
//
// Why the audit should find it clean: the ball and the slab (a box) are exact distances and min()
// joins them; both sit inside the cube and the field grows outside it. Nothing reads iTime.
// expect: entry=mainImage flags=none animated=no
// picture: eye=1.6,1.1,2.4 target=0,-0.1,0 focal=1.8

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(1.6, 1.1, 2.4);
    vec3 ta = vec3(0.0, -0.1, 0.0);
    vec3 ww = normalize(ta - ro);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    vec3 rd = normalize(uv.x * uu + uv.y * vv + 1.8 * ww);

    float t = 0.0;
    for (int i = 0; i < 128; i++) {
        vec3 p = ro + rd * t;
        float ball = length(p - vec3(0.0, 0.1, 0.0)) - 0.45;
        vec3 q = abs(p - vec3(0.0, -0.45, 0.0)) - vec3(0.8, 0.1, 0.8);
        float slab = length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
        float d = min(ball, slab);
        if (d < 0.001 || t > 20.0) break;
        t += d;
    }

    vec3 col = vec3(0.05, 0.06, 0.08);
    if (t < 20.0) col = vec3(0.9, 0.75, 0.6) * exp(-0.25 * t);
    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
