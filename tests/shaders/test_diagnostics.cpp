// Broken shaders must give diagnostics at the exact file and line a person would look at.

#include <shaders/DiagnosticParser.h>
#include <shaders/GlslChecker.h>
#include <shaders/SdfSource.h>
#include <shaders/TracerComposer.h>

#include "common/FirstError.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace sdfwb::shaders;
namespace fs = std::filesystem;

namespace {

fs::path corpus(const std::string& name) { return fs::path(SDFWB_TEST_FILES) / "shaders" / "files" / name; }

// Resolver + signature checks, then glslang on the composed fragment stage.
std::vector<Diagnostic> diagnose(const fs::path& file) {
    PreparedSdf sdf = prepareSdfFile(file, IncludeOptions{});
    if (!sdf.ok()) return sdf.diagnostics;
    auto composed = composeTracer(sdf, TracerFeatures{});
    EXPECT_TRUE(composed.hasValue());
    return checkWithGlslang(*composed);
}

std::string dump(const std::vector<Diagnostic>& diagnostics) {
    std::string out;
    for (const auto& d : diagnostics) out += formatDiagnostic(d) + "\n";
    return out;
}

// The first error, which must exist.
Diagnostic firstError(const std::vector<Diagnostic>& diagnostics) {
    const Diagnostic d = sdfwb::testing::firstError(diagnostics);
    if (d.message.empty()) ADD_FAILURE() << "no error in:\n" << dump(diagnostics);
    return d;
}

} // namespace

TEST(Diagnostics, MissingSemicolonPointsAtTheStatementThatLacksIt) {
    auto diagnostics = diagnose(corpus("missing_semicolon.glsl"));
    Diagnostic d = firstError(diagnostics);
    EXPECT_EQ(d.file, corpus("missing_semicolon.glsl").string()) << dump(diagnostics);
    EXPECT_EQ(d.line, 3) << dump(diagnostics);
    EXPECT_EQ(d.column, 23) << dump(diagnostics); // just after "0.5"
    EXPECT_NE(d.message.find("';'"), std::string::npos) << d.message;
}

TEST(Diagnostics, UndeclaredIdentifierHasLineAndColumn) {
    auto diagnostics = diagnose(corpus("undeclared_identifier.glsl"));
    Diagnostic d = firstError(diagnostics);
    EXPECT_EQ(d.file, corpus("undeclared_identifier.glsl").string());
    EXPECT_EQ(d.line, 3) << dump(diagnostics);
    EXPECT_EQ(d.column, 24) << dump(diagnostics);
    EXPECT_NE(d.message.find("radius"), std::string::npos) << d.message;
}

TEST(Diagnostics, WrongReturnType) {
    auto diagnostics = diagnose(corpus("wrong_return_type.glsl"));
    Diagnostic d = firstError(diagnostics);
    EXPECT_EQ(d.file, corpus("wrong_return_type.glsl").string());
    EXPECT_EQ(d.line, 4) << dump(diagnostics);
}

TEST(Diagnostics, NoSdfFunction) {
    auto diagnostics = diagnose(corpus("no_sdf.glsl"));
    Diagnostic d = firstError(diagnostics);
    EXPECT_EQ(d.file, corpus("no_sdf.glsl").string());
    EXPECT_EQ(d.line, 1);
    EXPECT_NE(d.message.find("float sdf(vec3 p)"), std::string::npos) << d.message;
}

TEST(Diagnostics, SdfWithWrongParametersPointsAtIt) {
    auto diagnostics = diagnose(corpus("wrong_signature.glsl"));
    Diagnostic d = firstError(diagnostics);
    EXPECT_EQ(d.line, 2) << dump(diagnostics);
    EXPECT_EQ(d.column, 1);
    EXPECT_NE(d.message.find("vec2"), std::string::npos) << d.message;
}

TEST(Diagnostics, ErrorInsideAnIncludedFileNamesThatFile) {
    auto diagnostics = diagnose(corpus("include_error/main.glsl"));
    Diagnostic d = firstError(diagnostics);
    EXPECT_EQ(fs::path(d.file), fs::canonical(corpus("include_error/helper.glsl"))) << dump(diagnostics);
    EXPECT_EQ(d.line, 4) << dump(diagnostics);
    EXPECT_EQ(d.column, 24);
}

