// Imitates: Inigo Quilez's "raymarching primitives" Shadertoy and his
// distance-functions article -- sdXxx( p, params ) primitives with IQ's
// argument order, `vec2 map( in vec3 pos )` answering (distance, material
// id), opU() keeping the nearer vec2, and the calcNormal()/castRay() pair
// (defined as on Shadertoy; sdfwb never calls them).
//
// Why the audit should find it clean: sdSphere, sdBox, sdRoundBox,
// sdTorus, sdCapsule and sdCappedCylinder are exact, sdOctahedron is the
// cheap 1-Lipschitz bound (normal of the face plane), and opU is a min of
// the .x parts, so the distance is continuous with |grad| <= 1. All the
// closed primitives sit inside the cube, so the field keeps growing
// outside it. The material id (.y) jumps, but it is not the distance.
// expect: entry=map flags=none animated=no

float sdSphere( vec3 p, float s )
{
    return length(p)-s;
}

float sdBox( vec3 p, vec3 b )
{
    vec3 d = abs(p) - b;
    return min(max(d.x,max(d.y,d.z)),0.0) + length(max(d,0.0));
}

float sdRoundBox( vec3 p, vec3 b, float r )
{
    vec3 q = abs(p) - b + r;
    return length(max(q,0.0)) + min(max(q.x,max(q.y,q.z)),0.0) - r;
}

float sdTorus( vec3 p, vec2 t )
{
    return length( vec2(length(p.xz)-t.x,p.y) )-t.y;
}

float sdCapsule( vec3 p, vec3 a, vec3 b, float r )
{
    vec3 pa = p-a, ba = b-a;
    float h = clamp( dot(pa,ba)/dot(ba,ba), 0.0, 1.0 );
    return length( pa - ba*h ) - r;
}

float sdCappedCylinder( vec3 p, float h, float r )
{
    vec2 d = abs(vec2(length(p.xz),p.y)) - vec2(r,h);
    return min(max(d.x,d.y),0.0) + length(max(d,0.0));
}

// bound, not exact (cheaper)
float sdOctahedron( vec3 p, float s )
{
    p = abs(p);
    return (p.x+p.y+p.z-s)*0.57735027;
}

//------------------------------------------------------------------

vec2 opU( vec2 d1, vec2 d2 )
{
    return (d1.x<d2.x) ? d1 : d2;
}

//------------------------------------------------------------------

vec2 map( in vec3 pos )
{
    vec2 res = vec2( 1e10, 0.0 );

    // floor slab
    res = opU( res, vec2( sdBox( pos-vec3( 0.0,-0.62, 0.0), vec3(0.9,0.04,0.9) ), 1.0 ) );

    // first row
    res = opU( res, vec2( sdSphere(    pos-vec3(-0.55,-0.3,-0.4), 0.2 ), 26.9 ) );
    res = opU( res, vec2( sdRoundBox(  pos-vec3( 0.0,-0.3,-0.4), vec3(0.18), 0.05 ), 41.0 ) );
    res = opU( res, vec2( sdTorus(     pos-vec3( 0.55,-0.3,-0.4), vec2(0.17,0.05) ), 25.0 ) );

    // second row
    res = opU( res, vec2( sdCapsule(   pos, vec3(-0.65,-0.45,0.3), vec3(-0.45,-0.1,0.45), 0.07 ), 31.9 ) );
    res = opU( res, vec2( sdCappedCylinder( pos-vec3( 0.0,-0.3,0.4), 0.2, 0.15 ), 8.0 ) );
    res = opU( res, vec2( sdOctahedron( pos-vec3( 0.55,-0.3,0.4), 0.25 ), 37.0 ) );

    // something on top
    res = opU( res, vec2( sdBox(       pos-vec3( 0.0, 0.35, 0.0), vec3(0.25,0.08,0.25) ), 16.9 ) );

    return res;
}

vec3 calcNormal( in vec3 pos )
{
    vec2 e = vec2(1.0,-1.0)*0.5773*0.0005;
    return normalize( e.xyy*map( pos + e.xyy ).x +
                      e.yyx*map( pos + e.yyx ).x +
                      e.yxy*map( pos + e.yxy ).x +
                      e.xxx*map( pos + e.xxx ).x );
}

vec2 castRay( in vec3 ro, in vec3 rd )
{
    vec2 res = vec2(-1.0,-1.0);
    float tmin = 0.5;
    float tmax = 20.0;
    float t = tmin;
    for( int i=0; i<70 && t<tmax; i++ )
    {
        vec2 h = map( ro+rd*t );
        if( abs(h.x)<(0.0001*t) )
        {
            res = vec2(t,h.y);
            break;
        }
        t += h.x;
    }
    return res;
}
