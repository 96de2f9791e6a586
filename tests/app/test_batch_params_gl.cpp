// Parameters from the command line, on SDF files written the way public code is (Shadertoy's
// map() with iTime, hg_sdf's pModPolar, IQ's primitives): --param values reach the GPU exactly as
// an edited initializer would, families write one file per instance that equals a plain run,
// the audit across a family finds where the field stops being conservative, and mistakes are named.
#include "common/ChildProcess.h"
#include "common/Scratch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;
using sdfwb::testing::readBytes;
using sdfwb::testing::RunResult;

namespace {

RunResult run(const std::string& arguments) { return sdfwb::testing::runCommand(SDFWB_BINARY, arguments); }

std::string params(const std::string& name) { return std::string(SDFWB_SOURCE_DIR) + "/tests/params/" + name; }

fs::path scratch(const std::string& name) { return sdfwb::testing::scratchPath("batch-params", name); }

// `text` with the first `from` replaced by `to` (which must be there).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

// Decodes one frame of an image or video file to RGB bytes with the ffmpeg tool.
std::vector<unsigned char> rgbFrame(const fs::path& file, int frame, int width, int height) {
    const fs::path raw = scratch(file.stem().string() + "-" + std::to_string(frame) + ".rgb");
    const std::string command = "ffmpeg -v error -y -i " + file.string() + " -vf \"select=eq(n\\," + std::to_string(frame) +
                                ")\" -frames:v 1 -f rawvideo -pix_fmt rgb24 " + raw.string();
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    const std::string bytes = readBytes(raw);
    EXPECT_EQ(bytes.size(), std::size_t(width) * height * 3) << file;
    return {bytes.begin(), bytes.end()};
}

double meanDifference(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
    if (a.size() != b.size() || a.empty()) return 1e9;
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += std::abs(int(a[i]) - int(b[i]));
    return sum / double(a.size());
}

} // namespace

TEST(BatchParams, AParamDrawsWhatEditingTheInitializerDraws) {
    const std::string file = params("iq_torus_map.glsl");
    const fs::path edited = scratch("torus_edited.glsl");
    std::ofstream(edited) << replaced(
        replaced(replaced(readBytes(file), "majorRadius = 0.6;", "majorRadius = 0.35;"), "capped = false;", "capped = true;"),
        "vec3 offset = vec3(0.0);", "vec3 offset = vec3(0.0, 0.15, 0.0);");
    const std::string common = " --size 96x64 --shading normals --quiet --output ";
    RunResult byParam =
        run("--batch render --sdf " + file + " --param majorRadius=0.35 --param capped=true --param offset=0,0.15,0" + common +
            scratch("param.png").string());
    ASSERT_EQ(byParam.exitCode, 0) << byParam.output;
    RunResult byText = run("--batch render --sdf " + edited.string() + common + scratch("edited.png").string());
    ASSERT_EQ(byText.exitCode, 0) << byText.output;
    RunResult byDefault = run("--batch render --sdf " + file + common + scratch("default.png").string());
    ASSERT_EQ(byDefault.exitCode, 0) << byDefault.output;
    const auto param = rgbFrame(scratch("param.png"), 0, 96, 64);
    EXPECT_EQ(param, rgbFrame(scratch("edited.png"), 0, 96, 64)) << "a --param must draw what the edited default draws";
    EXPECT_GT(meanDifference(param, rgbFrame(scratch("default.png"), 0, 96, 64)), 5.0) << "and differ from the default";
}

