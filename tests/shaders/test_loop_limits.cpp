// Loops a driver would cut short (shaders/LoopLimits.h): constant-count `for` loops found in
// glslang's syntax tree of the composed shader and reported at the user's file and line.

#include <shaders/LoopLimits.h>
#include <shaders/SdfSource.h>
#include <shaders/TracerComposer.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace sdfwb::shaders;
namespace fs = std::filesystem;

namespace {

std::vector<Diagnostic> longLoops(const PreparedSdf& sdf, std::uint64_t limit = kLlvmpipeLoopLimit) {
    EXPECT_TRUE(sdf.ok());
    auto composed = composeTracer(sdf, TracerFeatures{});
    EXPECT_TRUE(composed.hasValue());
    return composed ? findLongLoops(sdf, *composed, limit, "Mesa's llvmpipe") : std::vector<Diagnostic>{};
}

std::vector<Diagnostic> longLoops(const std::string& text) { return longLoops(prepareSdf(text, "<test>", {}, IncludeOptions{})); }

// An SDF whose loop has the given header, on line 3.
std::string withLoop(const std::string& header) {
    return "// a field summed in a loop\n"
           "float sdf(vec3 p) { float s = 0.0;\n"
           "  " +
           header +
           " { s += 1e-6; }\n"
           "  return length(p) - 0.5 - s * 1e-6; }\n";
}

} // namespace

// The example: 0.5 / 200000 added 200000 times is -0.164 at the origin on llvmpipe, not -0.5.
TEST(LoopLimits, AFieldSummedOver200000StepsIsFlaggedAtItsLine) {
    const auto found = longLoops("float sdf(vec3 p) {\n"
                                 "    float s = 0.0;\n"
                                 "    for (int i = 0; i < 200000; ++i) s += 0.5 / 200000.0;\n"
                                 "    return length(p) - s;\n"
                                 "}\n");
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].file, "<test>");
    EXPECT_EQ(found[0].line, 3);
    EXPECT_EQ(found[0].severity, Severity::Warning);
    EXPECT_NE(found[0].message.find("200000 times"), std::string::npos) << found[0].message;
    EXPECT_NE(found[0].message.find("65535"), std::string::npos) << found[0].message;
    EXPECT_NE(found[0].message.find("llvmpipe"), std::string::npos) << found[0].message;
}

TEST(LoopLimits, TripCountsAreCountedAsTheLoopRunsThem) {
    struct Case {
        const char* header;
        std::size_t warnings;
    } cases[] = {
        {"for (int i = 0; i < 65535; ++i)", 0},  // exactly the limit
        {"for (int i = 0; i <= 65535; i++)", 1}, // one more
        {"for (int i = 0; i < 65536; i++)", 1},
        {"for (int i = 70000; i > 0; --i)", 1},      // counting down
        {"for (int i = 70000; i >= 70000; i--)", 0}, // runs once
        {"for (int i = 0; i < 140000; i += 2)", 1},  // 70000
        {"for (int i = 0; i < 140000; i += 4)", 0},  // 35000
        {"for (int i = -40000; i < 40000; ++i)", 1}, // 80000
        {"for (float x = 0.0; x < 100000.0; x += 1.0)", 1},
        {"for (float x = 0.0; x < 1e5; x += 2.0)", 0}, // 50000
        {"for (float x = 0.0; x < 1e5; x += 0.5)", 1}, // 200000, the limit written with an exponent
        {"for (uint i = 0u; i < 100000u; ++i)", 1},
        {"for (int i = 0; i > 100000; ++i)", 0},    // never runs
        {"for (int i = 0; i < 100000; i *= 2)", 0}, // not a constant step: not judged
    };
    for (const Case& c : cases) {
        const auto found = longLoops(withLoop(c.header));
        EXPECT_EQ(found.size(), c.warnings) << c.header;
        if (!found.empty()) { EXPECT_EQ(found[0].line, 3) << c.header; }
    }
}

TEST(LoopLimits, ALoopInAnIncludedFileIsReportedThere) {
    const fs::path folder = fs::temp_directory_path() / ("sdfwb-loop-limits-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    std::ofstream(folder / "sum.glsl") << "// helpers\n"
                                          "float longSum() {\n"
                                          "    float s = 0.0;\n"
                                          "    for (int i = 0; i < 300000; ++i) s += 1e-7;\n"
                                          "    return s;\n"
                                          "}\n";
    const std::string text = "#include \"sum.glsl\"\nfloat sdf(vec3 p) { return length(p) - 0.5 + longSum(); }\n";
    const fs::path main = folder / "main.glsl";
    std::ofstream(main) << text;
    const auto found = longLoops(prepareSdf(text, main.string(), main, IncludeOptions{}));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(fs::path(found[0].file).filename(), "sum.glsl") << found[0].file;
    EXPECT_EQ(found[0].line, 4);
    fs::remove_all(folder);
}

TEST(LoopLimits, OnlyALargeNumberMakesTheShaderWorthParsing) {
    auto large = [](const std::string& number) {
        return hasLargeNumber(
            prepareSdf("float sdf(vec3 p) { return length(p) - " + number + "; }\n", "<test>", {}, IncludeOptions{}));
    };
    // A rotation matrix's long fractions and small exponents are not loop bounds (they made every
    // tilted shape pay a glslang parse on each build).
    EXPECT_FALSE(large("0.7071067811865476"));
    EXPECT_FALSE(large("9.745318556e-01"));
    EXPECT_FALSE(large("1e-7"));
    EXPECT_FALSE(large("1.5e4"));
    EXPECT_FALSE(large("32767.0"));
    EXPECT_TRUE(large("32768.0"));
    EXPECT_TRUE(large("100000"));
    EXPECT_TRUE(large("1e5"));
    EXPECT_TRUE(large("2.5E+6"));
    EXPECT_TRUE(large("0.25 * 1000000.0"));
}

TEST(LoopLimits, NothingWithoutALimitOrALargeNumber) {
    EXPECT_TRUE(longLoops(prepareSdf(withLoop("for (int i = 0; i < 200000; ++i)"), "<test>", {}, IncludeOptions{}), 0).empty())
        << "a driver without a limit";
    EXPECT_TRUE(longLoops(withLoop("for (int i = 0; i < 64; ++i)")).empty());
    // A nested pair of loops, each under the limit, is what the warning advises.
    EXPECT_TRUE(longLoops("float sdf(vec3 p) { float s = 0.0;\n"
                          "  for (int i = 0; i < 400; ++i) for (int j = 0; j < 500; ++j) s += 1e-6;\n"
                          "  return length(p) - 0.5 - s * 1e-6 + 0.0 * 200000.0; }\n")
                    .empty());
    EXPECT_EQ(loopLimitOf("llvmpipe (LLVM 15.0.6, 256 bits)"), kLlvmpipeLoopLimit);
    EXPECT_EQ(loopLimitOf("NVIDIA H100 80GB HBM3/PCIe/SSE2"), 0u);
}
