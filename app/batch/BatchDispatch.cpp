// The headless command line's front door: `--help` (the overview), `--version`, `--batch COMMAND`
// through the table of batch commands (CommandTable.h), `--batch JOBFILE` (every line checked
// before any runs), and the paper's `--sample` form.

#include "BatchCommands.h"
#include "CommandLine.h"
#include "CommandTable.h"

#include <jobs/JobJson.h>
#include <values/JobKinds.h>

#include <core/Regex.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace sdfwb::app {
namespace {

using detail::Arguments;
using detail::BatchCommandEntry;
using detail::batchCommandNames;
using detail::findBatchCommand;
using detail::Mode;

const char* const kOverview =
    "sdfwb " SDFWB_VERSION " - the SDF Workbench\n"
    "\n"
    "usage:\n"
    "  sdfwb [FILE.glsl]                  open the workbench on FILE (or on the default SDF)\n"
    "  sdfwb --batch <command> [options]  run headless (EGL, no display needed)\n"
    "  sdfwb --batch <command> --help     the options of one command\n"
    "  sdfwb --batch JOBFILE              run the batch steps in JOBFILE, one command per line\n"
    "  sdfwb --sample <Pattern> <N> <SDF> <outfile>   sample (the original sdf-explorer's form)\n"
    "  sdfwb --help | --version\n"
    "\n"
    "batch commands:\n"
    "  render   sphere-trace an SDF into an image (.png, .jpg, .exr)\n"
    "  animate  render an MP4 (H.264) over time and/or as a turntable\n"
    "  sample   write N (position, distance, gradient) samples to .bin, .npz or .ply\n"
    "  merge    join --shard outputs into the file one run would have written\n"
    "  audit    analyse the field: exact, conservative, non-conservative, truncated, discontinuous, nan\n"
    "  list     list the dataset (name, category, declared type, animated)\n"
    "  bench    measure error against run time (tracer, samplers, gradients, audit) into a report\n"
    "  params   list the parameters (annotated uniforms) an SDF declares\n"
    "  mesh     extract the surface as a mesh (.ply, .obj, .stl, .glb) with sharp edges, graded against the field\n"
    "  grade    grade any mesh against the exact field: Chamfer, F-score, normal consistency, Hausdorff, IoU\n"
    "           (`eval` is its old name, still accepted; the field at points is Python's sdfwb.evaluate)\n"
    "  probe    the march debugger: every step of one pixel's ray (position, f, step, |grad f|, oversteps)\n"
    "  run      many shapes from a manifest (CSV or JSON lines: sdf, pattern or recipe, n, seed, output),\n"
    "           each item in a child process; resumable (status file), --rank/--world-size slices\n"
    "  request  run one request given as JSON (FILE or - for stdin); every command's --print-request\n"
    "           prints the JSON its options make\n"
    "\n"
    "<SDF> arguments take a dataset name (any case) or a path to a .glsl file. <Pattern> takes a\n"
    "built-in pattern (grid, image, jitter, rand, surface, near, metropolis, metropolis_curvature),\n"
    "a path to a sampler .glsl file, or the name of one in $SDFWB_SAMPLER_PATH or\n"
    "~/.local/share/sdfwb/samplers. A job file holds one batch command per line, as typed after\n"
    "--batch, or one JSON request per line ('#' starts a comment); it runs no shell and stops at the\n"
    "first failing step.\n"
    "exit codes: 0 success, 1 the work failed, 2 bad arguments, 3 no OpenGL 4.3 context,\n"
    "130 interrupted (no partial file is left)\n";

int runBatchCommand(const std::string& command, const Arguments& arguments, Mode mode);

// Splits a job-file line into words: whitespace separates, '...' and "..." quote, \ escapes,
// '#' at the start of a word begins a comment. Nothing is expanded or executed.
std::optional<Arguments> splitWords(const std::string& line, std::string& error) {
    Arguments words;
    std::string word;
    bool inWord = false;
    char quote = 0;
    for (std::size_t i = 0; i < line.size(); ++i) {
        char c = line[i];
        if (quote) {
            if (c == quote)
                quote = 0;
            else if (c == '\\' && quote == '"' && i + 1 < line.size())
                word += line[++i];
            else
                word += c;
        } else if (c == '\'' || c == '"') {
            quote = c;
            inWord = true;
        } else if (c == '\\' && i + 1 < line.size()) {
            word += line[++i];
            inWord = true;
        } else if (c == ' ' || c == '\t' || c == '\r') {
            if (inWord) words.push_back(word);
            word.clear();
            inWord = false;
        } else if (c == '#' && !inWord) {
            break;
        } else {
            word += c;
            inWord = true;
        }
    }
    if (quote) {
        error = std::string("unterminated ") + quote + " quote";
        return std::nullopt;
    }
    if (inWord) words.push_back(word);
    return words;
}

// Runs (or checks) the job file `text`; `name` labels the messages.
int runJobText(const std::string& text, const std::string& name, Mode mode) {
    std::istringstream file(text);
    // Check every line before running any, so a typo on line 9 does not waste lines 1-8.
    struct Step {
        int line = 0;
        Arguments words;                        // a command as typed after --batch
        std::optional<values::Request> request; // or a request's JSON on one line
        std::string name() const { return request ? values::kindName(*request) : words.front(); }
    };
    std::vector<Step> steps;
    std::string line;
    int lineNumber = 0;
    while (std::getline(file, line)) {
        ++lineNumber;
        const std::string where = name + ":" + std::to_string(lineNumber) + ": ";
        if (const auto first = line.find_first_not_of(" \t\r"); first != std::string::npos && line[first] == '{') {
            auto request = jobs::requestFromJson(line);
            if (!request) {
                printError(where + request.error().message);
                return kExitUsage;
            }
            steps.push_back({lineNumber, {}, std::move(*request)});
            continue;
        }
        std::string error;
        auto words = splitWords(line, error);
        if (!words) {
            printError(where + error);
            return kExitUsage;
        }
        if (words->empty()) continue;
        if (!findBatchCommand(words->front())) {
            printError(where + "unknown command '" + words->front() + "' (" + batchCommandNames() + ", or a JSON request)");
            return kExitUsage;
        }
        steps.push_back({lineNumber, std::move(*words), std::nullopt});
    }
    if (steps.empty()) {
        printError(name + ": the job file has no steps");
        return kExitUsage;
    }
    for (const Step& step : steps) {
        int exitCode = kExitOk;
        if (step.request)
            exitCode = mode == Mode::Check ? kExitOk : runRequest(*step.request, OutputOptions{});
        else
            exitCode = runBatchCommand(step.words.front(), Arguments(step.words.begin() + 1, step.words.end()), mode);
        if (exitCode != kExitOk) {
            printError(name + ":" + std::to_string(step.line) + ": step '" + step.name() + "' failed (exit code " +
                       std::to_string(exitCode) + "); later steps not run");
            return exitCode;
        }
    }
    return kExitOk;
}

int runJobFile(const std::string& path, Mode mode) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        printError("'" + path + "': cannot read the job file");
        return kExitUsage;
    }
    std::ostringstream text;
    text << file.rdbuf();
    return runJobText(text.str(), path, mode);
}

