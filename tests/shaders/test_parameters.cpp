// The parameter parser: annotated uniforms in the styles people write them, and every mistake
// named at its line and column.
#include <shaders/Parameters.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace sdfwb::shaders;

namespace {

const Parameter* find(const ParameterScan& scan, const std::string& name) {
    for (const Parameter& p : scan.parameters)
        if (p.name == name) return &p;
    return nullptr;
}

std::string messages(const ParameterScan& scan) {
    std::string all;
    for (const Diagnostic& d : scan.diagnostics) all += formatDiagnostic(d) + "\n";
    return all;
}

} // namespace

TEST(Parameters, EveryTypeAndAnnotation) {
    const std::string text = "// a shape family\n"
                             "uniform float radius = 0.5;   // @range 0.1 1.0 @step 0.01 @label \"Sphere radius\"\n"
                             "uniform int count = 4; // @range 1 12\n"
                             "uniform bool hollow = true;\n"
                             "uniform vec2 offset = vec2(0.0); // @range -1 1\n"
                             "uniform vec3 tint = vec3(1, 0.5, 0.25); // @color\n"
                             "uniform highp vec4 rgba = vec4(0.1, 0.2, 0.3, 1.0); // @color @label Paint\n"
                             "uniform float scale = 2.0f; // scale of the noise @range 0.01 100 @log\n"
                             "uniform float plain = -3e-2;\n"
                             "float sdf(vec3 p) { return length(p - vec3(offset, 0.0)) - radius * scale; }\n";
    ParameterScan scan = parseParameters(text, "family.glsl");
    EXPECT_TRUE(scan.diagnostics.empty()) << messages(scan);
    ASSERT_EQ(scan.parameters.size(), 8u);
    const Parameter* radius = find(scan, "radius");
    ASSERT_TRUE(radius);
    EXPECT_EQ(radius->type, ParameterType::Float);
    EXPECT_FLOAT_EQ(radius->defaultValue[0], 0.5f);
    EXPECT_FLOAT_EQ(*radius->minimum, 0.1f);
    EXPECT_FLOAT_EQ(*radius->maximum, 1.0f);
    EXPECT_FLOAT_EQ(*radius->step, 0.01f);
    EXPECT_EQ(radius->label, "Sphere radius");
    EXPECT_EQ(radius->line, 2);
    EXPECT_EQ(radius->column, 1);
    const Parameter* count = find(scan, "count");
    ASSERT_TRUE(count);
    EXPECT_EQ(count->type, ParameterType::Int);
    EXPECT_FLOAT_EQ(*count->maximum, 12.0f);
    EXPECT_FLOAT_EQ(find(scan, "hollow")->defaultValue[0], 1.0f);
    const Parameter* offset = find(scan, "offset");
    EXPECT_EQ(componentCount(offset->type), 2);
    EXPECT_FLOAT_EQ(*offset->minimum, -1.0f);
    const Parameter* tint = find(scan, "tint");
    EXPECT_TRUE(tint->color);
    EXPECT_FLOAT_EQ(tint->defaultValue[2], 0.25f);
    const Parameter* rgba = find(scan, "rgba");
    EXPECT_TRUE(rgba->color);
    EXPECT_EQ(rgba->label, "Paint");
    EXPECT_FLOAT_EQ(rgba->defaultValue[3], 1.0f);
    EXPECT_TRUE(find(scan, "scale")->logarithmic);
    EXPECT_FLOAT_EQ(find(scan, "scale")->defaultValue[0], 2.0f);
    EXPECT_FLOAT_EQ(find(scan, "plain")->defaultValue[0], -0.03f);
    EXPECT_FALSE(find(scan, "plain")->minimum);
}

TEST(Parameters, OnlyFileScopeUniformsWithDefaultsCount) {
    const std::string text = "uniform float iTime;\n"                 // Shadertoy-style: no default, not a parameter
                             "uniform sampler2D noise;\n"             // not a parameter type
                             "uniform float weights[4];\n"            // arrays are not parameters
                             "/* uniform float commented = 1.0; */\n" // in a comment
                             "// uniform float alsoCommented = 1.0;\n"
                             "#define KNOB uniform float macro = 1.0;\n" // in a directive
                             "uniform Block { float inBlock; };\n"       // a block
                             "float sdf(vec3 p) { float uniform_ = 1.0; return length(p) - uniform_; }\n"
                             "uniform float late = 0.25; // @range 0 1\n";
    ParameterScan scan = parseParameters(text, "mixed.glsl");
    EXPECT_TRUE(scan.diagnostics.empty()) << messages(scan);
    ASSERT_EQ(scan.parameters.size(), 1u);
    EXPECT_EQ(scan.parameters[0].name, "late");
    EXPECT_EQ(scan.parameters[0].line, 9);
}

