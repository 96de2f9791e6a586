// Matcap: the view-space normal looks up a sphere image (a material captured as a lit sphere).
uniform sampler2D sdfwb_matcap;

vec3 sdfwb_shade(vec3 position, vec3 normal, vec3 direction, sdfwb_Hit hit) {
    vec3 viewNormal = vec3(dot(normal, sdfwb_cameraRight), dot(normal, sdfwb_cameraUp), dot(normal, -sdfwb_cameraForward));
    vec2 uv = viewNormal.xy * 0.49 + 0.5;
    // Level 0, as texture() reads this single-level image in a fragment shader: a compute shader
    // has no derivatives to choose a level by.
    return textureLod(sdfwb_matcap, vec2(uv.x, 1.0 - uv.y), 0.0).rgb;
}
