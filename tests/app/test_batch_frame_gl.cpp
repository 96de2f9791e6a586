// --normalize on a GLSL field as a user runs it: a scene built around its own camera (a ball at
// z = 5, outside [-1, 1]^3) framed by its surface's box or by a box given, on the real binary
// without a display (EGL). Every row is checked against the ball's exact distance through the frame
// the file records; bad boxes and fields without a surface are named and write nothing.

#include "common/ChildProcess.h"
#include "common/Scratch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Result = sdfwb::testing::RunResult;

Result run(const std::string& arguments) { return sdfwb::testing::runCommand(SDFWB_BINARY, arguments); }

fs::path scratch(const std::string& name) {
    const fs::path path = sdfwb::testing::scratchPath("batch-frame", name);
    fs::remove(path);
    return path;
}

fs::path writeShader(const std::string& name, const std::string& text) {
    const fs::path path = scratch(name);
    std::ofstream(path) << text;
    return path;
}

struct Framed {
    std::vector<float> rows; // x y z distance gx gy gz, from the .bin
    float centre[3] = {0.0f, 0.0f, 0.0f};
    float scale = 0.0f;
    std::string normalize;
};

// The .bin's rows and its sidecar's frame.
Framed readFramed(const fs::path& bin) {
    Framed framed;
    std::ifstream in(bin, std::ios::binary);
    std::uint32_t n = 0;
    in.read(reinterpret_cast<char*>(&n), 4);
    std::vector<float> columns(7 * std::size_t(n));
    in.read(reinterpret_cast<char*>(columns.data()), std::streamsize(columns.size() * 4));
    EXPECT_TRUE(in.good()) << bin;
    framed.rows.resize(columns.size());
    for (std::size_t i = 0; i < n; ++i) { // positions, distances, gradients as three arrays
        for (int a = 0; a < 3; ++a) framed.rows[7 * i + std::size_t(a)] = columns[3 * i + std::size_t(a)];
        framed.rows[7 * i + 3] = columns[3 * std::size_t(n) + i];
        for (int a = 0; a < 3; ++a)
            framed.rows[7 * i + 4 + std::size_t(a)] = columns[4 * std::size_t(n) + 3 * i + std::size_t(a)];
    }
    std::ifstream sidecarFile(bin.string() + ".json");
    std::stringstream sidecar;
    sidecar << sidecarFile.rdbuf();
    const std::string text = sidecar.str();
    static const std::regex frame(
        R"re("frame": \{"normalize": "([^"]*)", "centre": \[([-0-9.e+]+), ([-0-9.e+]+), ([-0-9.e+]+)\], "scale": ([-0-9.e+]+)\})re");
    std::smatch match;
    if (!std::regex_search(text, match, frame)) {
        ADD_FAILURE() << "no frame in " << bin << ".json: " << text;
        return framed;
    }
    framed.normalize = match[1].str();
    for (int a = 0; a < 3; ++a) framed.centre[a] = std::stof(match[2 + a].str());
    framed.scale = std::stof(match[5].str());
    return framed;
}

// Rows whose framed distance is not the ball's (centre (0, 0, 5), radius 1) at the field's point
// centre + scale * p, divided by scale; or that lie outside the unit box.
int wrongRows(const Framed& f) {
    int wrong = 0;
    for (std::size_t i = 0; i < f.rows.size() / 7; ++i) {
        const float* r = &f.rows[7 * i];
        const float x = f.centre[0] + f.scale * r[0], y = f.centre[1] + f.scale * r[1], z = f.centre[2] + f.scale * r[2];
        const float exact = (std::sqrt(x * x + y * y + (z - 5.0f) * (z - 5.0f)) - 1.0f) / f.scale;
        wrong += !(std::abs(r[3] - exact) < 1e-5f);
        wrong += !(std::abs(r[0]) <= 1.0f && std::abs(r[1]) <= 1.0f && std::abs(r[2]) <= 1.0f);
    }
    return wrong;
}

const char* kBall = "float sdf(vec3 p) { return length(p - vec3(0.0, 0.0, 5.0)) - 1.0; }\n";

} // namespace

