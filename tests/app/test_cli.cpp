// The command line as a user meets it: bad input gives one clear line, a non-zero exit and no file.
// These runs fail before any GL work, so they need no GL context.

#include <values/JobKinds.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <string_view>
#include <sys/wait.h>

namespace fs = std::filesystem;

namespace {

struct Result {
    int exitCode = -1;
    std::string output; // stdout and stderr
};

Result run(const std::string& arguments) {
    std::string command =
        "env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM " + std::string(SDFWB_BINARY) + " " + arguments + " 2>&1";
    Result result;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer;
    while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) result.output.append(buffer.data(), n);
    int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

std::string corpus(const std::string& name) {
    return (fs::path(SDFWB_SOURCE_DIR) / "tests" / "shaders" / "files" / name).string();
}

fs::path outputPath(const std::string& name) {
    fs::path path = fs::temp_directory_path() / ("sdfwb-cli-" + name);
    fs::remove(path);
    return path;
}

int lineCount(const std::string& text) {
    int lines = 0;
    for (char c : text) lines += c == '\n';
    return lines;
}

} // namespace

TEST(CommandLine, MissingSdfFileNamesIt) {
    fs::path out = outputPath("missing.png");
    Result r = run("--batch render --sdf /nonexistent/shape.glsl --output " + out.string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("/nonexistent/shape.glsl"), std::string::npos) << r.output;
    EXPECT_EQ(lineCount(r.output), 1) << r.output;
    EXPECT_FALSE(fs::exists(out));
}

