// Imitates: a whole Shadertoy in Inigo Quilez's "raymarching primitives"
// style, pasted unmodified: sdXxx() primitives, `vec2 map( in vec3 pos )`
// answering (distance, material id) with opU(), bounding boxes that skip a
// group of primitives when the box is already farther than the best hit,
// the ZERO macro (min(iFrame,0)) that keeps loops from being unrolled,
// calcNormal() with the tetrahedron technique, calcAO(), calcSoftshadow(),
// raycast() clipped to a bounding box, render(), setCamera(ro, ta, cr), and
// mainImage() with a 2x2 AA loop over iResolution and a camera turning with
// iTime. No floor: the primitives float in the unit cube, over a sky that
// depends on rd.y only, so the picture can be compared with sdfwb's tracer.
//
// Why the audit should find it clean: sdSphere, sdBoxFrame, sdTorus,
// sdCapsule, sdRoundBox, sdCappedCylinder and sdLink are exact, and opU is
// a min of the .x parts, so the distance is continuous with |grad| <= 1.
// The bounding-box skips change nothing: a group is skipped only when the
// distance to its box (a lower bound of the distance to anything inside)
// is already >= res.x, so the min would have kept res anyway. Everything
// sits inside the cube, so the field grows outside it. iTime only turns
// the camera in mainImage (the map never reads it), but the file uses it,
// so sdfwb treats the file as animated.
// expect: entry=map flags=none animated=yes
// picture: eye=2.2,1.2,2.4 target=0,-0.1,0 focal=3.2

#define AA 2   // make this 1 if your machine is too slow

#define ZERO (min(iFrame,0))

//------------------------------------------------------------------

float dot2( in vec3 v ) { return dot(v,v); }

float boxDist( in vec3 d )
{
    return length(max(d,0.0)) + min(max(d.x,max(d.y,d.z)),0.0);
}

float sdSphere( vec3 p, float s )
{
    return length(p)-s;
}

float sdBox( vec3 p, vec3 b )
{
    return boxDist( abs(p)-b );
}

float sdRoundBox( vec3 p, vec3 b, float r )
{
    return boxDist( abs(p)-b+r ) - r;
}

// the twelve edges of a box, e thick
float sdBoxFrame( vec3 p, vec3 b, float e )
{
    p = abs(p)-b;
    vec3 q = abs(p+e)-e;
    return min( min( boxDist(vec3(p.x,q.y,q.z)),
                     boxDist(vec3(q.x,p.y,q.z)) ),
                     boxDist(vec3(q.x,q.y,p.z)) );
}

float sdTorus( vec3 p, vec2 t )
{
    return length( vec2(length(p.xz)-t.x,p.y) )-t.y;
}

float sdCapsule( vec3 p, vec3 a, vec3 b, float r )
{
    vec3 pa = p-a, ba = b-a;
    float h = clamp( dot(pa,ba)/dot2(ba), 0.0, 1.0 );
    return length( pa - ba*h ) - r;
}

float sdCappedCylinder( vec3 p, float h, float r )
{
    vec2 d = abs(vec2(length(p.xz),p.y)) - vec2(r,h);
    return min(max(d.x,d.y),0.0) + length(max(d,0.0));
}

