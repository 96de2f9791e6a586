// The include resolver: search order, roots, #pragma once, comments, line mapping.

#include <shaders/IncludeResolver.h>
#include <shaders/SdfSource.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

using namespace sdfwb::shaders;
namespace fs = std::filesystem;

namespace {

class TemporaryFolder {
public:
    TemporaryFolder() {
        m_path = fs::temp_directory_path() / ("sdfwb-test-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                              "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(m_path);
        fs::create_directories(m_path);
    }
    ~TemporaryFolder() { fs::remove_all(m_path); }
    fs::path write(const std::string& name, const std::string& text) const {
        fs::path file = m_path / name;
        fs::create_directories(file.parent_path());
        std::ofstream(file) << text;
        return file;
    }
    const fs::path& path() const { return m_path; }

private:
    fs::path m_path;
};

} // namespace

TEST(Includes, LibraryRootIsSearchedAfterTheIncludingFolder) {
    TemporaryFolder folder;
    folder.write("lib/shared.glsl", "float fromLibrary() { return 1.0; }\n");
    folder.write("project/shared.glsl", "float fromProject() { return 2.0; }\n");
    fs::path main = folder.write("project/main.glsl", "#include \"shared.glsl\"\nfloat sdf(vec3 p) { return 0.0; }\n");
    IncludeOptions options;
    options.libraryRoots = {folder.path() / "lib"};
    ResolvedSource resolved = resolveIncludes("#include \"shared.glsl\"\n", main.string(), main, options);
    EXPECT_TRUE(resolved.diagnostics.empty());
    EXPECT_NE(resolved.text.find("fromProject"), std::string::npos);
    EXPECT_EQ(resolved.text.find("fromLibrary"), std::string::npos);

    // Unsaved text (no folder) finds the library's copy.
    ResolvedSource unsaved = resolveIncludes("#include \"shared.glsl\"\n", "<editor>", {}, options);
    EXPECT_TRUE(unsaved.diagnostics.empty());
    EXPECT_NE(unsaved.text.find("fromLibrary"), std::string::npos);
}

TEST(Includes, SymlinkOutOfTheRootsIsRefused) {
    TemporaryFolder folder;
    folder.write("outside/secret.glsl", "float secret() { return 42.0; }\n");
    fs::path main = folder.write("root/main.glsl", "#include \"link.glsl\"\n");
    fs::create_symlink(folder.path() / "outside" / "secret.glsl", folder.path() / "root" / "link.glsl");
    ResolvedSource resolved = resolveIncludes("#include \"link.glsl\"\n", main.string(), main, IncludeOptions{});
    ASSERT_EQ(resolved.diagnostics.size(), 1u);
    EXPECT_NE(resolved.diagnostics[0].message.find("leaves the allowed include roots"), std::string::npos);
    EXPECT_EQ(resolved.text.find("secret()"), std::string::npos);
}

TEST(Includes, DirectivesInCommentsAreIgnoredAndVersionLinesBlanked) {
    std::string text =
        "#version 330\n/*\n#include \"nothing.glsl\"\n*/\n// #include \"nothing.glsl\"\nfloat sdf(vec3 p) { return 0.0; }\n";
    ResolvedSource resolved = resolveIncludes(text, "<editor>", {}, IncludeOptions{});
    EXPECT_TRUE(resolved.diagnostics.empty());
    EXPECT_EQ(resolved.text.find("#version"), std::string::npos);
    EXPECT_EQ(resolved.text.rfind("#line 1 0\n", 0), 0u);
}

TEST(Includes, DeepChainsStopAtTheLimit) {
    TemporaryFolder folder;
    for (int i = 0; i < 40; ++i)
        folder.write("f" + std::to_string(i) + ".glsl", "#include \"f" + std::to_string(i + 1) + ".glsl\"\n");
    folder.write("f40.glsl", "float leaf() { return 0.0; }\n");
    fs::path main = folder.path() / "f0.glsl";
    IncludeOptions options;
    options.maxDepth = 32;
    ResolvedSource resolved = resolveIncludes("#include \"f1.glsl\"\n", main.string(), main, options);
    ASSERT_EQ(resolved.diagnostics.size(), 1u);
    EXPECT_NE(resolved.diagnostics[0].message.find("deeper than 32"), std::string::npos);
}

TEST(Includes, MalformedIncludeIsAnError) {
    ResolvedSource resolved = resolveIncludes("float a;\n#include <system.glsl>\n", "<editor>", {}, IncludeOptions{});
    ASSERT_EQ(resolved.diagnostics.size(), 1u);
    EXPECT_EQ(resolved.diagnostics[0].line, 2);
}

TEST(SdfSignature, StaticAnimatedAndPrototypes) {
    EXPECT_TRUE(detectSignature("float sdf(vec3 p) { return 0.0; }").found);
    EXPECT_FALSE(detectSignature("float sdf(vec3 p) { return 0.0; }").animated);
    EXPECT_TRUE(detectSignature("float sdf(in vec3 p, float t)\n{ return t; }").animated);
    EXPECT_TRUE(detectSignature("float sdf(Point3 X) { return 0.0; }").found);
    EXPECT_FALSE(detectSignature("float sdf(vec3 p);").found) << "a prototype is not a definition";
    EXPECT_FALSE(detectSignature("float sdf2(vec3 p) { return 0.0; }").found);
}

TEST(CompatNeeds, OnlySymbolsUsedAndNotDeclared) {
    auto needs = detectCompatNeeds(stripComments("float sdf(float3 p) { return saturate(p.x) * pi; } // lerp"));
    EXPECT_EQ(needs.symbols, (std::vector<std::string>{"pi", "saturate", "float3"}));
    EXPECT_FALSE(detectCompatNeeds("const float pi = 3.14; float sdf(vec3 p) { return pi; }").any());
    EXPECT_FALSE(detectCompatNeeds("#define saturate(x) clamp(x, 0., 1.)\nfloat sdf(vec3 p) { return saturate(p.x); }").any());
    EXPECT_FALSE(detectCompatNeeds("float sdf(vec3 p) { return length(p) - 0.5; }").any());
}

// Issue 32, point 2: a local variable or a parameter named like a built-in hides it in its own
// scope only; a declaration at file scope (or a macro anywhere) is the file's own.
TEST(CompatNeeds, LocalDeclarationsDoNotTurnTheBuiltInOff) {
    const std::string g3d = "vec3 tint(vec3 p) { vec3 pi = p * 2.0; return pi; }\n"
                            "float bend(float pi) { return pi * 0.5; }\n"
                            "float sdf(vec3 p) { return length(tint(p)) - 0.1 * pi; }\n";
    EXPECT_EQ(detectCompatNeeds(g3d).symbols, std::vector<std::string>{"pi"});
    EXPECT_FALSE(detectCompatNeeds("float pi = 3.0;\n" + g3d).any()) << "a global of that name is the file's";
    EXPECT_FALSE(detectCompatNeeds("float f() {\n#define pi 3.0\nreturn pi; }\n" + g3d).any()) << "macros have no scope";
    EXPECT_FALSE(
        detectCompatNeeds("struct S { float x; };\nfloat pi(float x) { return x; }\nfloat sdf(vec3 p) { return pi(p.x); }").any())
        << "a function of that name is the file's";

    const std::string shadertoy = "float wobble() { float iTime = 2.0; return sin(iTime); }\n"
                                  "vec2 flat2(vec3 iMouse) { return iMouse.xy; }\n"
                                  "float sdf(vec3 p) { return length(p) - 0.5 + 0.1 * sin(iTime) + 0.01 * iMouse.x; }\n";
    EXPECT_EQ(detectCompatNeeds(shadertoy).symbols, (std::vector<std::string>{"iTime", "iMouse"}));
    EXPECT_EQ(detectCompatNeeds("uniform vec4 iMouse;\n" + shadertoy).symbols, std::vector<std::string>{"iTime"});
    EXPECT_EQ(
        detectCompatNeeds("uniform vec3 iChannelResolution[4];\nfloat sdf(vec3 p) { return iChannelResolution[0].x; }").symbols,
        std::vector<std::string>{});
}

// Whole Shadertoy shaders: every input Shadertoy gives a single pass is provided when used and
// not declared; GLSL ES's texture2D too.
TEST(CompatNeeds, ShadertoyInputsAreFoundByUse) {
    const std::string text = "vec2 map(vec3 p) { return vec2(length(p) - 0.5, 1.0); }\n"
                             "void mainImage(out vec4 c, in vec2 f) {\n"
                             "  c = texture2D(iChannel2, f / iResolution.xy) + iMouse + iDate + float(iFrame) + iTimeDelta\n"
                             "    + iFrameRate + iSampleRate + iChannelTime[1] + iChannelResolution[3].x + iTime + fwidth(f.x);\n"
                             "}\n";
    auto needs = detectCompatNeeds(stripComments(text));
    for (const char* name : {"iResolution", "iTime", "iTimeDelta", "iFrame", "iFrameRate", "iMouse", "iDate", "iSampleRate",
                             "iChannel2", "iChannelTime", "iChannelResolution", "texture2D", "fwidth"})
        EXPECT_NE(std::find(needs.symbols.begin(), needs.symbols.end(), name), needs.symbols.end()) << name;
    EXPECT_EQ(std::find(needs.symbols.begin(), needs.symbols.end(), "iChannel0"), needs.symbols.end());
    EXPECT_TRUE(needs.usesTimeSymbol());
    EXPECT_TRUE(needs.usesShadertoyChannel());
}
