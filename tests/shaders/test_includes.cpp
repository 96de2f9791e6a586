// The include resolver: search order, roots, #pragma once, comments, line mapping.

#include <shaders/IncludeResolver.h>
#include <shaders/SdfSource.h>

#include <gtest/gtest.h>

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
