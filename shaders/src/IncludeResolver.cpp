#include <shaders/IncludeResolver.h>

#include <core/Paths.h>
#include <core/Regex.h>
#include <core/TextFile.h>

#include <algorithm>
#include <regex>
#include <set>

namespace sdfwb::shaders {
namespace fs = std::filesystem;

namespace {

// `#define B(1-fract(t*2))`: a ( right after the macro's name that does not begin a parameter list
// (names separated by commas). GLSL reads a function-like macro and fails; NVIDIA's driver, where
// such shaders were written (Bonzomatic, golfed code), reads the value `(1-fract(t*2))`. The offset
// of that (, or npos.
std::size_t malformedMacroParenthesis(const std::string& line) {
    static const std::regex define(R"(^\s*#\s*define\s+[A-Za-z_]\w*\()", kLinearRegex);
    static const std::regex parameters(R"(\s*([A-Za-z_]\w*\s*(,\s*[A-Za-z_]\w*\s*)*)?)", kLinearRegex);
    std::smatch match;
    if (!std::regex_search(line, match, define)) return std::string::npos;
    const std::size_t open = std::size_t(match.length(0)) - 1, close = line.find(')', open);
    if (close == std::string::npos ||
        std::regex_match(line.begin() + std::ptrdiff_t(open) + 1, line.begin() + std::ptrdiff_t(close), parameters))
        return std::string::npos;
    return open;
}

} // namespace

std::string_view SourceMap::lineText(int index, int line) const {
    if (index < 0 || index >= int(files.size()) || line < 1) return {};
    std::string_view text = files[std::size_t(index)].text;
    std::size_t start = 0;
    for (int i = 1; i < line; ++i) {
        std::size_t newline = text.find('\n', start);
        if (newline == std::string_view::npos) return {};
        start = newline + 1;
    }
    std::size_t end = text.find('\n', start);
    std::string_view result = text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
    if (!result.empty() && result.back() == '\r') result.remove_suffix(1);
    return result;
}

std::string SourceMap::fileName(int index) const {
    if (index < 0 || index >= int(files.size())) return "<unknown source " + std::to_string(index) + ">";
    return files[std::size_t(index)].name;
}

namespace {

std::vector<std::string_view> splitLines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) {
            if (start < text.size()) lines.push_back(text.substr(start));
            break;
        }
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.push_back(line);
        start = end + 1;
    }
    return lines;
}

// Tracks /* */ comments across lines so directives inside comments are left alone.
// Returns whether the line starts outside a comment, and updates the state for the next line.
bool startsOutsideComment(std::string_view line, bool& inBlockComment) {
    bool outside = !inBlockComment;
    for (std::size_t i = 0; i < line.size(); ++i) {
        if (inBlockComment) {
            if (line[i] == '*' && i + 1 < line.size() && line[i + 1] == '/') {
                inBlockComment = false;
                ++i;
            }
        } else if (line[i] == '/' && i + 1 < line.size()) {
            if (line[i + 1] == '/') break;
            if (line[i + 1] == '*') {
                inBlockComment = true;
                ++i;
            }
        }
    }
    return outside;
}

// Includes can expand exponentially (a file that includes another twice, nested a few levels:
// 40 lines on each of 3 levels took 20 s and would take hours at 5). Real SDFs include a few
// files; past these limits the rest of the #includes are skipped with one diagnostic.
constexpr std::size_t kMaxIncludedFiles = 1024;
constexpr std::size_t kMaxExpandedBytes = 16u << 20;

class Resolver {
public:
    Resolver(const IncludeOptions& options, ResolvedSource& out) : m_options(options), m_out(out) {}

    void addRoot(const fs::path& root) {
        std::error_code ec;
        fs::path canonical = fs::weakly_canonical(root, ec);
        if (!ec) m_roots.push_back(canonical);
    }

