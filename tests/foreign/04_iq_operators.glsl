// Imitates: Inigo Quilez's distance-functions article, "primitive
// combinations" and "alterations" sections: opUnion/opSubtraction/
// opIntersection, their smooth versions, opRound and opOnion, used on his
// sdSphere/sdBox/sdTorus, one `float map(vec3 p)` and an smax helper.
//
// Why the audit should find it clean: min and max of 1-Lipschitz fields
// are 1-Lipschitz and continuous; the smooth union/subtraction/intersection
// (polynomial, mix-and-clamp form) are convex mixes of the two gradients,
// so still 1-Lipschitz; opRound subtracts a constant and opOnion is
// abs(d) - t, both 1-Lipschitz. Everything is bounded inside the cube.
// expect: entry=map flags=none animated=no

float sdSphere( vec3 p, float s )
{
    return length(p)-s;
}

float sdBox( vec3 p, vec3 b )
{
    vec3 q = abs(p) - b;
    return length(max(q,0.0)) + min(max(q.x,max(q.y,q.z)),0.0);
}

float sdTorus( vec3 p, vec2 t )
{
    vec2 q = vec2(length(p.xz)-t.x,p.y);
    return length(q)-t.y;
}

float opUnion( float d1, float d2 ) { return min(d1,d2); }
float opSubtraction( float d1, float d2 ) { return max(-d1,d2); }
float opIntersection( float d1, float d2 ) { return max(d1,d2); }

float opSmoothUnion( float d1, float d2, float k )
{
    float h = clamp( 0.5 + 0.5*(d2-d1)/k, 0.0, 1.0 );
    return mix( d2, d1, h ) - k*h*(1.0-h);
}

float opSmoothSubtraction( float d1, float d2, float k )
{
    float h = clamp( 0.5 - 0.5*(d2+d1)/k, 0.0, 1.0 );
    return mix( d2, -d1, h ) + k*h*(1.0-h);
}

float opSmoothIntersection( float d1, float d2, float k )
{
    float h = clamp( 0.5 - 0.5*(d2-d1)/k, 0.0, 1.0 );
    return mix( d2, d1, h ) + k*h*(1.0-h);
}

float smax( float a, float b, float k )
{
    return -opSmoothUnion( -a, -b, k );
}

// rounding: the shape grows by rad
float opRound( float d, float rad )
{
    return d - rad;
}

// a shell of thickness 2*thickness around the surface
float opOnion( float d, float thickness )
{
    return abs(d) - thickness;
}

float map( vec3 p )
{
    // blob: a sphere melted into a box
    vec3 q = p - vec3(-0.5, 0.35, 0.0);
    float blob = opSmoothUnion( sdSphere(q - vec3(0.0,0.15,0.0), 0.18), sdBox(q, vec3(0.2,0.1,0.2)), 0.1 );

    // a rounded box with a spherical bite taken out of it
    q = p - vec3(0.45, 0.35, 0.0);
    float bitten = opSubtraction( sdSphere(q - vec3(0.15,0.15,0.15), 0.2), opRound( sdBox(q, vec3(0.17)), 0.05 ) );

    // onion sphere, cut open by a plane so the layers show
    q = p - vec3(-0.45, -0.4, 0.0);
    float shell = opOnion( opOnion( sdSphere(q, 0.3), 0.06 ), 0.02 );
    shell = opIntersection( shell, q.y - 0.05 );

    // torus intersected (smoothly) with a slab, then carved by a box
    q = p - vec3(0.45, -0.4, 0.0);
    float ring = opSmoothIntersection( sdTorus(q, vec2(0.25,0.1)), abs(q.y) - 0.06, 0.03 );
    ring = opSmoothSubtraction( sdBox(q - vec3(0.0,0.0,0.3), vec3(0.12,0.2,0.12)), ring, 0.03 );

    float d = opUnion( opUnion( blob, bitten ), opUnion( shell, ring ) );

    // a thin plinth everything stands on, its front trimmed with smax
    return opUnion( d, smax( sdBox(p - vec3(0.0,-0.78,0.0), vec3(0.85,0.05,0.6)), -(p.z + 0.55), 0.02 ) );
}
