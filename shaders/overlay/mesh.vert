// Mesh and point-cloud overlays: triangles or points through the tracer's camera (the same
// pinhole as its primary rays, so what lies on the zero set covers exactly the pixels of the
// traced surface). Points carry their sample's gradient (attribute 1) to colour them.
layout(location = 0) in vec3 sdfwb_vertex;
layout(location = 1) in vec3 sdfwb_vertexGradient;

uniform vec3 sdfwb_cameraPosition;
uniform vec3 sdfwb_cameraRight; // unit camera basis
uniform vec3 sdfwb_cameraUp;
uniform vec3 sdfwb_cameraForward;
uniform float sdfwb_tanHalfFovY;
uniform float sdfwb_aspect; // width / height
uniform float sdfwb_nearPlane;
uniform float sdfwb_farPlane;
uniform float sdfwb_pointSize; // pixels (points only)

out vec3 sdfwb_world;
out vec3 sdfwb_gradient;

void main() {
    vec3 v = sdfwb_vertex - sdfwb_cameraPosition;
    float z = dot(v, sdfwb_cameraForward); // distance in front of the camera (clip w)
    float n = sdfwb_nearPlane, f = sdfwb_farPlane;
    gl_Position = vec4(dot(v, sdfwb_cameraRight) / (sdfwb_aspect * sdfwb_tanHalfFovY), dot(v, sdfwb_cameraUp) / sdfwb_tanHalfFovY,
                       z * (f + n) / (f - n) - 2.0 * f * n / (f - n), z);
    sdfwb_world = sdfwb_vertex;
    sdfwb_gradient = sdfwb_vertexGradient;
    gl_PointSize = sdfwb_pointSize;
}
