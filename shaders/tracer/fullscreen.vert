// One triangle that covers the viewport; no vertex buffer needed (glDrawArrays(GL_TRIANGLES, 0, 3)).
out vec2 sdfwb_ndc;

void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    sdfwb_ndc = corner * 2.0 - 1.0;
    gl_Position = vec4(sdfwb_ndc, 0.0, 1.0);
}
