// Matcap: the view-space normal looks up a sphere image (a material captured as a lit sphere).
uniform sampler2D u_matcap;

vec3 shade(vec3 position, vec3 normal, vec3 direction, Hit hit) {
    vec3 viewNormal = vec3(dot(normal, u_cameraRight), dot(normal, u_cameraUp), dot(normal, -u_cameraForward));
    vec2 uv = viewNormal.xy * 0.49 + 0.5;
    return texture(u_matcap, vec2(uv.x, 1.0 - uv.y)).rgb;
}
