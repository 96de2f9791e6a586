// The parameter parser: annotated uniforms in the styles people write them, and every mistake
// named at its line and column.
#include <shaders/Parameters.h>

#include <gtest/gtest.h>

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
    std::string many;
    for (int i = 0; i < 5000; ++i)
        many += "uniform float p" + std::to_string(i) + " = " + std::to_string(i) + ".0; // @range -1 99999\n";
    ParameterScan scan = parseParameters(many, "many.glsl");
    EXPECT_EQ(scan.parameters.size(), 5000u);
    EXPECT_EQ(scan.parameters.back().line, 5000);
}
