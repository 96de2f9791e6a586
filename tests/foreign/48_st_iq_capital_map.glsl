// Imitates: a whole Shadertoy in Inigo Quilez's layout, but with the
// distance function spelled `Map` (capital M, as people who come from C++
// or HLSL code bases name their functions): `float Map( in vec3 p )`, a
// `castRay()` helper that holds the raymarch loop (`float h = Map(ro+rd*t)`
// ... `t += h`), calcNormal() with the four-tap `vec2(1,-1)*0.5773*eps`
// trick, calcAO(), calcSoftshadow(), render(), setCamera(), and a camera
// orbiting with iMouse: an atom model (a blended cluster of nucleons,
// three tilted orbits and an electron on each) floating in the cube.
//
// Issue 47, class 1: no function has a conventional name (sdf, map, scene,
// sceneSDF, sdScene, de, DE). sdfwb must find `Map` from the shader's own
// march: mainImage -> render() -> castRay(), whose loop advances the ray
// by Map's result. (calcSoftshadow's loop steps by Map too, clamped: the
// same function; calcNormal and calcAO call it outside any march.)
//
// Why the audit should find it clean: spheres and tori are exact
// distances; the nucleons are blended with IQ's polynomial smin (gradient
// h grad a + (1-h) grad b, a convex mix: |grad| <= 1); the orbits are tilted
// by rotations (isometries); nucleus, orbits and electrons are joined with
// min(). The orbits cross each other and run through their electrons, so
// the union has concave creases; across one the audit's per-axis central
// differences mix the two sides' gradients and read at most ~1.04 (two
// planes meeting at any angle), below 1.05, on bands a step wide along
// short crease curves. Continuous, finite, everything within 0.67 of the
// origin, and the field grows outside: no flag. The camera turns with
// iMouse only; nothing reads iTime: not animated.
// expect: entry=Map flags=none animated=no

//------------------------------------------------------------------

mat2 rot( in float a )
{
    float c = cos(a), s = sin(a);
    return mat2( c, s, -s, c );
}

float smin( float a, float b, float k )
{
    float h = clamp( 0.5 + 0.5*(b-a)/k, 0.0, 1.0 );
    return mix( b, a, h ) - k*h*(1.0-h);
}

float sdSphere( in vec3 p, in float r )
{
    return length(p) - r;
}

float sdTorus( in vec3 p, in vec2 t )
{
    return length( vec2(length(p.xz)-t.x, p.y) ) - t.y;
}

// the frame of the k-th orbit: spun about y by 120 degrees per orbit, tilted 60
vec3 orbitFrame( in vec3 p, in float k )
{
    p.xz *= rot( 2.0944*k );
    p.yz *= rot( 1.0472 );
    return p;
}

//------------------------------------------------------------------

float Map( in vec3 p )
{
    // nucleus: seven nucleons, blended
    float d = sdSphere( p, 0.15 );
    d = smin( d, sdSphere( p-vec3( 0.13, 0.04, 0.02), 0.12 ), 0.04 );
    d = smin( d, sdSphere( p-vec3(-0.12, 0.06,-0.03), 0.12 ), 0.04 );
    d = smin( d, sdSphere( p-vec3( 0.02, 0.14,-0.04), 0.11 ), 0.04 );
    d = smin( d, sdSphere( p-vec3(-0.03,-0.13, 0.05), 0.12 ), 0.04 );
    d = smin( d, sdSphere( p-vec3( 0.04,-0.02, 0.14), 0.11 ), 0.04 );
    d = smin( d, sdSphere( p-vec3(-0.02, 0.01,-0.14), 0.11 ), 0.04 );

    // three orbits, each with its electron
    for( int i=0; i<3; i++ )
    {
        float k = float(i);
        vec3 q = orbitFrame( p, k );
        d = min( d, sdTorus( q, vec2(0.6, 0.035) ) );
        float ph = 1.3 + 2.4*k;
        d = min( d, sdSphere( q - vec3(0.6*cos(ph), 0.0, 0.6*sin(ph)), 0.07 ) );
    }
    return d;
}

//------------------------------------------------------------------

