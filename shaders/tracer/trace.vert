// The sphere tracer's geometry. One triangle that covers the viewport (glDrawArrays(GL_TRIANGLES,
// 0, 3)), or with sdfwb_proxyBox the box rays are clipped to (glDrawArrays(GL_TRIANGLES, 0, 36),
// front faces culled): only pixels whose ray meets the box run the tracer; the others keep the
// background the frame was cleared to. No vertex buffer either way.
uniform bool sdfwb_proxyBox;
uniform mat4 sdfwb_proxyClip;  // world to clip space for the tracer's camera (SdfRenderer::render)
uniform float sdfwb_proxyHalf; // half the proxy box's side: a little over the traced box's

// A stage of a program pipeline (each SDF's fragment program is paired with this one): the
// built-in outputs are declared.
out gl_PerVertex {
    vec4 gl_Position;
};

// The box's corners, as bits x, y, z of the index: two triangles a face, counter-clockwise seen
// from outside.
const int sdfwb_kProxyCorners[36] = int[36](4, 6, 2, 4, 2, 0, 1, 3, 7, 1, 7, 5, 1, 5, 4, 1, 4, 0, 2, 6, 7, 2, 7, 3, 2, 3, 1,
                                            2, 1, 0, 4, 5, 7, 4, 7, 6);

void main() {
    if (sdfwb_proxyBox) {
        int corner = sdfwb_kProxyCorners[gl_VertexID];
        vec3 p = vec3(float(corner & 1), float((corner >> 1) & 1), float((corner >> 2) & 1)) * 2.0 - 1.0;
        gl_Position = sdfwb_proxyClip * vec4(p * sdfwb_proxyHalf, 1.0);
    } else {
        vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
        gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
    }
}
