#include <shaders/LoopLimits.h>

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <atomic>
#include <cctype>
#include <cmath>
#include <deque>
#include <mutex>
#include <optional>
#include <string>

namespace sdfwb::shaders {
namespace {

std::atomic<std::uint64_t> g_driverLoopLimit{0};

EShLanguage toLanguage(Stage stage) {
    return stage == Stage::Vertex ? EShLangVertex : stage == Stage::Compute ? EShLangCompute : EShLangFragment;
}

std::optional<double> constantOf(const glslang::TIntermTyped* node) {
    const glslang::TIntermConstantUnion* constant = node ? node->getAsConstantUnion() : nullptr;
    if (!constant || constant->getConstArray().size() != 1) return std::nullopt;
    const glslang::TConstUnion& value = constant->getConstArray()[0];
    switch (value.getType()) {
    case glslang::EbtInt:
        return double(value.getIConst());
    case glslang::EbtUint:
        return double(value.getUConst());
    case glslang::EbtFloat:
    case glslang::EbtDouble:
        return value.getDConst();
    default:
        return std::nullopt;
    }
}

const glslang::TIntermSymbol* symbolOf(const TIntermNode* node) { return node ? node->getAsSymbolNode() : nullptr; }

// The loop counter's start, from the statement before a `for` loop (glslang puts the init
// statement and the loop in one sequence): `int i = C` or `i = C`.
struct Start {
    long long id;
    double value;
};
void findStarts(TIntermNode* node, std::vector<Start>& starts) {
    if (!node) return;
    if (glslang::TIntermBinary* binary = node->getAsBinaryNode()) {
        if (binary->getOp() == glslang::EOpAssign)
            if (const glslang::TIntermSymbol* symbol = symbolOf(binary->getLeft()))
                if (auto value = constantOf(binary->getRight())) starts.push_back({symbol->getId(), *value});
        return;
    }
    if (glslang::TIntermAggregate* aggregate = node->getAsAggregate())
        if (aggregate->getOp() == glslang::EOpSequence)
            for (TIntermNode* child : aggregate->getSequence()) findStarts(child, starts);
}

// How many times a loop with this test and terminal runs from `start`, or nothing when the test
// or the step is not `counter <op> constant` / `counter += constant` (or ++/--).
std::optional<double> tripCount(const glslang::TIntermLoop* loop, const Start& start) {
    const glslang::TIntermBinary* test = loop->getTest() ? loop->getTest()->getAsBinaryNode() : nullptr;
    if (!test) return std::nullopt;
    const glslang::TIntermSymbol* counter = symbolOf(test->getLeft());
    auto limit = constantOf(test->getRight());
    if (!counter || counter->getId() != start.id || !limit) return std::nullopt;
    double step = 0.0;
    const TIntermNode* terminal = loop->getTerminal();
    if (const glslang::TIntermUnary* unary = terminal ? terminal->getAsUnaryNode() : nullptr) {
        const glslang::TIntermSymbol* stepped = symbolOf(unary->getOperand());
        if (!stepped || stepped->getId() != start.id) return std::nullopt;
        const glslang::TOperator op = unary->getOp();
        if (op == glslang::EOpPostIncrement || op == glslang::EOpPreIncrement) step = 1.0;
        if (op == glslang::EOpPostDecrement || op == glslang::EOpPreDecrement) step = -1.0;
    } else if (const glslang::TIntermBinary* binary = terminal ? terminal->getAsBinaryNode() : nullptr) {
        const glslang::TIntermSymbol* stepped = symbolOf(binary->getLeft());
        auto amount = constantOf(binary->getRight());
        if (!stepped || stepped->getId() != start.id || !amount) return std::nullopt;
        if (binary->getOp() == glslang::EOpAddAssign) step = *amount;
        if (binary->getOp() == glslang::EOpSubAssign) step = -*amount;
    }
    if (step == 0.0) return std::nullopt;
    const double span = *limit - start.value;
    switch (test->getOp()) {
    case glslang::EOpLessThan:
        return step > 0.0 && span > 0.0 ? std::ceil(span / step) : 0.0;
    case glslang::EOpLessThanEqual:
        return step > 0.0 && span >= 0.0 ? std::floor(span / step) + 1.0 : 0.0;
    case glslang::EOpGreaterThan:
        return step < 0.0 && span < 0.0 ? std::ceil(span / step) : 0.0;
    case glslang::EOpGreaterThanEqual:
        return step < 0.0 && span <= 0.0 ? std::floor(span / step) + 1.0 : 0.0;
    default:
        return std::nullopt;
    }
}

class LoopFinder : public glslang::TIntermTraverser {
public:
    LoopFinder(const ComposedShader& shader, std::uint64_t limit, std::string_view driver)
        : m_shader(shader), m_limit(limit), m_driver(driver) {}
    std::vector<Diagnostic> found;

    bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* aggregate) override {
        if (aggregate->getOp() != glslang::EOpSequence) return true;
        const glslang::TIntermSequence& sequence = aggregate->getSequence();
        for (std::size_t i = 1; i < sequence.size(); ++i)
            if (const glslang::TIntermLoop* loop = sequence[i] ? sequence[i]->getAsLoopNode() : nullptr) {
                std::vector<Start> starts;
                findStarts(sequence[i - 1], starts);
                for (const Start& start : starts)
                    if (auto count = tripCount(loop, start); count && *count > double(m_limit)) report(*loop, *count);
            }
        return true;
    }

private:
    void report(const glslang::TIntermLoop& loop, double count) {
        const glslang::TSourceLoc& location = loop.getLoc();
        Diagnostic diagnostic;
        diagnostic.file = m_shader.map.fileName(location.string);
        diagnostic.line = location.line;
        diagnostic.column = location.column;
        diagnostic.severity = Severity::Warning;
        char text[320];
        std::snprintf(text, sizeof text,
                      "this loop runs up to %.0f times, but %.*s ends every loop after %llu iterations without an "
                      "error: the result is silently wrong (split it into nested loops of at most %llu each, or "
                      "run on a GPU)",
                      count, int(m_driver.size()), m_driver.data(), (unsigned long long)m_limit, (unsigned long long)m_limit);
        diagnostic.message = text;
        found.push_back(std::move(diagnostic));
    }
    const ComposedShader& m_shader;
    std::uint64_t m_limit;
    std::string_view m_driver;
};

} // namespace

namespace {
std::vector<Diagnostic> parseForLongLoops(const ComposedShader& composed, std::uint64_t limit, std::string_view driver);
} // namespace

bool hasLargeNumber(const PreparedSdf& sdf) {
    for (const SourceFile& file : sdf.source.map.files) {
        const std::string& text = file.text;
        for (std::size_t i = 0; i < text.size();) {
            if (text[i] < '0' || text[i] > '9' ||
                (i > 0 && (std::isalnum(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '_'))) {
                ++i;
                continue;
            }
            std::size_t end = i;
            while (end < text.size() && text[end] >= '0' && text[end] <= '9') ++end;
            if (end - i > 5 || (end - i == 5 && std::stoul(text.substr(i, 5)) >= 32768)) return true;
            // 1e5, 2.5E+6: an exponent of 5 or more
            std::size_t at = end;
            if (at < text.size() && text[at] == '.')
                while (++at < text.size() && text[at] >= '0' && text[at] <= '9') {}
            if (at + 1 < text.size() && (text[at] == 'e' || text[at] == 'E')) {
                std::size_t digits = at + 1 + (text[at + 1] == '+' || text[at + 1] == '-');
                int exponent = 0;
                while (digits < text.size() && text[digits] >= '0' && text[digits] <= '9') {
                    if (exponent < 100) exponent = exponent * 10 + (text[digits] - '0');
                    ++digits;
                }
                if (exponent >= 5 && text[at + 1] != '-') return true;
                at = digits;
            }
            // Past the whole literal: the digits of a fraction (0.7071067811) or of an exponent are
            // not a number of their own.
            i = std::max(end, at);
        }
    }
    return false;
}

std::vector<Diagnostic> findLongLoops(const PreparedSdf& sdf, const ComposedShader& composed, std::uint64_t limit,
                                      std::string_view driver) {
    if (limit == 0 || !hasLargeNumber(sdf)) return {};
    // The same shader again (each mesh call, each sample run in a process builds its evaluators):
    // the warnings found last time, without a second glslang parse.
    struct Known {
        std::string text;
        std::uint64_t limit;
        std::string driver;
        std::vector<Diagnostic> found;
    };
    static std::mutex knownMutex;
    static std::deque<Known> known;  // the newest last, at most 16
    std::string key = composed.text; // the text and the names its diagnostics use
    for (const SourceFile& file : composed.map.files) key += '\0' + file.name;
    {
        std::lock_guard lock(knownMutex);
        for (const Known& k : known)
            if (k.limit == limit && k.driver == driver && k.text == key) return k.found;
    }
    std::vector<Diagnostic> found = parseForLongLoops(composed, limit, driver);
    std::lock_guard lock(knownMutex);
    known.push_back({std::move(key), limit, std::string(driver), found});
    if (known.size() > 16) known.pop_front();
    return found;
}

namespace {

std::vector<Diagnostic> parseForLongLoops(const ComposedShader& composed, std::uint64_t limit, std::string_view driver) {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
    glslang::TShader shader(toLanguage(composed.stage));
    const char* text = composed.text.c_str();
    const int length = int(composed.text.size()); // past a NUL byte in a comment, as the checker reads it
    shader.setStringsWithLengths(&text, &length, 1);
    if (!shader.parse(GetDefaultResources(), 430, ECoreProfile, false, false, EShMsgDefault)) return {};
    glslang::TIntermediate* intermediate = shader.getIntermediate();
    if (!intermediate || !intermediate->getTreeRoot()) return {};
    LoopFinder finder(composed, limit, driver);
    intermediate->getTreeRoot()->traverse(&finder);
    return std::move(finder.found);
}

} // namespace

std::uint64_t loopLimitOf(std::string_view rendererString) {
    return rendererString.find("llvmpipe") != std::string_view::npos ? kLlvmpipeLoopLimit : 0;
}

void setDriverLoopLimit(std::uint64_t limit) { g_driverLoopLimit.store(limit); }
std::uint64_t driverLoopLimit() { return g_driverLoopLimit.load(); }

} // namespace sdfwb::shaders