TEST(Parameters, MistakesAreNamedAtTheirLineAndColumn) {
    struct Case {
        const char* text;
        int line, column;
        Severity severity;
        const char* expected;
    };
    const Case cases[] = {
        {"uniform float r = 0.5; // @range 1 0\n", 1, 27, Severity::Error, "is empty"},
        {"\nuniform float r = 0.5; // @range 0.1\n", 2, 27, Severity::Error, "@range takes two numbers"},
        {"uniform int n = 2; // @range 0.5 4\n", 1, 23, Severity::Error, "two whole numbers"},
        {"uniform int n = 2.5;\n", 1, 17, Severity::Error, "whole number"},
        {"uniform float r = radius0 * 2.0;\n", 1, 19, Severity::Error, "literal defaults"},
        {"uniform bool b = 1; \n", 1, 18, Severity::Error, "true or false"},
        {"uniform vec3 c = vec3(1, 2); // @color\n", 1, 18, Severity::Error, "takes 1 or 3 numbers"},
        {"uniform float r = 0.5; // @color\n", 1, 27, Severity::Error, "@color needs a vec3 or vec4"},
        {"uniform float r = 0.5; // @range 0 1 @log\n", 1, 26, Severity::Error, "@log needs a @range with a positive minimum"},
        {"uniform float r = 0.5; // @step -1\n", 1, 27, Severity::Error, "@step takes a positive number"},
        {"uniform float r; // @range 0 1\n", 1, 15, Severity::Error, "need a default"},
        {"uniform float r = 2.0; // @range 0 1\n", 1, 26, Severity::Warning, "outside its @range"},
        {"uniform float r = 0.5; // @rnage 0 1\n", 1, 27, Severity::Warning, "unknown annotation '@rnage'"},
        {"uniform float r = 0.5; // @label \"open\n", 1, 27, Severity::Error, "no closing quote"},
        {"uniform float r = 0.5;\nuniform float r = 0.6;\n", 2, 15, Severity::Error, "declared twice (first at line 1)"},
        {"uniform float r = 1e39;\n", 1, 19, Severity::Error, "must be a number"},
        {"uniform float r = nan;\n", 1, 19, Severity::Error, "must be a number"},
        {"uniform bool b = false; // @range 0 1\n", 1, 28, Severity::Error, "a bool takes no @range"},
        {"uniform vec3 v; slider[uniform float s; slider[0,1,2]\n", 1, 47, Severity::Error, "no closing ] before this ["},
    };
    for (const Case& c : cases) {
        ParameterScan scan = parseParameters(c.text, "bad.glsl");
        ASSERT_FALSE(scan.diagnostics.empty()) << c.text;
        const Diagnostic& d = scan.diagnostics.front();
        EXPECT_EQ(d.file, "bad.glsl");
        EXPECT_EQ(d.line, c.line) << c.text << formatDiagnostic(d);
        EXPECT_EQ(d.column, c.column) << c.text << formatDiagnostic(d);
        EXPECT_EQ(d.severity, c.severity) << c.text << formatDiagnostic(d);
        EXPECT_NE(d.message.find(c.expected), std::string::npos) << c.text << formatDiagnostic(d);
    }
}

