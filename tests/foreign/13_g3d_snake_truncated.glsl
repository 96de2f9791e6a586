// Imitates: the original sdf-explorer's scene files in G3D's shading
// dialect (Point3 X, float3, lerp, saturate, pi all provided by the host,
// no #version) and its snake, whose distance was capped with min(1.0, ...)
// "so the marcher never takes huge steps". Here the cap is 0.5.
//
// Why truncated: once the true field exceeds 0.5 the result stays at 0.5,
// a flat plateau (|grad f| = 0) starting about 0.8 from the body and
// covering the rest of the probe range out to distance 3 (and the cube's
// corners). Not non-conservative: the body is a sine-wave tube measured
// vertically, whose gradient is at most sqrt(1 + (A k)^2) ~ 1.55 plus 0.06
// from the taper; dividing by 1.65 makes it 1-Lipschitz. Continuous (the
// head is a ball joined with min, the ends clipped with max), finite.
// expect: entry=sdf flags=truncated animated=no

float sdf(Point3 X) {
    const float amplitude  = 0.15;
    const float wavelength = 0.8;
    const float lipschitz  = 1.65;

    float k = 2.0 * pi / wavelength;

    // Body: a tube around y = A sin(k x), thinning towards the tail (+x)
    float3 offset = float3(0.0, X.y - amplitude * sin(k * X.x), X.z);
    float radius = lerp(0.16, 0.08, saturate((X.x + 0.7) / 1.4));
    float body = (length(offset.yz) - radius) / lipschitz;
    body = max(body, abs(X.x) - 0.75);

    // Head: a ball at the front end
    Point3 head = Point3(-0.78, amplitude * sin(k * -0.78), 0.0);
    float d = min(body, length(X - head) - 0.18);

    return min(0.5, d);
}