TEST(Diagnostics, IncludeCycleIsReportedAtTheIncludeThatClosesIt) {
    auto diagnostics = diagnose(corpus("include_cycle/a.glsl"));
    Diagnostic d = firstError(diagnostics);
    EXPECT_EQ(fs::path(d.file), fs::canonical(corpus("include_cycle/b.glsl"))) << dump(diagnostics);
    EXPECT_EQ(d.line, 2);
    EXPECT_NE(d.message.find("cycle"), std::string::npos) << d.message;
}

TEST(Diagnostics, IncludeEscapingTheRootIsRefused) {
    auto diagnostics = diagnose(corpus("escape/root/main.glsl"));
    Diagnostic d = firstError(diagnostics);
    EXPECT_EQ(d.file, corpus("escape/root/main.glsl").string());
    EXPECT_EQ(d.line, 2);
    EXPECT_NE(d.message.find("leaves the allowed include roots"), std::string::npos) << d.message;
}

TEST(Diagnostics, MissingIncludeNamesTheFile) {
    auto diagnostics = diagnose(corpus("include_missing/main.glsl"));
    Diagnostic d = firstError(diagnostics);
    EXPECT_EQ(d.line, 2);
    EXPECT_EQ(d.column, 10);
    EXPECT_NE(d.message.find("does_not_exist.glsl"), std::string::npos) << d.message;
}

TEST(Diagnostics, LineNumbersSurviveIncludes) {
    auto diagnostics = diagnose(corpus("pragma_once/main.glsl"));
    Diagnostic d = firstError(diagnostics);
    EXPECT_EQ(d.file, corpus("pragma_once/main.glsl").string()) << dump(diagnostics);
    EXPECT_EQ(d.line, 8) << dump(diagnostics);
    EXPECT_EQ(diagnostics.size(), 1u) << "the second include of a #pragma once file must not redefine shape():\n"
                                      << dump(diagnostics);
}

TEST(Diagnostics, ValidFilesHaveNoErrors) {
    for (const char* name : {"g3d_dialect.glsl", "own_pi.glsl", "animated.glsl"}) {
        auto diagnostics = diagnose(corpus(name));
        EXPECT_FALSE(hasErrors(diagnostics)) << name << ":\n" << dump(diagnostics);
    }
}

TEST(DiagnosticParser, MesaLogWithColumn) {
    SourceMap map;
    map.files.push_back({"shape.glsl", "float sdf(vec3 p) {\n  return foo;\n}\n"});
    auto diagnostics = parseInfoLog("0:2(10): error: `foo' undeclared\n0:2(3): warning: something odd\n", map);
    ASSERT_EQ(diagnostics.size(), 2u);
    EXPECT_EQ(diagnostics[0].file, "shape.glsl");
    EXPECT_EQ(diagnostics[0].line, 2);
    EXPECT_EQ(diagnostics[0].column, 10);
    EXPECT_EQ(diagnostics[0].severity, Severity::Error);
    EXPECT_EQ(diagnostics[1].severity, Severity::Warning);
}

TEST(DiagnosticParser, NvidiaLog) {
    SourceMap map;
    map.files.push_back({"a.glsl", ""});
    map.files.push_back({"b.glsl", "x\ny\nz\n"});
    auto diagnostics = parseInfoLog("1(3) : error C1008: undefined variable \"zz\"\n", map);
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_EQ(diagnostics[0].file, "b.glsl");
    EXPECT_EQ(diagnostics[0].line, 3);
}

TEST(DiagnosticParser, GlslangSummaryLinesAreDropped) {
    SourceMap map;
    map.files.push_back({"a.glsl", "float x = y;\n"});
    auto diagnostics = parseInfoLog("ERROR: 0:1: 'y' : undeclared identifier \nERROR: 0:1: '' : compilation terminated \n"
                                    "ERROR: 2 compilation errors.  No code generated.\n",
                                    map);
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_EQ(diagnostics[0].column, 11);
}

TEST(DiagnosticParser, UnknownSourceNumberIsNamedNotCrashed) {
    SourceMap map;
    auto diagnostics = parseInfoLog("ERROR: 7:1: 'q' : undeclared identifier\n", map);
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_NE(diagnostics[0].file.find("7"), std::string::npos);
}