TEST(Parameters, HostileTextEndsCleanly) {
    // Unterminated declarations, stray braces and a long run of uniforms: no crash, no hang.
    for (const char* text :
         {"uniform", "uniform float", "uniform float x =", "uniform float x = vec3(", "}}}} uniform float x = 1.0;",
          "uniform vec3 v = vec3(1,,2);", "uniform float x = 1.0; // @", "uniform float x = 1.0; // @label"}) {
        ParameterScan scan = parseParameters(text, "hostile.glsl");
        for (const Diagnostic& d : scan.diagnostics) EXPECT_GE(d.line, 1) << text;
    }
    // A NUL inside an initializer (found by the parameters fuzzer): the number is the whole text up
    // to the `;`, not the "1" before the NUL, so it is not a default sdfwb could write back.
    const std::string nul("uniform float r = 1\0x\n;\nfloat sdf(vec3 p) { return length(p) - r; }\n", 68);
    ParameterScan withNul = parseParameters(nul, "nul.glsl");
    EXPECT_TRUE(withNul.parameters.empty());
    // A slider whose ] closes the next declaration's (found by the fuzzer): both claimed the same
    // default text, so saving defaults wrote it twice ("33,3)"). Only the complete one is a parameter.
    const std::string shared = "uniform vec3 v; slider[uniform float s; slider[-3.0,3.0,5.0] Locked\n";
    ParameterScan overlapping = parseParameters(shared, "shared.frag");
    ASSERT_EQ(overlapping.parameters.size(), 1u);
    EXPECT_EQ(overlapping.parameters[0].name, "s");
    std::string many;
    for (int i = 0; i < 5000; ++i)
        many += "uniform float p" + std::to_string(i) + " = " + std::to_string(i) + ".0; // @range -1 99999\n";
    ParameterScan scan = parseParameters(many, "many.glsl");
    EXPECT_EQ(scan.parameters.size(), 5000u);
    EXPECT_EQ(scan.parameters.back().line, 5000);
}

// ---- values, families and rewriting defaults ----

namespace {

std::vector<Parameter> declared(const std::string& text) {
    ParameterScan scan = parseParameters(text, "family.glsl");
    EXPECT_TRUE(scan.diagnostics.empty()) << messages(scan);
    return scan.parameters;
}

const std::string kFamily = "uniform float radius = 0.5; // @range 0.1 0.9\n"
                            "uniform int count = 4; // @range 1 12\n"
                            "uniform bool hollow = false;\n"
                            "uniform vec3 offset = vec3(0.0, 0.1, 0.0); // @range -1 1\n"
                            "uniform float scale = 1.0; // @range 0.01 100 @log\n"
                            "float sdf(vec3 p) { return length(p - offset) * scale - radius; }\n";

} // namespace

TEST(ParameterValues, ParsedFromTheCommandLineFormAndRefusedWithTheText) {
    auto radius = parseParameterValue("radius=0.3");
    ASSERT_TRUE(radius) << radius.error().message;
    EXPECT_EQ(radius->name, "radius");
    EXPECT_EQ(radius->value, std::vector<float>{0.3f});
    auto offset = parseParameterValue("offset=1, -2.5 ,3e-1");
    ASSERT_TRUE(offset);
    EXPECT_EQ(offset->value, (std::vector<float>{1.0f, -2.5f, 0.3f}));
    auto hollow = parseParameterValue("hollow=true");
    ASSERT_TRUE(hollow);
    EXPECT_EQ(hollow->value, std::vector<float>{1.0f});
    EXPECT_EQ(formatParameterValue(*offset), "offset=1,-2.5,0.3");
    for (const char* bad : {"radius", "=1", "2x=1", "radius=", "radius=nan", "radius=1e39", "radius=1,2,3,4,5", "radius=a"}) {
        auto value = parseParameterValue(bad);
        ASSERT_FALSE(value) << bad;
        EXPECT_NE(value.error().message.find(std::string("'") + bad + "'"), std::string::npos) << value.error().message;
    }
}

TEST(ParameterValues, ResolvedAgainstTheDeclarationsWithClearErrors) {
    const auto params = declared(kFamily);
    auto defaults = resolveParameters(params, {});
    ASSERT_TRUE(defaults);
    ASSERT_EQ(defaults->settings.size(), 5u);
    EXPECT_EQ(defaults->settings[3].value[1], 0.1f); // offset.y, the initializer
    auto given = resolveParameters(params, {{"offset", {0.25f}}, {"count", {7.0f}}, {"radius", {2.0f}}});
    ASSERT_TRUE(given) << given.error().message;
    EXPECT_EQ(given->settings[3].value, (std::array<float, 4>{0.25f, 0.25f, 0.25f, 0.0f})); // one number fills a vector
    EXPECT_EQ(given->settings[1].value[0], 7.0f);
    ASSERT_EQ(given->warnings.size(), 1u); // radius 2 is outside 0.1..0.9: a warning, not an error
    EXPECT_NE(given->warnings[0].find("radius"), std::string::npos);
    struct Case {
        ParameterValue value;
        const char* expected;
    };
    const Case cases[] = {
        {{"radius2", {1.0f}}, "'radius2' is not declared (declared: radius, count, hollow, offset, scale)"},
        {{"offset", {1.0f, 2.0f}}, "'offset' is a vec3: give 1 or 3 numbers, not 2"},
        {{"count", {2.5f}}, "'count' is an int: 2.5 is not a whole number"},
        {{"hollow", {0.5f}}, "'hollow' is a bool"},
        {{"radius", {1.0f, 2.0f}}, "'radius' is a float: give one number"},
    };
    for (const Case& c : cases) {
        auto resolved = resolveParameters(params, {c.value});
        ASSERT_FALSE(resolved) << c.expected;
        EXPECT_NE(resolved.error().message.find(c.expected), std::string::npos) << resolved.error().message;
    }
}