    void run(const std::string& text, const std::string& name, const fs::path& path) {
        m_out.map.files.push_back({name, text});
        std::error_code ec;
        fs::path canonical = path.empty() ? fs::path() : fs::weakly_canonical(path, ec);
        expand(0, canonical, 0);
    }

private:
    void expand(int fileIndex, const fs::path& canonicalPath, int depth) {
        // Copy: m_out.map.files may grow (and reallocate) while we expand.
        const std::string text = m_out.map.files[std::size_t(fileIndex)].text;
        const std::string name = m_out.map.files[std::size_t(fileIndex)].name;
        if (!canonicalPath.empty()) m_stack.push_back(canonicalPath);
        m_out.text += "#line 1 " + std::to_string(fileIndex) + "\n";

        static const std::regex includeQuoted(R"re(^\s*#\s*include\s+"([^"]*)"\s*(//.*)?$)re", kLinearRegex);
        static const std::regex includeAny(R"(^\s*#\s*include\b.*$)", kLinearRegex);
        static const std::regex versionLine(R"(^\s*#\s*version\b.*$)", kLinearRegex);
        static const std::regex pragmaOnce(R"(^\s*#\s*pragma\s+once\s*$)", kLinearRegex);
        static const std::regex extensionLine(R"(^\s*#\s*extension\s+(\w+)\s*:\s*(\w+)\s*$)", kLinearRegex);

        bool inBlockComment = false;
        std::vector<std::string_view> lines = splitLines(text);
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const std::string line(lines[i]);
            const int lineNumber = int(i) + 1;
            // Directives start with '#' after blanks; other lines skip the four regexes.
            const std::size_t firstCharacter = line.find_first_not_of(" \t\v\f\r");
            bool directiveAllowed = startsOutsideComment(lines[i], inBlockComment) && firstCharacter != std::string::npos &&
                                    line[firstCharacter] == '#';
            std::smatch match;
            if (directiveAllowed && std::regex_match(line, match, includeQuoted)) {
                int column = int(line.find('"')) + 1;
                includeFile(match[1].str(), name, lineNumber, column, canonicalPath, depth);
                m_out.text += "#line " + std::to_string(lineNumber + 1) + " " + std::to_string(fileIndex) + "\n";
            } else if (directiveAllowed && std::regex_match(line, includeAny)) {
                m_out.diagnostics.push_back({name, lineNumber, int(line.find('#')) + 1, Severity::Error,
                                             "malformed #include: expected #include \"file.glsl\""});
                m_out.text += "\n";
            } else if (directiveAllowed && (std::regex_match(line, versionLine) || std::regex_match(line, pragmaOnce))) {
                m_out.text += "\n"; // the composer writes #version; #pragma once is handled here
            } else if (directiveAllowed && std::regex_match(line, match, extensionLine)) {
                // Directives must precede the composed code; ES extensions are part of core 4.30.
                const std::string extension = match[1].str();
                const bool es = extension.rfind("GL_OES_", 0) == 0 || extension.rfind("GL_EXT_", 0) == 0;
                const std::string directive = "#extension " + extension + " : " + match[2].str();
                if (!es && std::find(m_out.extensions.begin(), m_out.extensions.end(), directive) == m_out.extensions.end())
                    m_out.extensions.push_back(directive);
                m_out.text += "\n";
            } else if (const std::size_t open = directiveAllowed ? malformedMacroParenthesis(line) : std::string::npos;
                       open != std::string::npos) {
                const std::size_t macroStart = line.find("define") + 6;
                const std::string macro = line.substr(macroStart, open - macroStart);
                m_out.diagnostics.push_back({name, lineNumber, int(open) + 1, Severity::Warning,
                                             "this ( does not begin a parameter list, so #define" + macro +
                                                 "( is no function-like macro: read as the value of" + macro +
                                                 ", as NVIDIA's driver reads it (a space before the ( says so in GLSL)"});
                m_out.text += line.substr(0, open) + " " + line.substr(open) + "\n";
            } else {
                // A NUL byte, which the source checks allow only in comments: a space for the compilers
                // (Mesa's preprocessor ends the code there).
                const std::size_t at = m_out.text.size();
                m_out.text += line;
                std::replace(m_out.text.begin() + std::ptrdiff_t(at), m_out.text.end(), '\0', ' ');
                m_out.text += "\n";
            }
        }
        if (!canonicalPath.empty()) m_stack.pop_back();
    }

    void includeFile(const std::string& target, const std::string& includer, int line, int column, const fs::path& includerPath,
                     int depth) {
        auto report = [&](std::string message) {
            m_out.diagnostics.push_back({includer, line, column, Severity::Error, std::move(message)});
        };
        if (target.empty()) return report("empty #include path");
        if (depth + 1 > m_options.maxDepth)
            return report("#include \"" + target + "\": include chain deeper than " + std::to_string(m_options.maxDepth));

        std::vector<fs::path> candidates;
        if (!includerPath.empty()) candidates.push_back(includerPath.parent_path() / target);
        for (const fs::path& root : m_options.libraryRoots) candidates.push_back(root / target);

        std::error_code ec;
        fs::path found;
        bool escaped = false;
        for (const fs::path& candidate : candidates) {
            if (!fs::is_regular_file(candidate, ec)) continue;
            fs::path canonical = fs::weakly_canonical(candidate, ec);
            if (ec) continue;
            if (!paths::isInsideRoots(canonical, m_roots)) {
                escaped = true;
                continue;
            }
            found = canonical;
            break;
        }
        if (found.empty()) {
            if (escaped) return report("#include \"" + target + "\": path leaves the allowed include roots");
            return report("#include \"" + target + "\": file not found (looked next to " + includer +
                          (m_options.libraryRoots.empty() ? std::string(")") : " and in the library roots)"));
        }
        if (std::find(m_stack.begin(), m_stack.end(), found) != m_stack.end()) {
            std::string chain;
            for (const fs::path& p : m_stack) chain += p.filename().string() + " -> ";
            return report("#include cycle: " + chain + found.filename().string());
        }
        if (m_onceFiles.count(found)) return;
        if (m_out.map.files.size() > kMaxIncludedFiles || m_out.text.size() > kMaxExpandedBytes) {
            if (m_limitReported) return;
            m_limitReported = true;
            return report("#include \"" + target + "\": too many includes (over " + std::to_string(kMaxIncludedFiles) +
                          " files or " + std::to_string(kMaxExpandedBytes >> 20) +
                          " MiB expanded); is a file included repeatedly without #pragma once?");
        }

        auto text = readTextFile(found);
        if (!text) return report("#include \"" + target + "\": " + text.error().message);
        static const std::regex pragmaOnceInFile(R"((^|\n)\s*#\s*pragma\s+once\s*(\r?\n|$))", kLinearRegex);
        if (std::regex_search(*text, pragmaOnceInFile)) m_onceFiles.insert(found);

        int index = int(m_out.map.files.size());
        m_out.map.files.push_back({found.string(), std::move(*text)});
        expand(index, found, depth + 1);
    }

    const IncludeOptions& m_options;
    ResolvedSource& m_out;
    std::vector<fs::path> m_roots;
    std::vector<fs::path> m_stack;
    std::set<fs::path> m_onceFiles;
    bool m_limitReported = false;
};

} // namespace

ResolvedSource resolveIncludes(const std::string& text, const std::string& name, const fs::path& path,
                               const IncludeOptions& options) {
    ResolvedSource out;
    Resolver resolver(options, out);
    if (!path.empty()) resolver.addRoot(path.parent_path().empty() ? fs::path(".") : path.parent_path());
    for (const fs::path& root : options.libraryRoots) resolver.addRoot(root);
    resolver.run(text, name, path);
    return out;
}

} // namespace sdfwb::shaders