int runBatchCommand(const std::string& command, const Arguments& arguments, Mode mode) {
    if (const BatchCommandEntry* entry = findBatchCommand(command)) return entry->run(arguments, mode);
    printError("--batch: unknown command '" + command + "' (" + batchCommandNames() + ", or a job file); see sdfwb --help");
    return kExitUsage;
}

// `arguments` are argv[1..].
std::optional<int> commandLine(const Arguments& arguments, Mode mode) {
    if (arguments.empty()) return std::nullopt;
    const std::string& first = arguments[0];
    if (first == "--help" || first == "-h") {
        std::printf("%s", kOverview);
        return kExitOk;
    }
    if (first == "--version") {
        std::printf("sdfwb %s\n", SDFWB_VERSION);
        return kExitOk;
    }
    if (first == "--batch") {
        if (arguments.size() < 2) {
            printError("--batch: missing command (" + batchCommandNames() + ") or job file; see sdfwb --help");
            return kExitUsage;
        }
        const std::string& command = arguments[1];
        if (command == "--help" || command == "-h") {
            std::printf("%s", kOverview);
            return kExitOk;
        }
        const Arguments rest(arguments.begin() + 2, arguments.end());
        std::error_code ec;
        if (!findBatchCommand(command) && std::filesystem::is_regular_file(command, ec)) {
            if (!rest.empty()) {
                printError("--batch " + command + ": a job file takes no further arguments");
                return kExitUsage;
            }
            return runJobFile(command, mode);
        }
        return runBatchCommand(command, rest, mode);
    }
    if (first == "--sample") {
        // The paper's interface: sdfwb --sample <Pattern> <N> <SDF> <outfile>
        if (arguments.size() != 5) {
            printError("--sample: expected <Pattern> <N> <SDF> <outfile>; see sdfwb --help");
            return kExitUsage;
        }
        values::SampleRequest command;
        command.pattern = arguments[1];
        command.sdf.sdf = arguments[3];
        command.output = arguments[4];
        static const std::regex digits(R"(^\d{1,19}$)", kLinearRegex);
        if (!std::regex_match(arguments[2], digits)) {
            printError("--sample: <N> must be a positive integer, got '" + arguments[2] + "'");
            return kExitUsage;
        }
        command.count = std::stoull(arguments[2]);
        // The original wrote .bin whatever the name; keep that unless the name asks for npz/ply.
        std::string extension = std::filesystem::path(command.output).extension().string();
        if (extension != ".npz" && extension != ".ply") command.format = "bin";
        if (mode == Mode::Check) return kExitOk;
        return runSample(command, OutputOptions{});
    }
    if (first.rfind("-", 0) == 0) {
        printError("unknown option '" + first + "'; see sdfwb --help");
        return kExitUsage;
    }
    if (arguments.size() > 1) {
        printError("unexpected argument '" + arguments[1] + "': the workbench opens one file; see sdfwb --help");
        return kExitUsage;
    }
    return std::nullopt; // the workbench, on argv[1]
}

} // namespace

std::optional<int> runCommandLine(int argc, char** argv) {
    return commandLine(Arguments(argv + std::min(argc, 1), argv + argc), Mode::Run);
}

std::optional<int> checkCommandLine(const std::vector<std::string>& arguments) { return commandLine(arguments, Mode::Check); }

int checkJobFile(const std::string& text, const std::string& name) { return runJobText(text, name, Mode::Check); }

} // namespace sdfwb::app
