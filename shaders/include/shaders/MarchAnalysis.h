#pragma once
// Which function a whole shader marches by, read from glslang's syntax tree: a pasted Shadertoy's
// distance function is called Map, GetDist, sceneDist, field or anything else, but its own ray
// marcher says which one it is. A loop in a function that mainImage's call graph reaches calls a
// user function of a vec3, and a variable the call's point depends on (t in `ro + rd * t`, or the
// point itself) grows by the call's result or its .x (`t += d`, `dO += dS`, `p += rd * h.x`). An
// AO or glow loop, whose accumulator the point does not depend on, does not count.

#include <shaders/ShaderComposer.h>

#include <string>
#include <vector>

namespace sdfwb::shaders {

struct MarchedFunction {
    std::string name; // the function's name
    std::string file; // where its first march call is (the composed map's file name)
    int line = 0;     // that call's line
    int loops = 0;    // loops that step by it
    int loopLine = 0; // the line of the first loop that steps by it (two functions one loop steps by share it)
    // A struct return: the struct's name and the float member the march reads (the distance).
    std::string returnType;
    std::string member;
    std::string valueType; // what it returns: float, vec2, vec4 or the struct's name
    // A vector return whose distance is not its x (`vec4 sdScene(vec3 p)` returning (colour,
    // distance), `t += ds.w`): the component the march steps by (y, z or w). Empty otherwise.
    std::string component;
    // The constant the march compares the distance with to stop (`if (d < 0.001) break;`), in the
    // first loop that has one, and that comparison's line; 0 when none is one constant.
    float hitThreshold = 0.0f;
    int hitLine = 0;
    int depth = 0; // calls from mainImage to the function holding its first march (a primary ray's is nearer)
    // Its calls whose values reach the step of its first loop (`min(sdSphere(p, c1, r1), sdSphere(p,
    // c2, r2))`: 2); more than one makes that loop's inline field the scene, not one call's.
    int stepCalls = 0;

    // A field with `in` parameters after the point (`vec2 Scene(vec3 p, vec3 plateRot)`) whose
    // values mainImage computes and hands to the marching function: how a wrapper gets them.
    //   prelude     mainImage's statements before the one that calls the marching function
    //   traced      the marching function's parameters the call reads, with what mainImage passes
    //   arguments   the text after the point in the march's call (", plateRot")
    //   coordinate, colour   mainImage's parameter names (the wrapper declares them)
    // Empty `arguments` with extraParameters > 0: the values could not be traced (`unresolved`
    // says why).
    int extraParameters = 0;
    std::string prelude, arguments, coordinate, colour, unresolved;
    std::string caller; // whose call of the marching function gives the values: mainImage, or the nearest function's
    std::vector<TracedValue> traced;
    // A field that reads file-scope variables mainImage sets before the march (`radius = ...;` from
    // iTime): their names; `prelude` (with coordinate and colour) then holds mainImage's statements
    // before the call of the marching function, which the wrapper runs first.
    std::vector<std::string> globals;
    std::string setter; // whose statements those are: mainImage, or the function that marches (its parameters zero)
    // Another marched function whose march's result decides whether this one's runs (a refraction's
    // march inside `if (t.x > 0.)` of the primary hit), or is handed to the function that runs it
    // (dr2's `SmokeCol(ro, rd, dstObj)`): its name, or empty; `afterHow` says which, for the reason.
    std::string after, afterHow;
};

// The functions `composed` (a fragment stage holding the user's code and mainImage; no main is
// needed) marches by, in the order of their first march call; empty when the text does not parse
// or has no mainImage.
std::vector<MarchedFunction> marchedFunctions(const ComposedShader& composed);

// A march that writes its field inline, with no function to call: a loop whose float counter grows
// by a value computed from a vec3 point the loop computes from the counter (`vec3 p = ro + rd * t;
// float d = length(p) - 1.; t += d;`, golfed `vec3 p = g * d; ... g += e = length(p) - 1.;`).
// Or the point itself grows by a float computed from it (`p += rd * d;`, `p = c += e * dir;`).
// The field at a point is the loop's body run once with the point set to it (shaders/src/InlineField.h).
struct InlineMarch {
    std::string function;       // the function holding the loop (mainImage or one it reaches)
    std::string file;           // the composed map's file name of the loop
    int line = 0;               // the loop's line
    std::string counter, point; // `t` and `p` (the same where the loop marches the point itself)
    int pointSize = 3;          // 4: a vec4 whose xyz is the point (golfed `p = vec4(z * dir, .1 * iTime)`)
    std::string field;          // where the point itself grows (`p += rd * d`): the float it grows by
    // Where it grows by a float expression of itself in the step (`p += (.1 - length(o.xy)) * d`,
    // golfed): that factor's index (0 or 1) in the step's product, and `field` its text once read.
    int fieldFactor = -1;
    std::string step; // what the counter grows by (`d`, `e * .7`)
    // A march that steps a fixed amount and stops where a value of the point crosses a level (a
    // height field's `if (p.y < h) break;`, a potential's `if (v > 0.) break;`): that comparison as
    // written, `field` the difference that is negative where it stops (`p.y - h`), a level of the
    // shader's values and not a distance. Empty for the other marches.
    std::string level;
    // The wrapper's body: the function's parameters declared (mainImage's as coordinate and
    // colour name them: the caller declares those), its statements before the loop, then `body`.
    std::string prelude, body, coordinate, colour;
    // Where the loop is in another function that mainImage calls at the top of its body
    // (`t = raymarch(ro, rd, torusParams, angle)`): `prelude` is mainImage's statements before that
    // call, run once, and `traced` the function's parameters with what mainImage passes (as
    // MarchedFunction's); `body` then begins with the function's statements before the loop.
    std::vector<TracedValue> traced;
    std::string unresolved; // why the loop's text could not be used (prelude and body empty)
    // The constant the loop compares its step's float with to stop (`if (d < .001) break;`), as
    // MarchedFunction's; 0 when none is one constant.
    float hitThreshold = 0.0f;
    int hitLine = 0;
};

// The inline marches of `composed` (as marchedFunctions reads it), in the order of their loops.
std::vector<InlineMarch> inlineMarches(const ComposedShader& composed);

} // namespace sdfwb::shaders