float castRay( in vec3 ro, in vec3 rd )
{
    float tmin = 0.5;
    float tmax = 8.0;

    float t = tmin;
    for( int i=0; i<160; i++ )
    {
        float h = Map( ro+rd*t );
        if( abs(h)<0.0002*t || t>tmax ) break;
        t += h;
    }
    if( t>tmax ) t = -1.0;
    return t;
}

float calcSoftshadow( in vec3 ro, in vec3 rd, in float mint, in float tmax )
{
    float res = 1.0;
    float t = mint;
    for( int i=0; i<32; i++ )
    {
        float h = Map( ro + rd*t );
        res = min( res, 8.0*h/t );
        t += clamp( h, 0.02, 0.2 );
        if( res<0.005 || t>tmax ) break;
    }
    return clamp( res, 0.0, 1.0 );
}

vec3 calcNormal( in vec3 pos )
{
    vec2 e = vec2(1.0,-1.0)*0.5773*0.0005;
    return normalize( e.xyy*Map( pos + e.xyy ) +
                      e.yyx*Map( pos + e.yyx ) +
                      e.yxy*Map( pos + e.yxy ) +
                      e.xxx*Map( pos + e.xxx ) );
}

float calcAO( in vec3 pos, in vec3 nor )
{
    float occ = 0.0;
    float sca = 1.0;
    for( int i=0; i<5; i++ )
    {
        float hr = 0.01 + 0.12*float(i)/4.0;
        float dd = Map( nor*hr + pos );
        occ += -(dd-hr)*sca;
        sca *= 0.95;
    }
    return clamp( 1.0 - 3.0*occ, 0.0, 1.0 );
}

vec3 render( in vec3 ro, in vec3 rd )
{
    vec3 col = vec3(0.05,0.06,0.09) + 0.06*rd.y;

    float t = castRay( ro, rd );
    if( t>0.0 )
    {
        vec3 pos = ro + t*rd;
        vec3 nor = calcNormal( pos );
        vec3 ref = reflect( rd, nor );

        // nucleus warm, orbits pale, electrons blue
        float r = length(pos);
        vec3 mate = (r<0.32) ? vec3(0.8,0.35,0.15) : vec3(0.55,0.6,0.65);
        for( int i=0; i<3; i++ )
        {
            float ph = 1.3 + 2.4*float(i);
            vec3 q = orbitFrame( pos, float(i) );
            if( length(q - vec3(0.6*cos(ph), 0.0, 0.6*sin(ph)))<0.08 ) mate = vec3(0.1,0.35,0.9);
        }

        float occ = calcAO( pos, nor );
        vec3  lig = normalize( vec3(-0.4, 0.7, 0.5) );
        float dif = clamp( dot(nor,lig), 0.0, 1.0 ) * calcSoftshadow( pos, lig, 0.02, 3.0 );
        float amb = 0.5 + 0.5*nor.y;
        float spe = pow( clamp( dot(ref,lig), 0.0, 1.0 ), 24.0 );

        vec3 lin = vec3(0.0);
        lin += 1.4*dif*vec3(1.0,0.9,0.75);
        lin += 0.4*amb*occ*vec3(0.4,0.5,0.7);
        col = mate*lin + 0.5*spe*dif;
    }
    return clamp( col, 0.0, 1.0 );
}

mat3 setCamera( in vec3 ro, in vec3 ta, float cr )
{
    vec3 cw = normalize(ta-ro);
    vec3 cp = vec3(sin(cr), cos(cr),0.0);
    vec3 cu = normalize( cross(cw,cp) );
    vec3 cv = normalize( cross(cu,cw) );
    return mat3( cu, cv, cw );
}

void mainImage( out vec4 fragColor, in vec2 fragCoord )
{
    vec2 p = (2.0*fragCoord-iResolution.xy)/iResolution.y;
    vec2 mo = iMouse.xy/iResolution.xy;

    // camera
    float an = 0.6 + 6.2831*mo.x;
    vec3 ta = vec3( 0.0 );
    vec3 ro = ta + vec3( 2.6*cos(an), 0.8 + 1.5*mo.y, 2.6*sin(an) );
    mat3 ca = setCamera( ro, ta, 0.0 );
    vec3 rd = ca * normalize( vec3(p,2.2) );

    vec3 col = render( ro, rd );
    col = pow( col, vec3(0.4545) );

    fragColor = vec4( col, 1.0 );
}
