#pragma once
// A field written inline in a march loop (`for (...) { vec3 p = ro + rd * t; float d = length(p) - 1.;
// if (d < 1e-3) break; t += d; }`, golfed `g += e = ...`), as text: the loop's body run once at a
// given point. MarchAnalysis finds the loop, its counter and its point from glslang's tree; this
// file reads the loop's text.

#include <set>
#include <string>
#include <vector>

namespace sdfwb::shaders {

// Just past the statement that starts at or after `at` in `text` (comments blanked): a block, an
// if/else, a loop, a switch or a simple statement up to its semicolon; npos when it does not end.
std::size_t statementEnd(const std::string& text, std::size_t at);

// The statements of a block's inside, in order (empty when one does not end).
std::vector<std::string> splitStatements(const std::string& text);

// `text` with the break, continue, return and discard that leave the enclosing loop blanked (the
// break and continue of loops and switches nested in it stay; their return and discard, which
// would leave the field, go too): the loop's body run once must reach its step.
std::string withoutLoopExits(const std::string& text);

// `text` with the line that starts at `line` rewritten when it holds no loop keyword but uses an
// object-like macro that expands to a loop (`#define c F{...}` with `#define F for(...)`, golfed
// code): that use replaced by its expansion, every object-like macro in it expanded too, on the
// same line (the lines after it keep their numbers). Else `text` as it is.
std::string withLoopMacroExpanded(const std::string& text, std::size_t line);

// The block that computes the field at `sdfwb_point` from the loop whose keyword is at `keyword`
// in `text`: the loop's initialisation, its body's statements up to the one that advances
// `counter` (`counter += STEP;`) with `point` set to sdfwb_point after the statement that computes
// it from `counter` and those right after it that only move or turn it (the camera's placement),
// then `return float(STEP);`. `step` receives STEP. Empty, with `why`,
// when the loop does not have that form. With `pointSize` 4 the point is a vec4 whose xyz is set.
std::string inlineFieldBody(const std::string& text, std::size_t keyword, const std::string& counter, const std::string& point,
                            std::string& step, std::string& why, int pointSize = 3);

// The same for a loop that marches the point itself (`p += rd * d;`, `p = c += e * dir;`) by a
// float `field` computed from it: the body with `point` set to sdfwb_point at its start, up to the
// step when the field is computed before it, else all of it with the step left out (a copy it
// makes, `p = c`, kept); then `return float(field);`. `step` receives what the point grows by.
// With `factor` 0 or 1 the field is that factor of the step's product (`p += (.1 - length(o.xy)) *
// d`): the body up to the step, and `field` receives the factor's text.
std::string pointMarchBody(const std::string& text, std::size_t keyword, const std::string& point, std::string& field, int factor,
                           std::string& step, std::string& why);

// The same for a loop that steps a fixed amount (`t += .05`, `p += rd * .05` with `counter` the
// point) and stops where a value of the point crosses a level: an if after the point that leaves
// the loop (`if (p.y < h) break;`, `if (v > 0.) return t;`), else the loop's test or an if that
// holds the step (`if (h < p.y) { t += dt; p = ...; h = f(p.xz); }`). The comparison's side must
// mention one of `levels.values` (what the loop computes from the point through the shader's
// functions, and those functions), or both its sides one of `levels.sides` (the point and what the
// loop computes from it: a height written inline). The body computes the point's value as the loop does (the statements
// before that if, or all of them), then returns `field`: the sides' difference, negative where the
// march stops (`p.y - h`, `0.0 - v`); `level` receives the comparison as written.
struct LevelNames {
    std::set<std::string> values; // a side that mentions one makes the comparison the level
    std::set<std::string> sides;  // two sides that each mention one do (`cos(p.z) - abs(sin(p.x)) < p.y`)
};
std::string levelFieldBody(const std::string& text, std::size_t keyword, const std::string& counter, const std::string& point,
                           const LevelNames& levels, std::string& field, std::string& level, std::string& step, std::string& why);

} // namespace sdfwb::shaders
