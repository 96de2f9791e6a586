// --normalize on a GLSL field as a user runs it: a scene built around its own camera (a ball at
// z = 5, outside [-1, 1]^3) framed by its surface's box or by a box given, on the real binary
// without a display (EGL). Every row is checked against the ball's exact distance through the frame
// the file records; bad boxes and fields without a surface are named and write nothing. --level
// gives an unsigned field (a pasted shader's distance to thin lines) the surface its march stops at.

#include "common/ChildProcess.h"
#include "common/Scratch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
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
    float level = 0.0f;
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
        R"re("frame": \{"normalize": "([^"]*)", "centre": \[([-0-9.e+]+), ([-0-9.e+]+), ([-0-9.e+]+)\], "scale": ([-0-9.e+]+), "level": ([-0-9.e+]+)\})re");
    std::smatch match;
    if (!std::regex_search(text, match, frame)) {
        ADD_FAILURE() << "no frame in " << bin << ".json: " << text;
        return framed;
    }
    framed.normalize = match[1].str();
    for (int a = 0; a < 3; ++a) framed.centre[a] = std::stof(match[2 + a].str());
    framed.scale = std::stof(match[5].str());
    framed.level = std::stof(match[6].str());
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

    // A scene the unit box cuts (a ball of radius 1.5 at the origin): named as cut, with its whole box.
    const fs::path big = writeShader("big.glsl", "float map(vec3 p) { return length(p) - 1.5; }\n"
                                                 "void mainImage(out vec4 c, in vec2 u) {\n"
                                                 "    float t = 0.0;\n"
                                                 "    for (int i = 0; i < 64; i++) { float d = map(vec3(0.0, 0.0, -4.0 + t)); "
                                                 "if (d < 0.001) break; t += d; }\n"
                                                 "    c = vec4(t);\n}\n");
    r = run("--batch sample --sdf " + big.string() + " --pattern rand -n 100 -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::size_t said = r.output.find("[-1, 1]^3 cuts the scene; it lies whole in the box ");
    ASSERT_NE(said, std::string::npos) << r.output;
    float box[6];
    ASSERT_EQ(
        std::sscanf(r.output.c_str() + said + 51, "%f,%f,%f,%f,%f,%f", &box[0], &box[1], &box[2], &box[3], &box[4], &box[5]), 6)
        << r.output.substr(said);
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(box[a], -1.5f, 0.15f) << r.output.substr(said);
        EXPECT_NEAR(box[a + 3], 1.5f, 0.15f) << r.output.substr(said);
    }
}