TEST(BatchFrame, AFieldsSurfaceOutsideTheUnitBoxIsFramedByItsValues) {
    const fs::path ball = writeShader("ball.glsl", kBall);
    // As it is: no row of [-1, 1]^3 is inside the ball.
    const fs::path plain = scratch("plain.npz");
    Result r = run("--batch sample --sdf " + ball.string() + " --pattern rand -n 2000 -o " + plain.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;

    const fs::path cube = scratch("cube.bin");
    r = run("--batch sample --sdf " + ball.string() + " --normalize unit-cube --pattern rand -n 4000 -o " + cube.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("the surface lies in"), std::string::npos) << r.output;
    const Framed framed = readFramed(cube);
    EXPECT_EQ(framed.normalize, "unit-cube");
    // The lattice that found it (half side 8, cells of 16/39): the zeros between its points are
    // symmetric about the ball's centre, and the box is theirs grown by a cell.
    EXPECT_NEAR(framed.centre[0], 0.0f, 0.05f);
    EXPECT_NEAR(framed.centre[1], 0.0f, 0.05f);
    EXPECT_NEAR(framed.centre[2], 5.0f, 0.05f);
    EXPECT_GT(framed.scale, 1.0f) << "the ball fits: its radius is 1";
    EXPECT_LT(framed.scale, 1.0f + 16.0f / 39.0f + 0.05f);
    EXPECT_EQ(wrongRows(framed), 0);
    int inside = 0;
    for (std::size_t i = 0; i < framed.rows.size() / 7; ++i) inside += framed.rows[7 * i + 3] < 0.0f;
    EXPECT_GT(inside, 200) << "the framed box holds the ball (about a quarter of it by volume)";

    // A box given: centre (0, 0, 5), longest half side 2.
    const fs::path boxed = scratch("boxed.bin");
    r = run("--batch sample --sdf " + ball.string() + " --normalize=-2,-1,3,2,1,7 --pattern rand -n 2000 -o " + boxed.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Framed given = readFramed(boxed);
    EXPECT_EQ(given.centre[2], 5.0f);
    EXPECT_EQ(given.scale, 2.0f);
    EXPECT_EQ(wrongRows(given), 0);

    // The picture: framed, the ball fills the view; as it is, nothing is drawn.
    const fs::path picture = scratch("framed.png");
    r = run("--batch render --sdf " + ball.string() + " --normalize unit-sphere --size 64x48 -o " + picture.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(picture));
}

// A whole Shadertoy shader whose surface is outside the unit box: the run says so and names the
// option, and writes the field as it is. A dataset file, whose surface is in the box, is not searched.
TEST(BatchFrame, APastedSceneOutsideTheUnitBoxIsWarnedAbout) {
    const fs::path pasted = writeShader("pasted.glsl", std::string(kBall) + "void mainImage(out vec4 c, in vec2 u) {\n"
                                                                            "    float t = 0.0;\n"
                                                                            "    for (int i = 0; i < 64; i++) {\n"
                                                                            "        float d = sdf(vec3(0.0, 0.0, 1.0) * t);\n"
                                                                            "        if (d < 0.001) break;\n"
                                                                            "        t += d;\n"
                                                                            "    }\n"
                                                                            "    c = vec4(t);\n"
                                                                            "}\n");
    const fs::path out = scratch("pasted.npz");
    Result r = run("--batch sample --sdf " + pasted.string() + " --pattern rand -n 100 -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("the field has no surface in [-1, 1]^3; it lies in the box"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--normalize unit-cube frames it"), std::string::npos) << r.output;
    r = run("--batch sample --sdf sphere --pattern rand -n 100 -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("no surface in"), std::string::npos) << r.output;
}

TEST(BatchFrame, BadBoxesAndFieldsWithoutASurfaceAreNamedAndWriteNothing) {
    const fs::path ball = writeShader("ball2.glsl", kBall);
    const fs::path glow = writeShader("glow.glsl", "float sdf(vec3 p) { return 0.2 + 0.1 * sin(p.x); }\n");
    const fs::path out = scratch("bad.npz");
    struct Case {
        std::string arguments, culprit;
        int exitCode;
    } cases[] = {
        {"--sdf " + ball.string() + " --normalize 1,2,3", "--normalize", 2},
        {"--sdf " + ball.string() + " --normalize=1,0,0,-1,1,1", "--normalize", 2},
        {"--sdf " + ball.string() + " --normalize 0,0,0,1,1,nan", "--normalize", 2},
        {"--sdf " + glow.string() + " --normalize unit-cube", "no surface within [-64, 64]^3", 1},
    };
    for (const Case& c : cases) {
        Result r = run("--batch sample " + c.arguments + " --pattern rand -n 10 -o " + out.string());
        EXPECT_EQ(r.exitCode, c.exitCode) << c.arguments << "\n" << r.output;
        EXPECT_NE(r.output.find(c.culprit), std::string::npos) << c.arguments << "\n" << r.output;
        EXPECT_FALSE(fs::exists(out)) << c.arguments;
    }
}
