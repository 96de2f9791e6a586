// Hostile and broken SDF sources: each gets a clear diagnostic at the user's own file and line
// before any compiler runs (or is accepted when it is harmless), never a crash or a hang.

#include <shaders/GlslChecker.h>
#include <shaders/SdfSource.h>
#include <shaders/ShaderComposer.h>
#include <shaders/TracerComposer.h>

#include "common/FirstError.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

using namespace sdfwb;
using namespace std::string_literals;
namespace fs = std::filesystem;

namespace {

shaders::PreparedSdf prepare(const std::string& text, const fs::path& path = {}) {
    return shaders::prepareSdf(text, path.empty() ? "hostile.glsl" : path.string(), path, shaders::IncludeOptions{});
}

shaders::Diagnostic firstError(const shaders::PreparedSdf& sdf) { return sdfwb::testing::firstError(sdf.diagnostics); }

} // namespace

TEST(Hostile, OwnMainIsRefusedAtItsLine) {
    auto sdf = prepare("float sdf(vec3 p) { return length(p) - 0.5; }\n\nvoid main() { }\n");
    auto error = firstError(sdf);
    EXPECT_EQ(error.line, 3);
    EXPECT_EQ(error.column, 6);
    EXPECT_NE(error.message.find("main()"), std::string::npos) << error.message;
}

TEST(Hostile, OnlyTheReservedPrefixIsRefused) {
    // Definitions with the prefix, in any letter case: functions, uniforms, structs, constants and
    // macros, each at its own line and column.
    auto sdf = prepare("float sdfwb_map(vec3 p) { return length(p) - 0.5; }\n"
                       "uniform float SDFWB_time;\n"
                       "struct Sdfwb_Hit { float t; };\n"
                       "#define sdfwb_EPS 1e-3\n"
                       "  const float sdfwb_k = 2.0;\n"
                       "float sdf(vec3 p) { return length(p) - 0.5; }\n");
    std::vector<std::pair<int, int>> where;
    for (const auto& d : sdf.diagnostics) {
        ASSERT_EQ(d.severity, shaders::Severity::Error);
        EXPECT_NE(d.message.find("reserved"), std::string::npos) << d.message;
        where.push_back({d.line, d.column});
    }
    EXPECT_EQ(where, (std::vector<std::pair<int, int>>{{1, 7}, {2, 15}, {3, 8}, {4, 9}, {5, 15}}));
    // The names our own shaders used to take, and uses (not definitions) of the prefix, are fine.
    auto fine = prepare("float map(vec3 p) { return length(p) - 0.5; }\n"
                        "uniform float u_time;\nstruct Hit { float t; };\n#define normal(p) p\n"
                        "float sdf(vec3 p) { return map(normal(p)); }\n");
    EXPECT_TRUE(fine.ok()) << (fine.diagnostics.empty() ? "" : fine.diagnostics.front().message);
}

TEST(Hostile, NonAsciiBytesInCodeAreRefusedButCommentsMayHoldAnything) {
    auto bad = prepare("float sdf(vec3 p) {\n  return length(p) - 0.5\xe9;\n}\n");
    auto error = firstError(bad);
    EXPECT_EQ(error.line, 2);
    EXPECT_EQ(error.column, 25);
    EXPECT_NE(error.message.find("0xE9"), std::string::npos) << error.message;
    auto zero = prepare(std::string("float sdf(vec3 p) { return length(p) - 0.5; }\n\0\0garbage", 55));
    EXPECT_FALSE(zero.ok()) << "NUL bytes are binary data";
    auto comment = prepare("// caf\xc3\xa9 \xff\xfe Latin-1 and broken UTF-8 in a comment\nfloat sdf(vec3 p) { return length(p) "
                           "- 0.5; } /* \x80 */\n");
    EXPECT_TRUE(comment.ok());
}

// A NUL byte in a comment is a comment's byte: the compilers read the code past it (glslang and the
// driver get the text's length, not a C string that ends there).
TEST(Hostile, ANulByteInACommentDoesNotEndTheCode) {
    const std::string text = "// pasted \0 junk\nfloat sdf(vec3 p) { return length(p) - 0.5; }\n"s;
    ASSERT_EQ(text.find('\0'), 10u);
    auto sdf = prepare(text);
    ASSERT_TRUE(sdf.ok()) << firstError(sdf).message;
    const std::vector<shaders::ShaderPiece> stage{{"<test main>", "void main() {}\n"}};
    EXPECT_TRUE(shaders::checkWithGlslang(shaders::composeSdfShader(sdf, shaders::Stage::Fragment, stage, {})).empty());
    // A whole shader whose own main() comes after the byte: its march is read, so its field is found.
    auto whole = prepare("// \0\nfloat map(vec3 p) { return length(p) - 1.0; }\n"
                         "void mainImage(out vec4 c, in vec2 f) { float t = 0.0;\n"
                         "  for (int i = 0; i < 64; i++) { float d = map(vec3(0, 0, -3.0 + t)); if (d < 0.001) "
                         "break; t += d; }\n  c = vec4(t); }\n"s);
    EXPECT_TRUE(whole.ok()) << firstError(whole).message;
    EXPECT_EQ(whole.signature.entry, "map");
}

