#include <shaders/DiagnosticParser.h>

#include <cctype>
#include <regex>
#include <string>

namespace sdfwb::shaders {
namespace {

// glslang's grammar token names, as a person would write them.
std::string prettyTokens(std::string message) {
    static const std::pair<const char*, const char*> names[] = {{"SEMICOLON", "';'"},
                                                                {"COMMA", "','"},
                                                                {"RIGHT_BRACE", "'}'"},
                                                                {"LEFT_BRACE", "'{'"},
                                                                {"RIGHT_PAREN", "')'"},
                                                                {"LEFT_PAREN", "'('"},
                                                                {"RIGHT_BRACKET", "']'"},
                                                                {"LEFT_BRACKET", "'['"},
                                                                {"EQUAL", "'='"},
                                                                {"DOT", "'.'"},
                                                                {"COLON", "':'"},
                                                                {"IDENTIFIER", "identifier"},
                                                                {"FLOATCONSTANT", "number"},
                                                                {"INTCONSTANT", "number"}};
    for (const auto& [token, pretty] : names) {
        std::regex word(std::string("\\b") + token + "\\b");
        message = std::regex_replace(message, word, pretty);
    }
    return message;
}

bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// 1-based column of `token` as a whole word in `line`, or 0.
int findTokenColumn(std::string_view line, std::string_view token) {
    if (token.empty()) return 0;
    std::size_t position = 0;
    while ((position = line.find(token, position)) != std::string_view::npos) {
        bool startOk = position == 0 || !isIdentifierChar(line[position - 1]) || !isIdentifierChar(token.front());
        std::size_t end = position + token.size();
        bool endOk = end >= line.size() || !isIdentifierChar(line[end]) || !isIdentifierChar(token.back());
        if (startOk && endOk) return int(position) + 1;
        position = end;
    }
    return 0;
}

bool isBlank(std::string_view line) {
    for (char c : line)
        if (!std::isspace(static_cast<unsigned char>(c))) return false;
    return true;
}

// Length of the line without a trailing // comment and whitespace.
int codeEnd(std::string_view line) {
    std::size_t comment = line.find("//");
    std::string_view code = line.substr(0, comment);
    while (!code.empty() && std::isspace(static_cast<unsigned char>(code.back()))) code.remove_suffix(1);
    return int(code.size());
}

Severity severityFromWord(std::string word) {
    for (char& c : word) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (word == "warning") return Severity::Warning;
    if (word == "note") return Severity::Note;
    return Severity::Error;
}

void addDiagnostic(std::vector<Diagnostic>& out, const SourceMap& map, int fileIndex, int line, int column, Severity severity,
                   std::string token, std::string message) {
    // glslang reports what it could not parse, not what is missing: for a missing ';' the
    // culprit is the end of the previous statement.
    bool missingSemicolon = message.find("expecting") != std::string::npos && message.find("SEMICOLON") != std::string::npos;
    message = prettyTokens(message);
    std::string_view lineText = map.lineText(fileIndex, line);
    if (column == 0) column = findTokenColumn(lineText, token);
    if (missingSemicolon) {
        std::size_t firstCode = lineText.find_first_not_of(" \t");
        bool atLineStart = firstCode == std::string_view::npos || column == 0 || int(firstCode) + 1 >= column;
        if (atLineStart) {
            int previous = line - 1;
            while (previous >= 1 &&
                   isBlank(map.lineText(fileIndex, previous).substr(0, std::size_t(codeEnd(map.lineText(fileIndex, previous))))))
                --previous;
            if (previous >= 1) {
                line = previous;
                column = codeEnd(map.lineText(fileIndex, previous)) + 1;
                message = "missing ';' at the end of this statement (" + message + ")";
            }
        }
    }
    if (!token.empty() && message.find('\'' + token + '\'') == std::string::npos) message += ": '" + token + "'";
    out.push_back({map.fileName(fileIndex), line, column, severity, std::move(message)});
}

} // namespace

std::vector<Diagnostic> parseInfoLog(std::string_view log, const SourceMap& map) {
    // glslang: "ERROR: 2:14: 'token' : message"
    static const std::regex glslang(R"(^(ERROR|WARNING|NOTE|UNIMPLEMENTED):\s*(\d+):(\d+):\s*'([^']*)'\s*:\s*(.*?)\s*$)");
    // Mesa: "2:14(7): error: message"
    static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\):\s*(error|warning|note)\s*:\s*(.*?)\s*$)");
    // NVIDIA: "2(14) : error C1008: message"
    static const std::regex nvidia(R"(^(\d+)\((\d+)\)\s*:\s*(error|warning)\s*\w*\s*:\s*(.*?)\s*$)");

    std::vector<Diagnostic> out;
    std::size_t start = 0;
    while (start < log.size()) {
        std::size_t end = log.find('\n', start);
        std::string line(log.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
        start = end == std::string_view::npos ? log.size() : end + 1;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::smatch m;
        if (std::regex_match(line, m, glslang)) {
            std::string message = m[5].str();
            if (message == "compilation terminated") continue;
            std::string word = m[1].str() == "UNIMPLEMENTED" ? "error" : m[1].str();
            addDiagnostic(out, map, std::stoi(m[2].str()), std::stoi(m[3].str()), 0, severityFromWord(word), m[4].str(), message);
        } else if (std::regex_match(line, m, mesa)) {
            addDiagnostic(out, map, std::stoi(m[1].str()), std::stoi(m[2].str()), std::stoi(m[3].str()),
                          severityFromWord(m[4].str()), "", m[5].str());
        } else if (std::regex_match(line, m, nvidia)) {
            addDiagnostic(out, map, std::stoi(m[1].str()), std::stoi(m[2].str()), 0, severityFromWord(m[3].str()), "",
                          m[4].str());
        } else if (line.rfind("ERROR: ", 0) == 0 && line.find("compilation errors") == std::string::npos &&
                   line.find("No code generated") == std::string::npos) {
            // An error without location (e.g. a link error): keep it, attributed to the root file.
            out.push_back({map.fileName(0), 0, 0, Severity::Error, line.substr(7)});
        }
    }
    return out;
}

} // namespace sdfwb::shaders
