// Imitates: IQ's opDisplace example (a primitive plus sin(20x)sin(20y)
// sin(20z) ripples) and the value-noise bumps that Shadertoys add on top:
// hash()/noise() helpers in the usual fract(sin(...)*43758.5453) style and
// a `float map(vec3 p)` entry.
//
// Why non-conservative: the ripple term 0.08*sin(20x)sin(20y)sin(20z) has
// partial derivatives up to 0.08*20 = 1.6, so |grad f| reaches ~2.6 where
// it lines up with the sphere's gradient and exceeds 1.05 over a large
// part of the cube; the article itself warns that displacement breaks the
// distance bound. The noise adds at most ~0.2 more. Everything is smooth (value
// noise with a smoothstep fade is continuous) and finite, and the sphere
// term grows outside, so only this flag.
// expect: entry=map flags=non-conservative animated=no

float hash( vec3 p )
{
    return fract( sin( dot(p, vec3(127.1, 311.7, 74.7)) ) * 43758.5453 );
}

float noise( in vec3 x )
{
    vec3 i = floor(x);
    vec3 f = fract(x);
    f = f*f*(3.0-2.0*f);

    return mix(mix(mix( hash(i+vec3(0,0,0)), hash(i+vec3(1,0,0)), f.x),
                   mix( hash(i+vec3(0,1,0)), hash(i+vec3(1,1,0)), f.x), f.y),
               mix(mix( hash(i+vec3(0,0,1)), hash(i+vec3(1,0,1)), f.x),
                   mix( hash(i+vec3(0,1,1)), hash(i+vec3(1,1,1)), f.x), f.y), f.z);
}

float sdSphere( vec3 p, float s )
{
    return length(p) - s;
}

float displacement( vec3 p )
{
    return sin(20.0*p.x)*sin(20.0*p.y)*sin(20.0*p.z);
}

float opDisplace( vec3 p )
{
    float d1 = sdSphere( p, 0.55 );
    float d2 = 0.08*displacement( p );
    return d1 + d2;
}

float map( vec3 p )
{
    return opDisplace( p ) + 0.02*(noise( 3.0*p ) - 0.5);
}