// a chain link: a torus of radius r1 stretched by le along y
float sdLink( vec3 p, float le, float r1, float r2 )
{
    vec3 q = vec3( p.x, max(abs(p.y)-le,0.0), p.z );
    return length( vec2(length(q.xy)-r1,q.z) ) - r2;
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

    // back row
    if( sdBox( pos-vec3(0.0,-0.2,-0.45), vec3(0.85,0.28,0.25) )<res.x )
    {
    res = opU( res, vec2( sdSphere(    pos-vec3(-0.6,-0.2,-0.45), 0.22 ), 1.0 ) );
    res = opU( res, vec2( sdBoxFrame(  pos-vec3( 0.0,-0.2,-0.45), vec3(0.2), 0.03 ), 2.0 ) );
    res = opU( res, vec2( sdTorus(     pos-vec3( 0.6,-0.2,-0.45), vec2(0.18,0.06) ), 3.0 ) );
    }

    // front row
    if( sdBox( pos-vec3(0.0,-0.2,0.45), vec3(0.85,0.28,0.25) )<res.x )
    {
    res = opU( res, vec2( sdCapsule(   pos, vec3(-0.7,-0.38,0.45), vec3(-0.5,-0.02,0.45), 0.07 ), 4.0 ) );
    res = opU( res, vec2( sdRoundBox(  pos-vec3( 0.0,-0.2,0.45), vec3(0.18), 0.05 ), 5.0 ) );
    res = opU( res, vec2( sdCappedCylinder( pos-vec3( 0.6,-0.2,0.45), 0.2, 0.16 ), 6.0 ) );
    }

    // on top, in the middle
    if( sdBox( pos-vec3(0.0,0.35,0.0), vec3(0.2,0.3,0.1) )<res.x )
    {
    res = opU( res, vec2( sdLink(      pos-vec3( 0.0, 0.35, 0.0), 0.12, 0.12, 0.04 ), 7.0 ) );
    }

    return res;
}

//------------------------------------------------------------------

// ray against an axis-aligned box of half size rad at the origin: (tnear, tfar)
vec2 iBox( in vec3 ro, in vec3 rd, in vec3 rad )
{
    vec3 inv = 1.0/rd;
    vec3 mid = -inv*ro;
    vec3 ext = abs(inv)*rad;
    vec3 ta = mid - ext;
    vec3 tb = mid + ext;
    return vec2( max(max(ta.x,ta.y),ta.z), min(min(tb.x,tb.y),tb.z) );
}

vec2 raycast( in vec3 ro, in vec3 rd )
{
    vec2 res = vec2(-1.0,-1.0);

    float tmin = 0.1;
    float tmax = 20.0;

    // only march where the scene can be
    vec2 tb = iBox( ro, rd, vec3(0.95) );
    if( tb.x<tb.y && tb.y>0.0 && tb.x<tmax )
    {
        tmin = max(tb.x,tmin);
        tmax = min(tb.y,tmax);

        float t = tmin;
        for( int i=ZERO; i<256 && t<tmax; i++ )
        {
            vec2 h = map( ro+rd*t );
            if( abs(h.x)<(0.0001*t) )
            {
                res = vec2(t,h.y);
                break;
            }
            t += h.x;
        }
    }

    return res;
}

// https://iquilezles.org/articles/rmshadows (the idea; this is our code)
float calcSoftshadow( in vec3 ro, in vec3 rd, in float mint, in float tmax )
{
    float res = 1.0;
    float t = mint;
    for( int i=ZERO; i<32; i++ )
    {
        float h = map( ro + rd*t ).x;
        res = min( res, clamp( 10.0*h/t, 0.0, 1.0 ) );
        t += clamp( h, 0.01, 0.15 );
        if( res<0.003 || t>tmax ) break;
    }
    return res*res*(3.0-2.0*res);
}

const vec3 kTetra[4] = vec3[4]( vec3( 1,-1,-1), vec3(-1,-1, 1),
                                vec3(-1, 1,-1), vec3( 1, 1, 1) );

// tetrahedron technique: four taps instead of six
vec3 calcNormal( in vec3 pos )
{
    const float h = 0.0005;
    vec3 n = vec3(0.0);
    for( int i=ZERO; i<4; i++ )
    {
        vec3 e = 0.5773*kTetra[i];
        n += e*map( pos + h*e ).x;
    }
    return normalize(n);
}

float calcAO( in vec3 pos, in vec3 nor )
{
    float occ = 0.0;
    float sca = 1.0;
    for( int i=ZERO; i<5; i++ )
    {
        float h = 0.015 + 0.03*float(i);
        float d = map( pos + h*nor ).x;
        occ += (h-d)*sca;
        sca *= 0.9;
        if( occ>0.4 ) break;
    }
    return clamp( 1.0 - 2.5*occ, 0.0, 1.0 ) * (0.6+0.4*nor.y);
}