TEST(ParameterValues, SavedAsDefaultsTheFileReadsBackTheSameValues) {
    const auto params = declared(kFamily);
    auto values = resolveParameters(
        params, {{"radius", {0.25f}}, {"offset", {1.0f, -0.5f, 0.125f}}, {"hollow", {1.0f}}, {"count", {9.0f}}});
    ASSERT_TRUE(values);
    const std::string saved = withDefaults(kFamily, params, values->settings);
    EXPECT_NE(saved.find("uniform float radius = 0.25; // @range 0.1 0.9"), std::string::npos) << saved; // comment kept
    EXPECT_NE(saved.find("uniform vec3 offset = vec3(1.0, -0.5, 0.125);"), std::string::npos) << saved;
    EXPECT_NE(saved.find("uniform bool hollow = true;"), std::string::npos) << saved;
    EXPECT_NE(saved.find("uniform int count = 9;"), std::string::npos) << saved;
    const auto again = declared(saved);
    ASSERT_EQ(again.size(), params.size());
    for (std::size_t i = 0; i < again.size(); ++i) EXPECT_EQ(again[i].defaultValue, values->settings[i].value) << again[i].name;
    EXPECT_EQ(again[0].minimum, params[0].minimum);
    EXPECT_EQ(parametersJson(values->settings), R"({"radius":0.25,"count":9,"hollow":true,"offset":[1,-0.5,0.125],"scale":1})");
    EXPECT_EQ(glslLiteral(ParameterType::Float, {3.0f}), "3.0"); // a float literal, not the int 3

    // An initializer written over lines keeps its line breaks: the lines after it keep their
    // numbers (found by the fuzzer: joined, a slider's ] on a later line came onto its line).
    const std::string split = "uniform vec3 tint = vec3(\n    0.1, 0.5,\n    0.25);\nuniform float r = 0.5;\n";
    const auto splitParams = declared(split);
    ASSERT_EQ(splitParams.size(), 2u);
    const std::string rewritten = withDefaults(split, splitParams, {{"tint", ParameterType::Vec3, {0.2f, 0.5f, 0.25f, 0.0f}}});
    EXPECT_EQ(std::count(rewritten.begin(), rewritten.end(), '\n'), std::count(split.begin(), split.end(), '\n')) << rewritten;
    EXPECT_EQ(declared(rewritten)[1].line, 4);

    // A uniform whose `;` is missing before a directive line (found by the fuzzer): its
    // initializer stops at the directive, so the next uniform is not taken into it, whatever the
    // directive's line holds before and after saving (an unclosed `(` before, a closed one after).
    const std::string unended = "uniform float radius = c1 0.05 // a slider\n"
                                "#iUniform color3 tint = color3(0.8, 0.5, 0x \"file://noise.png\"\n"
                                "uniform bool Julia; checkbox[false]\n";
    const auto unendedParams = declared(unended);
    ASSERT_EQ(unendedParams.size(), 2u);
    std::vector<ParameterSetting> defaults;
    for (const Parameter& p : unendedParams) defaults.push_back({p.name, p.type, p.defaultValue});
    const auto saved2 = declared(withDefaults(unended, unendedParams, defaults));
    ASSERT_EQ(saved2.size(), 2u);
    for (std::size_t i = 0; i < saved2.size(); ++i) EXPECT_EQ(saved2[i].name, unendedParams[i].name);
}