TEST(CommandLine, FileWithoutSdfNamesFileAndLine) {
    fs::path out = outputPath("nosdf.png");
    Result r = run("--batch render --sdf " + corpus("no_sdf.glsl") + " --output " + out.string());
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find(corpus("no_sdf.glsl") + ":1:1: error:"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
}

TEST(CommandLine, UnknownOptionIsNamed) {
    fs::path out = outputPath("unknown.png");
    Result r = run("--batch render --sdf sphere --output " + out.string() + " --frobnicate 3");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--frobnicate"), std::string::npos) << r.output;
    EXPECT_EQ(lineCount(r.output), 1) << r.output;
    EXPECT_FALSE(fs::exists(out));
}

TEST(CommandLine, MalformedSizeIsNamed) {
    fs::path out = outputPath("size.png");
    for (const char* size : {"640by360", "0x10", "640x", "99999x2", "-3x4"}) {
        Result r = run(std::string("--batch render --sdf sphere --output ") + out.string() + " --size " + size);
        EXPECT_EQ(r.exitCode, 2) << size << ": " << r.output;
        EXPECT_NE(r.output.find("--size"), std::string::npos) << r.output;
        EXPECT_EQ(lineCount(r.output), 1) << r.output;
    }
    EXPECT_FALSE(fs::exists(out));
}

TEST(CommandLine, NonFiniteAndOutOfRangeNumbersAreRefusedWhileParsing) {
    fs::path out = outputPath("numbers.png");
    struct Case {
        std::string arguments, culprit;
    } cases[] = {
        {"render --sdf sphere --time nan --output " + out.string(), "--time"},
        {"render --sdf sphere --time inf --output " + out.string(), "--time"},
        {"render --sdf sphere --cones sometimes --output " + out.string(), "--cones"},
        {"render --sdf sphere --cone-tile 0 --output " + out.string(), "--cone-tile"},
        {"animate --sdf sphere --fps 0 --output " + outputPath("numbers.mp4").string(), "--fps"},
        {"animate --sdf sphere --seconds 0 --output " + outputPath("numbers.mp4").string(), "--seconds"},
        {"audit --sdf sphere --samples 1", "--samples"},
        {"sample --sdf sphere -p rand -n 10 --gradient-step 0 -o " + outputPath("n.bin").string(), "--gradient-step"},
        {"sample --sdf sphere -p surface -n 10 --surface-tolerance -1 -o " + outputPath("n.bin").string(), "--surface-tolerance"},
        {"sample --sdf sphere -p rand -n 10 --time nan -o " + outputPath("n.bin").string(), "--time"}};
    for (const Case& c : cases) {
        Result r = run("--batch " + c.arguments);
        EXPECT_EQ(r.exitCode, 2) << c.arguments << ": " << r.output;
        EXPECT_NE(r.output.find(c.culprit), std::string::npos) << r.output;
        EXPECT_EQ(lineCount(r.output), 1) << r.output;
    }
    EXPECT_FALSE(fs::exists(out));
}

// The job kinds' table (values/JobKinds.h) and the CLI's commands agree: every kind, and every
// former name of one, is a batch command whose help shows the kind's name.
TEST(CommandLine, EveryJobKindIsABatchCommand) {
    for (const sdfwb::values::JobKind& kind : sdfwb::values::kJobKinds)
        for (const std::string_view name : {kind.name, kind.formerName}) {
            if (name.empty()) continue;
            Result r = run("--batch " + std::string(name) + " --help");
            EXPECT_EQ(r.exitCode, 0) << name << ": " << r.output;
            EXPECT_NE(r.output.find("--batch " + std::string(kind.name)), std::string::npos) << r.output; // its usage line
        }
}

// The keys an object of a request accepts, as the request's JSON error lists them ("'zzz':
// unknown key (known here: a, b)"), with the key paths of the objects nested in it ("trace.max_steps").
std::set<std::string> requestKeys(const std::string& kind, const std::string& path = {}) {
    std::string json = "{\"zzz_unknown\": 1}";
    for (std::string rest = path; !rest.empty();) {
        const std::size_t dot = rest.rfind('.');
        json = "{\"" + rest.substr(dot == std::string::npos ? 0 : dot + 1) + "\": " + json + "}";
        rest = dot == std::string::npos ? "" : rest.substr(0, dot);
    }
    json.insert(1, "\"kind\": \"" + kind + "\", ");
    const fs::path file = outputPath("keys-" + kind + ".json");
    std::ofstream(file) << json;
    const Result r = run("--batch request " + file.string());
    fs::remove(file);
    static const std::regex listed(R"(unknown key \(known here: ([a-z0-9_, ]*)\))");
    std::smatch match;
    std::set<std::string> keys;
    if (!std::regex_search(r.output, match, listed)) return keys; // not an object
    std::string names = match[1].str() + ", ";
    for (std::size_t at = 0, comma; (comma = names.find(", ", at)) != std::string::npos; at = comma + 2) {
        const std::string key = path.empty() ? names.substr(at, comma - at) : path + "." + names.substr(at, comma - at);
        keys.insert(key);
        if (path.empty() && key != "kind")
            for (const std::string& nested : requestKeys(kind, key)) keys.insert(nested);
    }
    return keys;
}

// An option whose name is not its key's says in its help which request keys it sets ("--size ...
// (JSON: width, height)"), and a failure about those keys names it. Each such key is one the
// command's request accepts: a key renamed in the JSON, or a wrong path, fails here.
TEST(CommandLine, OptionsNamedApartFromTheirKeysNameRealKeys) {
    static const std::regex setsKeys(R"(\(JSON: ([a-z0-9_., ]+)\))");
    std::set<std::string> named;
    for (const sdfwb::values::JobKind& kind : sdfwb::values::kJobKinds) {
        const Result help = run("--batch " + std::string(kind.name) + " --help");
        const std::set<std::string> keys = requestKeys(std::string(kind.name));
        for (std::sregex_iterator it(help.output.begin(), help.output.end(), setsKeys), end; it != end; ++it) {
            const std::string list = (*it)[1].str() + ", ";
            for (std::size_t at = 0, comma; (comma = list.find(", ", at)) != std::string::npos; at = comma + 2) {
                const std::string path = list.substr(at, comma - at);
                EXPECT_TRUE(keys.count(path)) << kind.name << ": " << path << " is no key of its request";
                named.insert(path);
            }
        }
    }
    ASSERT_TRUE(requestKeys("render").count("trace.over_relaxation")) << "nested keys were not read";
    for (const char* path : {"width", "height", "n", "items", "x", "y", "shard_index", "near_truncation", "params", "params_end",
                             "channels", "trace.over_relaxation", "camera.position", "bounds_min"})
        EXPECT_TRUE(named.count(path)) << path << ": no option's help says it sets it";
}

// A failure that names request keys names them as each front end writes them: on the command line
// the options that set them (--size for 'width', 'height'; -n; --item for 'items'), in a JSON
// request its own keys. One message, worded twice: no table of message texts (core/KeyedText.h).
TEST(CommandLine, FailuresNameTheOptionsThatSetTheirKeys) {
    const fs::path manifest = outputPath("keys-manifest.csv"), samples = outputPath("keys.npz");
    std::ofstream(manifest) << "sdf,pattern,n,output\nsphere,rand,100,a.npz\n";
    const std::string sample = "--batch sample --sdf sphere -n 10 -o " + samples.string();
    const std::pair<std::string, std::string> cases[] = {
        {sample + " -p near --near-truncate 2", "--near-truncate: needs --near-widths"},
        {sample + " -p rand --shard 1/2 --randomize 2", "--shard cannot be combined with --sweep or --randomize"},
        {sample + " -p rand --near-widths 0.1", "--near-widths: only the near pattern takes widths (the pattern is 'rand')"},
        {"--batch probe --sdf sphere --size 64x48 --pixel 70,5", "--pixel: 70,5 lies outside the 64x48 frame"},
        {"--batch render --sdf sphere --output " + outputPath("keys.png").string() + " --camera nan,0,3",
         "--camera/--target/--plane: expected finite numbers"},
        {"--batch run " + manifest.string() + " --rank 3 --world-size 2", "--rank: must be below --world-size (2), got 3"},
        {"--batch run " + manifest.string() + " --item 7", "--item: 7 is past the manifest's last item (0)"},
    };
    for (const auto& [arguments, expected] : cases) {
        const Result r = run(arguments);
        EXPECT_EQ(r.exitCode, 2) << arguments << "\n" << r.output;
        EXPECT_EQ(r.output, "sdfwb: " + expected + "\n") << arguments;
    }
    // The same failures from a JSON request keep its keys, options nowhere.
    const std::pair<std::string, std::string> requests[] = {
        {R"({"kind": "sample", "sdf": "sphere", "pattern": "near", "n": 10, "output": ")" + samples.string() +
             R"(", "near_truncation": 2})",
         "'near_truncation': needs 'near_widths'"},
        {R"({"kind": "probe", "sdf": "sphere", "width": 64, "height": 48, "x": 70, "y": 5})",
         "'x', 'y': 70,5 lies outside the 64x48 frame"},
        {R"({"kind": "run", "manifest": ")" + manifest.string() + R"(", "rank": 3, "world_size": 2})",
         "'rank': must be below 'world_size' (2), got 3"},
    };
    const fs::path file = outputPath("keys-request.json");
    for (const auto& [json, expected] : requests) {
        std::ofstream(file) << json;
        const Result r = run("--batch request " + file.string());
        EXPECT_EQ(r.exitCode, 2) << json << "\n" << r.output;
        EXPECT_EQ(r.output, "sdfwb: " + expected + "\n") << json;
    }
    fs::remove(file);
    fs::remove(manifest);
    EXPECT_FALSE(fs::exists(samples));
}