TEST(BatchParams, EachFamilyInstanceEqualsAPlainRunWithItsValues) {
    const std::string file = params("hg_polar_columns.glsl");
    const fs::path out = scratch("columns.npz");
    RunResult family =
        run("--batch sample --sdf " + file + " --pattern near -n 3000 --seed 5 --sweep columns=3:12:4 --output " + out.string());
    ASSERT_EQ(family.exitCode, 0) << family.output;
    const fs::path index = scratch("columns_index.json");
    ASSERT_TRUE(fs::exists(index)) << family.output;
    const std::string indexText = readBytes(index);
    for (const char* name : {"columns_00000.npz", "columns_00001.npz", "columns_00002.npz", "columns_00003.npz"}) {
        EXPECT_TRUE(fs::exists(out.parent_path() / name)) << name;
        EXPECT_NE(indexText.find(name), std::string::npos) << indexText;
    }
    EXPECT_FALSE(fs::exists(out.parent_path() / "columns_00004.npz"));
    EXPECT_NE(indexText.find("\"columns\": 9"), std::string::npos) << indexText;
    // Instance 2 (columns = 9) is the file a single run with --param columns=9 writes, byte for byte.
    const fs::path single = scratch("nine.npz");
    RunResult plain =
        run("--batch sample --sdf " + file + " --pattern near -n 3000 --seed 5 --param columns=9 --output " + single.string());
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    const std::string nine = readBytes(single);
    EXPECT_EQ(nine, readBytes(out.parent_path() / "columns_00002.npz"));
    EXPECT_NE(nine, readBytes(out.parent_path() / "columns_00001.npz")) << "another count, another shape";
    std::string utf32; // npz strings are NumPy '<U' arrays: UTF-32, little-endian
    for (char c : std::string("{\"columns\":9,\"ringRadius\":0.55,\"columnRadius\":0.1}"))
        utf32 += std::string(1, c) + std::string(3, '\0');
    EXPECT_NE(nine.find(utf32), std::string::npos) << "the values in the npz metadata";
    // PLY carries the values in a comment, .bin in a JSON sidecar beside it.
    const fs::path ply = scratch("columns.ply");
    ASSERT_EQ(
        run("--batch sample --sdf " + file + " --pattern rand -n 100 --param ringRadius=0.4 --output " + ply.string()).exitCode,
        0);
    EXPECT_NE(readBytes(ply).find("comment sdfwb parameters {\"columns\":6,\"ringRadius\":0.4,\"columnRadius\":0.1}\n"),
              std::string::npos);
    const fs::path bin = scratch("columns.bin");
    RunResult randomized =
        run("--batch sample --sdf " + file + " --pattern rand -n 100 --randomize 3 --seed 11 --output " + bin.string());
    ASSERT_EQ(randomized.exitCode, 0) << randomized.output;
    for (const char* name : {"columns_00000.bin", "columns_00001.bin", "columns_00002.bin"}) {
        EXPECT_EQ(fs::file_size(out.parent_path() / name), 4u + 28u * 100u) << "the paper's layout, unchanged";
        const std::string sidecar = readBytes(out.parent_path() / (std::string(name) + ".json"));
        EXPECT_NE(sidecar.find("\"parameters\": {\"columns\":"), std::string::npos) << sidecar;
    }
}