TEST(ParameterFamilies, SweepsMakeAGridWithExactEndpoints) {
    const auto params = declared(kFamily);
    auto sweep = parseParameterSweep("radius=0.1:0.7:4");
    ASSERT_TRUE(sweep) << sweep.error().message;
    EXPECT_EQ(formatParameterSweep(*sweep), "radius=0.1:0.7:4");
    auto offsets = parseParameterSweep("offset=0,0,0:1,0.5,0:2");
    ASSERT_TRUE(offsets);
    auto grid = familyInstances(params, {{"scale", {2.0f}}}, {*sweep, *offsets}, 0, 0);
    ASSERT_TRUE(grid) << grid.error().message;
    ASSERT_EQ(grid->size(), 8u);
    // The first sweep varies slowest; ends are the given numbers exactly; the base value holds.
    EXPECT_EQ((*grid)[0][0].name, "radius");
    EXPECT_EQ((*grid)[0][0].value[0], 0.1f);
    EXPECT_EQ((*grid)[1][0].value[0], 0.1f);
    EXPECT_EQ((*grid)[7][0].value[0], 0.7f);
    EXPECT_NEAR((*grid)[2][0].value[0], 0.3f, 1e-6f);
    EXPECT_EQ((*grid)[1][1].name, "offset");
    EXPECT_EQ((*grid)[1][1].value, (std::vector<float>{1.0f, 0.5f, 0.0f}));
    EXPECT_EQ((*grid)[5][2].name, "scale");
    EXPECT_EQ((*grid)[5][2].value[0], 2.0f);
    for (const char* bad : {"radius=0.1:0.7", "radius=0.1:0.7:0", "radius=0.1:0.7:x", "offset=0,0:1:2", "radius=a:b:2"})
        EXPECT_FALSE(parseParameterSweep(bad)) << bad;
    auto unknown = familyInstances(params, {}, {ParameterSweep{"size", {0.0f}, {1.0f}, 2}}, 0, 0);
    ASSERT_FALSE(unknown);
    EXPECT_NE(unknown.error().message.find("'size' is not declared"), std::string::npos);
    auto huge = familyInstances(
        params, {}, {ParameterSweep{"radius", {0.1f}, {0.9f}, 1000}, ParameterSweep{"scale", {1.0f}, {2.0f}, 1000}}, 0, 0);
    ASSERT_FALSE(huge);
    EXPECT_NE(huge.error().message.find("100000"), std::string::npos);
}

TEST(ParameterFamilies, RandomDrawsAreDeterministicAndStayInTheirRanges) {
    const auto params = declared(kFamily);
    auto a = familyInstances(params, {}, {}, 2000, 42);
    auto b = familyInstances(params, {}, {}, 2000, 42);
    auto c = familyInstances(params, {}, {}, 2000, 43);
    ASSERT_TRUE(a && b && c);
    EXPECT_EQ(*a, *b);
    EXPECT_NE(*a, *c);
    int logBelowOne = 0, hollow = 0;
    std::set<int> counts;
    for (const auto& instance : *a) {
        ASSERT_EQ(instance.size(), 5u); // every ranged parameter and the bool
        EXPECT_GE(instance[0].value[0], 0.1f);
        EXPECT_LE(instance[0].value[0], 0.9f);
        EXPECT_EQ(instance[1].value[0], std::round(instance[1].value[0]));
        counts.insert(int(instance[1].value[0]));
        hollow += instance[2].value[0] == 1.0f;
        for (float x : instance[3].value) EXPECT_TRUE(x >= -1.0f && x <= 1.0f);
        logBelowOne += instance[4].value[0] < 1.0f;
    }
    EXPECT_EQ(counts, (std::set<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12})); // every whole value in 1..12, ends included
    EXPECT_NEAR(hollow, 1000, 120);
    EXPECT_NEAR(logBelowOne, 1000, 120); // log-uniform over 0.01..100: half the draws below 1 (uniform: 1 %)
    auto fixed = familyInstances(params, {{"radius", {0.5f}}}, {}, 5, 1);
    ASSERT_TRUE(fixed);
    for (const auto& instance : *fixed) EXPECT_EQ(instance[0].value[0], 0.5f); // a given value is not drawn
    auto none = familyInstances(declared("uniform float plain = 1.0;\n"), {}, {}, 3, 0);
    ASSERT_FALSE(none);
    EXPECT_NE(none.error().message.find("no parameter has a @range"), std::string::npos);
}