TEST(Hostile, OwnVersionLineIsAcceptedAndTheCheckerStillPasses) {
    auto sdf = prepare("#version 330 core\nfloat sdf(vec3 p) { return length(p) - 0.5; }\n");
    EXPECT_TRUE(sdf.ok());
    auto composed = shaders::composeTracer(sdf, shaders::TracerFeatures{});
    ASSERT_TRUE(composed.hasValue());
    auto diagnostics = shaders::checkWithGlslang(*composed);
    EXPECT_FALSE(shaders::hasErrors(diagnostics)) << (diagnostics.empty() ? "" : diagnostics.front().message);
}

TEST(Hostile, DeepIncludeChainStopsWithTheFileThatWentTooDeep) {
    const fs::path folder = fs::temp_directory_path() / ("sdfwb-deep-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    for (int i = 0; i < 200; ++i)
        std::ofstream(folder / ("inc" + std::to_string(i) + ".glsl"))
            << (i < 199 ? "#include \"inc" + std::to_string(i + 1) + ".glsl\"\n"
                        : std::string("float base(vec3 p) { return length(p) - 0.5; }\n"));
    auto sdf = shaders::prepareSdf("#include \"inc0.glsl\"\nfloat sdf(vec3 p) { return base(p); }\n",
                                   (folder / "deep.glsl").string(), folder / "deep.glsl", shaders::IncludeOptions{});
    auto error = firstError(sdf);
    EXPECT_NE(error.message.find("deeper"), std::string::npos) << error.message;
    EXPECT_NE(error.file.find("inc"), std::string::npos) << error.file;
    fs::remove_all(folder);
}

TEST(Hostile, HugeSourceIsRefusedQuicklyWithItsSize) {
    std::string filler;
    filler.reserve(11u << 20);
    for (int i = 0; filler.size() < (10u << 20); ++i) filler += "float f" + std::to_string(i) + "(float x) { return x * 2.0; }\n";
    auto start = std::chrono::steady_clock::now();
    auto sdf = prepare(filler + "float sdf(vec3 p) { return length(p) - 0.5; }\n");
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    auto error = firstError(sdf);
    EXPECT_NE(error.message.find("MB of code"), std::string::npos) << error.message;
    EXPECT_EQ(error.line, 1);
    EXPECT_LT(seconds, 60.0);
    // 10 MB of comments is not code: accepted.
    std::string comments;
    for (int i = 0; comments.size() < (10u << 20); ++i)
        comments += "// a long comment line that takes room but is no code at all ......\n";
    EXPECT_TRUE(prepare(comments + "float sdf(vec3 p) { return length(p) - 0.5; }\n").ok());
}

// Golfed code written for NVIDIA's driver (a Bonzomatic shader's `#define B(1-fract(t*2))`): a ( after
// a macro's name that begins no parameter list is read as the macro's value, with a warning at the (.
// A real parameter list stays a function-like macro.
TEST(Hostile, AMacroWhoseParenthesisIsNoParameterListIsItsValue) {
    auto sdf = prepare("#define R(0.25+0.25)\n#define F(a, b) ((a) + (b))\n"
                       "float sdf(vec3 p) { return length(p) - F(R, 0.0); }\n");
    ASSERT_TRUE(sdf.ok()) << firstError(sdf).message;
    ASSERT_EQ(sdf.diagnostics.size(), 1u);
    EXPECT_EQ(sdf.diagnostics[0].severity, shaders::Severity::Warning);
    EXPECT_EQ(sdf.diagnostics[0].line, 1);
    EXPECT_EQ(sdf.diagnostics[0].column, 10);
    EXPECT_NE(sdf.diagnostics[0].message.find("read as the value of R"), std::string::npos) << sdf.diagnostics[0].message;
    const std::vector<shaders::ShaderPiece> stage{{"<test main>", "void main() {}\n"}};
    EXPECT_TRUE(shaders::checkWithGlslang(shaders::composeSdfShader(sdf, shaders::Stage::Fragment, stage, {})).empty());
}