TEST(BatchParams, TheAuditAcrossAFamilyFindsWhereTheFieldStopsBeingConservative) {
    // Stretching y by s multiplies |grad f| by s there: conservative up to 1, not beyond.
    RunResult r =
        run("--batch audit --sdf " + params("st_blend_itime.glsl") + " --sweep stretch=0.5:2:4 --samples 4000 --json --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string json = r.output.substr(r.output.find('{'));
    std::vector<std::string> verdicts;
    std::vector<float> lipschitz;
    for (std::size_t at = json.find("\"verdict\": \""); at != std::string::npos; at = json.find("\"verdict\": \"", at + 1)) {
        const std::size_t begin = at + 12;
        verdicts.push_back(json.substr(begin, json.find('"', begin) - begin));
        const std::size_t l = json.find("\"lipschitz\": ", at);
        lipschitz.push_back(std::stof(json.substr(l + 13)));
    }
    ASSERT_EQ(verdicts.size(), 4u) << json;
    EXPECT_TRUE(verdicts[0] == "conservative" || verdicts[0] == "exact") << verdicts[0];
    EXPECT_TRUE(verdicts[1] == "conservative" || verdicts[1] == "exact") << verdicts[1];
    EXPECT_EQ(verdicts[2], "non-conservative");
    EXPECT_EQ(verdicts[3], "non-conservative");
    EXPECT_NEAR(lipschitz[2], 1.5f, 0.08f);
    EXPECT_NEAR(lipschitz[3], 2.0f, 0.1f);
    // The text report draws it: one bar per instance, '|' at L = 1.
    RunResult text = run("--batch audit --sdf " + params("st_blend_itime.glsl") + " --sweep stretch=0.5:2:4 --samples 4000");
    ASSERT_EQ(text.exitCode, 0) << text.output;
    EXPECT_NE(text.output.find("4 instances"), std::string::npos) << text.output;
    EXPECT_NE(text.output.find("blend=0.1 stretch=2 "), std::string::npos) << text.output;
    EXPECT_NE(text.output.find(" ################|############### "), std::string::npos) << text.output; // L = 2 of 2
}

TEST(BatchParams, KeyframedParametersMoveTheClipFromStartToEnd) {
    const std::string file = params("iq_torus_map.glsl");
    const fs::path clip = scratch("grow.mp4");
    RunResult r = run("--batch animate --sdf " + file + " --param minorRadius=0.05 --param-end minorRadius=0.3 --size 96x64" +
                      " --seconds 1 --fps 5 --quiet --output " + clip.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("every frame is the same"), std::string::npos) << r.output;
    ASSERT_EQ(run("--batch render --sdf " + file + " --param minorRadius=0.05 --size 96x64 --quiet --output " +
                  scratch("thin.png").string())
                  .exitCode,
              0);
    ASSERT_EQ(run("--batch render --sdf " + file + " --param minorRadius=0.3 --size 96x64 --quiet --output " +
                  scratch("thick.png").string())
                  .exitCode,
              0);
    const auto thin = rgbFrame(scratch("thin.png"), 0, 96, 64), thick = rgbFrame(scratch("thick.png"), 0, 96, 64);
    const auto first = rgbFrame(clip, 0, 96, 64), last = rgbFrame(clip, 4, 96, 64);
    // H.264 is lossy: each end is near its own render and far from the other's.
    EXPECT_LT(meanDifference(first, thin), 4.0);
    EXPECT_LT(meanDifference(last, thick), 4.0);
    EXPECT_GT(meanDifference(first, thick), 3.0 * meanDifference(first, thin));
    EXPECT_GT(meanDifference(last, thin), 3.0 * meanDifference(last, thick));
}

TEST(BatchParams, MistakesAreNamedAndNothingIsWritten) {
    const std::string file = params("iq_torus_map.glsl");
    const fs::path out = scratch("bad.npz");
    struct Case {
        std::string arguments;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {"--batch sample --sdf " + file + " -p rand -n 10 --param radius=0.3 -o " + out.string(),
         "parameter 'radius' is not declared (declared: majorRadius, minorRadius, offset, capped)"},
        {"--batch render --sdf " + file + " --param offset=1,2 --output " + scratch("bad.png").string(),
         "parameter 'offset' is a vec3: give 1 or 3 numbers, not 2"},
        {"--batch audit --sdf " + file + " --param majorRadius=big", "'majorRadius=big': the value must be"},
        {"--batch sample --sdf " + file + " -p rand -n 10 --sweep majorRadius=0.2:0.8 -o " + out.string(),
         "expected NAME=FROM:TO:COUNT"},
        {"--batch sample --sdf " + file + " -p rand -n 10 --sweep minorRadius=0.1:0.2:3 --shard 0/2 -o " + out.string(),
         "--shard cannot be combined with --sweep or --randomize"},
        {"--batch audit --sdf " + file + " --sweep minorRadius=0.1:0.2:3 --plane 0,0,1,0",
         "--plane cannot be combined with --sweep or --randomize"},
        {"--batch sample --sdf " + file + " -p rand -n 10 --sweep thickness=0.1:0.2:3 -o " + out.string(),
         "parameter 'thickness' is not declared"},
        {"--batch sample --sdf " + file + " -p rand -n 10 --param minorRadius=0.1 --param minorRadius=0.2 -o " + out.string(),
         "'minorRadius' is given twice"},
    };
    for (const Case& c : cases) {
        RunResult r = run(c.arguments);
        EXPECT_EQ(r.exitCode, 2) << c.arguments << "\n" << r.output;
        EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.arguments << "\n" << r.output;
    }
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(scratch("bad_00000.npz")));
    // Outside the declared range: drawn, with a warning naming the range.
    RunResult outside = run("--batch render --sdf " + file + " --param majorRadius=0.95 --size 32x32 --output " +
                            scratch("outside.png").string());
    EXPECT_EQ(outside.exitCode, 0) << outside.output;
    EXPECT_NE(outside.output.find("parameter 'majorRadius' = 0.95 lies outside its @range 0.2 0.8"), std::string::npos)
        << outside.output;
}
