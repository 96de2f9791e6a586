// Imitates: Inigo Quilez's Menger sponge (his "menger fractal" article and
// Shadertoy): sdBox for the outer cube, then for each level a mod()-folded
// cross measured per axis pair, kept with max(); `vec4 map( in vec3 p )`
// returning the distance in .x and trap/occlusion values in .yzw, as his
// shader does. Four levels, scaled to 0.85 to sit inside the cube.
//
// Why the audit should find it clean: at level m the cross term is
// (min(max(r.x,r.y), ...) - 1)/s with r = |1 - 3|mod(p*s/3, 2) - 1||; its
// derivative along any axis is 3 * (s/3) / s = 1 and min/max pick one
// axis at a time, so every term is 1-Lipschitz. r is symmetric under
// a -> -a, so the mod() wrap (a from +1 to -1) does not jump. max() of
// 1-Lipschitz continuous terms stays so; outside, the outer box dominates
// and grows. Uniform scaling by 0.85 keeps the Lipschitz constant. Only
// .yzw (not the distance) change abruptly.
// expect: entry=map flags=none animated=no

const float SCALE = 0.85;

float sdBox( vec3 p, vec3 b )
{
    vec3 di = abs(p) - b;
    float mc = max(di.x, max(di.y, di.z));
    return min(mc, length(max(di, 0.0)));
}

vec4 map( in vec3 p )
{
    p /= SCALE;

    float d = sdBox( p, vec3(1.0) );
    vec4 res = vec4( d, 1.0, 0.0, 0.0 );

    float s = 1.0;
    for( int m=0; m<4; m++ )
    {
        vec3 a = mod( p*s, 2.0 ) - 1.0;
        s *= 3.0;
        vec3 r = abs( 1.0 - 3.0*abs(a) );

        float da = max( r.x, r.y );
        float db = max( r.y, r.z );
        float dc = max( r.z, r.x );
        float c = ( min( da, min(db, dc) ) - 1.0 )/s;

        if( c > d )
        {
            d = c;
            res = vec4( d, min(res.y, 0.2*da*db*dc), (1.0 + float(m))/4.0, 0.0 );
        }
    }

    res.x = d*SCALE;
    return res;
}