vec3 render( in vec3 ro, in vec3 rd )
{
    // sky
    vec3 col = vec3(0.7, 0.75, 0.9) - max(rd.y,0.0)*0.3;

    vec2 res = raycast(ro,rd);
    float t = res.x;
    float m = res.y;
    if( m>-0.5 )
    {
        vec3 pos = ro + t*rd;
        vec3 nor = calcNormal( pos );

        // material: warm colours, little blue
        vec3 mate = 0.5 + 0.4*sin( m*1.9 + vec3(0.0,0.9,1.8) );
        mate *= vec3(1.0,0.9,0.2);

        // lighting
        float occ = calcAO( pos, nor );

        vec3 lin = vec3(0.0);

        // sun
        {
            vec3  lig = normalize( vec3(0.6, 0.7, 0.3) );
            vec3  hal = normalize( lig-rd );
            float dif = clamp( dot( nor, lig ), 0.0, 1.0 );
                  dif *= calcSoftshadow( pos, lig, 0.02, 2.5 );
            float spe = pow( clamp( dot( nor, hal ), 0.0, 1.0 ), 16.0 );
                  spe *= dif;
                  spe *= 0.04+0.96*pow( clamp(1.0-dot(hal,lig),0.0,1.0), 5.0 );
            lin += 2.0*dif*vec3(1.30,1.00,0.70);
            lin += 4.0*spe*vec3(1.30,1.00,0.70);
        }
        // sky
        {
            float dif = sqrt( clamp( 0.5+0.5*nor.y, 0.0, 1.0 ) );
                  dif *= occ;
            lin += 0.6*dif*vec3(0.40,0.60,1.15);
        }
        // back
        {
            float dif = clamp( dot( nor, normalize(vec3(-0.5,0.0,-0.6)) ), 0.0, 1.0 );
                  dif *= occ;
            lin += 0.5*dif*vec3(0.30,0.25,0.20);
        }
        // sss-ish rim, and a little ambient so no side is black
        {
            float dif = pow( clamp( 1.0+dot(nor,rd), 0.0, 1.0 ), 2.0 );
                  dif *= occ;
            lin += 0.25*dif*vec3(1.0);
            lin += 0.08;
        }
        col = mate*lin;
    }

    return clamp( col, 0.0, 1.0 );
}

mat3 setCamera( in vec3 ro, in vec3 ta, float cr )
{
    vec3 cw = normalize(ta-ro);
    vec3 cp = vec3(sin(cr), cos(cr),0.0);
    vec3 cu = normalize( cross(cw,cp) );
    vec3 cv =          ( cross(cu,cw) );
    return mat3( cu, cv, cw );
}

void mainImage( out vec4 fragColor, in vec2 fragCoord )
{
    // camera: turns slowly about the y axis
    float an = 0.15*iTime;
    vec3 ta = vec3( 0.0, -0.1, 0.0 );
    vec3 ro = ta + vec3( 2.2*cos(an) + 2.4*sin(an), 1.3, 2.4*cos(an) - 2.2*sin(an) );
    // camera-to-world transformation
    mat3 ca = setCamera( ro, ta, 0.0 );

    vec3 tot = vec3(0.0);
    for( int m=ZERO; m<AA; m++ )
    for( int n=ZERO; n<AA; n++ )
    {
        // pixel coordinates, the AA samples centred on the pixel
        vec2 o = (vec2(float(m),float(n)) + 0.5) / float(AA) - 0.5;
        vec2 p = (2.0*(fragCoord+o)-iResolution.xy)/iResolution.y;

        // focal length
        const float fl = 3.2;

        // ray direction
        vec3 rd = ca * normalize( vec3(p,fl) );

        // render
        vec3 col = render( ro, rd );

        // gamma
        col = pow( col, vec3(0.4545) );

        tot += col;
    }
    tot /= float(AA*AA);

    fragColor = vec4( tot, 1.0 );
}