TEST(CommandLine, UnknownTracerAndConesAreNamed) {
    fs::path out = outputPath("tracer.png");
    for (const std::string option : {"--tracer vertex", "--cones maybe"}) {
        Result r = run("--batch render --sdf sphere --output " + out.string() + " " + option);
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find(option.substr(0, option.find(' ')) + ": expected auto"), std::string::npos) << r.output;
        EXPECT_EQ(lineCount(r.output), 1) << r.output;
        EXPECT_FALSE(fs::exists(out));
    }
}

TEST(CommandLine, UnsupportedImageTypeAndMissingFolder) {
    Result r = run("--batch render --sdf sphere --output /tmp/sdfwb-cli-image.xyz");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find(".xyz"), std::string::npos) << r.output;
    r = run("--batch render --sdf sphere --output /nonexistent-folder/out.png");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("/nonexistent-folder"), std::string::npos) << r.output;
}

TEST(CommandLine, UnknownBatchCommandAndTopLevelOption) {
    Result r = run("--batch paint");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("'paint'"), std::string::npos) << r.output;
    r = run("--turbo");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("'--turbo'"), std::string::npos) << r.output;
}

TEST(CommandLine, HelpListsWhatTheCodeAccepts) {
    Result r = run("--help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* word : {"--batch", "render", "list", "exit codes"})
        EXPECT_NE(r.output.find(word), std::string::npos) << word;
    r = run("--batch render --help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* option : {"--sdf", "--output", "--size", "--time", "--shading", "--camera", "--fov", "--quiet", "--json"})
        EXPECT_NE(r.output.find(option), std::string::npos) << option;
}

TEST(CommandLine, WorkbenchWithoutDisplaySaysSo) {
    Result r = run("");
#ifdef SDFWB_WITH_GUI
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_NE(r.output.find("DISPLAY"), std::string::npos) << r.output;
#else
    // A build without the workbench (the sanitizer build) says so instead.
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("built without the workbench"), std::string::npos) << r.output;
#endif
}

TEST(CommandLine, ListFindsTheDataset) {
    Result r = run("--batch list --json");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("\"name\": \"Torus\""), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("\"declared_type\""), std::string::npos) << r.output;
}

// CLI11 converts "-5" for an unsigned option by wrapping it (to 2^64 - 5): counts and seeds are
// checked as written, and the message names the option and what it takes.
TEST(CommandLine, NegativeCountsAndSeedsAreRefusedAsSuch) {
    fs::path out = outputPath("negative.npz");
    for (const std::string& option :
         {std::string("-n -5"), std::string("-n 0"), std::string("-n 1e6"), std::string("-n 100 --seed -1")}) {
        Result r = run("--batch sample --sdf sphere --pattern rand " + option + " --output " + out.string());
        EXPECT_EQ(r.exitCode, 2) << option << ": " << r.output;
        const bool seed = option.find("--seed") != std::string::npos;
        EXPECT_NE(r.output.find(seed ? "--seed" : "-n"), std::string::npos) << option << ": " << r.output;
        EXPECT_NE(r.output.find(seed ? "must be a non-negative integer" : "must be a positive integer"), std::string::npos)
            << option << ": " << r.output;
        EXPECT_EQ(r.output.find("exceed the limit"), std::string::npos) << option << ": " << r.output;
        EXPECT_FALSE(fs::exists(out)) << option;
    }
}