// The tutorials' first scene (a ball of radius 1 at (0, 1, 6) on the plane y = 0, the camera at
// (0, 1, 0)): [-1, 1]^3 holds only the floor. The run names the plane and the box of what stands on
// it, and --normalize unit-cube frames that box (the ball whole, down to the floor), not the floor.
TEST(BatchFrame, AFloorAloneInTheUnitBoxIsNamedAndWhatStandsOnItIsFramed) {
    const fs::path floor = writeShader("floor.glsl", "float GetDist(vec3 p) {\n"
                                                     "    vec4 s = vec4(0, 1, 6, 1);\n"
                                                     "    float sphereDist = length(p - s.xyz) - s.w;\n"
                                                     "    float planeDist = p.y;\n"
                                                     "    return min(sphereDist, planeDist);\n}\n"
                                                     "float RayMarch(vec3 ro, vec3 rd) {\n"
                                                     "    float dO = 0.;\n"
                                                     "    for (int i = 0; i < 100; i++) {\n"
                                                     "        vec3 p = ro + rd * dO;\n"
                                                     "        float dS = GetDist(p);\n"
                                                     "        dO += dS;\n"
                                                     "        if (dO > 100. || dS < .01) break;\n"
                                                     "    }\n    return dO;\n}\n"
                                                     "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                                                     "    vec2 uv = (fragCoord - .5 * iResolution.xy) / iResolution.y;\n"
                                                     "    float d = RayMarch(vec3(0, 1, 0), normalize(vec3(uv.x, uv.y, 1)));\n"
                                                     "    fragColor = vec4(vec3(d / 6.), 1.0);\n}\n");
    const fs::path out = scratch("floor.bin");
    Result r = run("--batch sample --sdf " + floor.string() + " --pattern rand -n 100 -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::size_t said =
        r.output.find("[-1, 1]^3 holds only the plane y = 0 of this scene; what stands on it lies in the box ");
    ASSERT_NE(said, std::string::npos) << r.output;
    r = run("--batch sample --sdf " + floor.string() + " --normalize unit-cube --pattern rand -n 4000 -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Framed framed = readFramed(out);
    // The ball spans y 0-2 and z 5-7 and meets the floor: the box's centre is near (0, 1, 6) and
    // its half side near 1, grown by the finding lattice's cell (16/39) and the floor's level.
    EXPECT_NEAR(framed.centre[0], 0.0f, 0.1f);
    EXPECT_NEAR(framed.centre[1], 1.0f, 0.5f);
    EXPECT_NEAR(framed.centre[2], 6.0f, 0.1f);
    EXPECT_GT(framed.scale, 1.0f);
    EXPECT_LT(framed.scale, 1.0f + 2.0f * 16.0f / 39.0f + 0.05f);
    int inside = 0;
    for (std::size_t i = 0; i < framed.rows.size() / 7; ++i) inside += framed.rows[7 * i + 3] < 0.0f;
    EXPECT_GT(inside, 400) << "the framed box holds the ball and the floor under it";
    // A plane alone is not a scene standing on it: no box is named.
    const fs::path plane = writeShader("plane.glsl", "float map(vec3 p) { return p.y + 0.5; }\n"
                                                     "void mainImage(out vec4 c, in vec2 u) {\n"
                                                     "    float t = 0.0;\n"
                                                     "    for (int i = 0; i < 64; i++) { float d = map(vec3(0.0, 1.0, 0.0) + "
                                                     "normalize(vec3(u, -1.0)) * t); if (d < 0.001) break; t += d; }\n"
                                                     "    c = vec4(t);\n}\n");
    r = run("--batch sample --sdf " + plane.string() + " --pattern rand -n 100 -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("holds only the plane"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("in the box"), std::string::npos) << r.output;
    // Nor a floor with blocks repeated without end (a city: 6 x 8 x 6 blocks every 11 units, none in
    // [-1, 1]^3), which every larger cube cuts.
    const fs::path blocks = writeShader(
        "city.glsl", "float map(vec3 p) {\n"
                     "    vec3 q = p;\n"
                     "    q.xz = mod(q.xz, 11.0) - 5.5;\n"
                     "    vec3 d = abs(q - vec3(0.0, 4.0, 0.0)) - vec3(3.0, 4.0, 3.0);\n"
                     "    return min(p.y, length(max(d, 0.0)) + min(max(d.x, max(d.y, d.z)), 0.0));\n}\n"
                     "void mainImage(out vec4 c, in vec2 u) {\n"
                     "    float t = 0.0;\n"
                     "    for (int i = 0; i < 64; i++) { float d = map(vec3(0.0, 1.0, 0.0) + normalize(vec3(u, -1.0)) * t); "
                     "if (d < 0.001) break; t += d; }\n"
                     "    c = vec4(t);\n}\n");
    r = run("--batch sample --sdf " + blocks.string() + " --pattern rand -n 100 -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("holds only the plane"), std::string::npos) << r.output;
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

namespace {

// A whole shader in the style of public ones that draw thin lines: the distance to two segments,
// floored (never negative: an unsigned field), marched until it drops below 0.001.
const char* kLines = R"glsl(
float sdSegment(vec3 p, vec3 a, vec3 b) {
    vec3 pa = p - a, ba = b - a;
    float h = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
    return length(pa - ba * h);
}
float map(vec3 p) {
    float d = sdSegment(p, vec3(-0.6, 0.0, 0.0), vec3(0.6, 0.0, 0.0));
    d = min(d, sdSegment(p, vec3(0.0, -0.6, 0.1), vec3(0.0, 0.6, 0.1)));
    return max(d, 0.0004);
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (fragCoord - 0.5 * iResolution.xy) / iResolution.y;
    vec3 ro = vec3(0.0, 0.0, -3.0), rd = normalize(vec3(uv, 1.5));
    float t = 0.0;
    for (int i = 0; i < 120; i++) {
        float d = map(ro + rd * t);
        if (d < 0.001 || t > 20.0) break;
        t += d;
    }
    fragColor = vec4(vec3(t < 20.0 ? 1.0 : 0.0), 1.0);
}
)glsl";

// The distance from a point to the two segments of kLines.
float linesDistance(const float* p) {
    auto segment = [&](const float a[3], const float b[3]) {
        float pa[3], ba[3], dot = 0.0f, len = 0.0f;
        for (int i = 0; i < 3; ++i) pa[i] = p[i] - a[i], ba[i] = b[i] - a[i], dot += pa[i] * ba[i], len += ba[i] * ba[i];
        const float h = std::clamp(dot / len, 0.0f, 1.0f);
        float d = 0.0f;
        for (int i = 0; i < 3; ++i) d += (pa[i] - ba[i] * h) * (pa[i] - ba[i] * h);
        return std::sqrt(d);
    };
    const float a0[3] = {-0.6f, 0.0f, 0.0f}, b0[3] = {0.6f, 0.0f, 0.0f};
    const float a1[3] = {0.0f, -0.6f, 0.1f}, b1[3] = {0.0f, 0.6f, 0.1f};
    return std::min(segment(a0, b0), segment(a1, b1));
}

} // namespace

// Without --level the field has no inside: the run says so and names the option; surface samples
// miss and there is nothing to mesh. With --level 0.02 the surface is the tubes of radius 0.02 the
// march shows: every surface row lies on them, the mesh is written, and the file records the level.
TEST(BatchFrame, AnUnsignedFieldGetsTheSurfaceItsMarchStopsAtWithLevel) {
    const fs::path lines = writeShader("lines.glsl", kLines);
    const fs::path plain = scratch("lines-plain.npz");
    Result r = run("--batch sample --sdf " + lines.string() + " --pattern surface -n 500 -o " + plain.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("never negative"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("below 0.001 (line 18): --level 0.001"), std::string::npos) << "its march's hit test: " << r.output;
    EXPECT_NE(r.output.find("500 bad rows"), std::string::npos) << "no surface sample can be found: " << r.output;
    const fs::path mesh = scratch("lines.ply");
    r = run("--batch mesh --sdf " + lines.string() + " --resolution 64 -o " + mesh.string());
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("never negative"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(mesh));

    const fs::path levelled = scratch("lines-level.bin");
    r = run("--batch sample --sdf " + lines.string() + " --level 0.02 --pattern surface -n 2000 -o " + levelled.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("never negative"), std::string::npos) << "the levelled field has a surface: " << r.output;
    const Framed framed = readFramed(levelled);
    EXPECT_EQ(framed.level, 0.02f);
    EXPECT_EQ(framed.scale, 1.0f);
    ASSERT_EQ(framed.rows.size(), 7u * 2000u);
    // Rays that miss the thin tubes are NaN rows (the surface sampler's misses); the others lie on them.
    int found = 0, off = 0, wrong = 0;
    for (std::size_t i = 0; i < 2000; ++i) {
        const float* row = &framed.rows[7 * i];
        if (!std::isfinite(row[0])) continue;
        ++found;
        off += !(std::abs(linesDistance(row) - 0.02f) < 2e-4f);
        wrong += !(std::abs(row[3] - (linesDistance(row) - 0.02f)) < 1e-5f);
    }
    EXPECT_GT(found, 1600) << "most rays reach the tubes";
    EXPECT_EQ(off, 0) << "surface rows lie on the tubes of radius 0.02";
    EXPECT_EQ(wrong, 0) << "the written value is f - level";

    r = run("--batch mesh --sdf " + lines.string() + " --level 0.02 --resolution 96 -o " + mesh.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_GT(fs::file_size(mesh), 10000u);

    // A level and a frame together: the search finds the tubes (of radius 0.05: thicker than the
    // search lattice's cell), not the floored lines.
    const fs::path both = scratch("lines-both.bin");
    r = run("--batch sample --sdf " + lines.string() + " --level 0.05 --normalize unit-cube --pattern rand -n 200 -o " +
            both.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Framed framedBoth = readFramed(both);
    EXPECT_EQ(framedBoth.level, 0.05f);
    EXPECT_NEAR(framedBoth.scale, 0.65f, 0.06f) << "half the tubes' longest side, 0.6 + 0.05, grown by a lattice cell";
    for (std::size_t i = 0; i < 200; ++i) {
        const float* row = &framedBoth.rows[7 * i];
        float p[3];
        for (int a = 0; a < 3; ++a) p[a] = framedBoth.centre[a] + framedBoth.scale * row[a];
        EXPECT_NEAR(row[3], (linesDistance(p) - 0.05f) / framedBoth.scale, 1e-5f) << i;
    }
}

// A pasted shader whose `map` is a stub returning 0 (its picture is a glow mainImage draws
// itself): a constant, named as one, not an unsigned distance with a level to take.
TEST(BatchFrame, AConstantFieldIsNamedAsOne) {
    const fs::path stub = writeShader("stub.glsl", "float map(vec3 p) { return 0.0; }\n"
                                                   "void mainImage(out vec4 O, in vec2 I) {\n"
                                                   "    vec2 uv = I / iResolution.xy - 0.5; float g = 0.0;\n"
                                                   "    for (float i = 0.0; i < 10.0; i++) g += 0.01 / length(uv + 0.01 * i);\n"
                                                   "    O = vec4(g);\n}\n");
    const fs::path out = scratch("stub.npz");
    Result r = run("--batch sample --sdf " + stub.string() + " --pattern rand -n 100 -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("the field is 0 everywhere within [-64, 64]^3: a constant, with no surface (is map the"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("--level"), std::string::npos) << r.output;
}

TEST(BatchFrame, ALevelThatIsNotANumberOrIsGivenForAMeshIsNamed) {
    const fs::path lines = writeShader("lines2.glsl", kLines);
    const fs::path out = scratch("level-bad.npz");
    const fs::path meshFile =
        writeShader("tetra.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    for (const std::string& arguments : {"--sdf " + lines.string() + " --level nan", "--sdf " + lines.string() + " --level x",
                                         "--sdf " + meshFile.string() + " --level 0.1"}) {
        Result r = run("--batch sample " + arguments + " --pattern rand -n 10 -o " + out.string());
        EXPECT_EQ(r.exitCode, 2) << arguments << "\n" << r.output;
        EXPECT_NE(r.output.find("--level"), std::string::npos) << arguments << "\n" << r.output;
        EXPECT_FALSE(fs::exists(out)) << arguments;
    }
}
