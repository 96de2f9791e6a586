#include <widgets/GlslEditor.h>

#include "GlslLexer.h"

#include <Qsci/qsciapis.h>

#include <QColor>
#include <QFileInfo>
#include <QFontMetrics>

#include <algorithm>
#include <map>

namespace sdfwb::widgets {

GlslEditor::GlslEditor(QWidget* parent) : QsciScintilla(parent) {
    m_lexer = new GlslLexer(this);
    setLexer(m_lexer);
    setUtf8(true);
    setIndentationsUseTabs(false);
    setIndentationWidth(4);
    setTabWidth(4);
    setAutoIndent(true);
    setBraceMatching(SloppyBraceMatch);
    setFolding(BoxedTreeFoldStyle);
    setCaretLineVisible(true);
    setCaretLineBackgroundColor(QColor(0xf4, 0xf4, 0xf8));

    setMarginType(0, NumberMargin);
    setMarginLineNumbers(0, true);
    setMarginWidth(0, QFontMetrics(m_lexer->font(0)).horizontalAdvance("00000") + 6);
    setMarginType(1, SymbolMargin);
    setMarginWidth(1, 14);
    setMarginSensitivity(1, false);

    m_errorMarker = markerDefine(Circle, 8);
    setMarkerBackgroundColor(QColor(0xd0, 0x20, 0x20), m_errorMarker);
    setMarkerForegroundColor(QColor(0x90, 0x10, 0x10), m_errorMarker);
    m_warningMarker = markerDefine(Circle, 9);
    setMarkerBackgroundColor(QColor(0xe0, 0xa0, 0x10), m_warningMarker);
    setMarkerForegroundColor(QColor(0xa0, 0x70, 0x00), m_warningMarker);
    setMarginMarkerMask(1, (1 << m_errorMarker) | (1 << m_warningMarker));

    m_errorIndicator = indicatorDefine(SquiggleIndicator, 8);
    setIndicatorForegroundColor(QColor(0xd0, 0x20, 0x20), m_errorIndicator);
    m_warningIndicator = indicatorDefine(SquiggleIndicator, 9);
    setIndicatorForegroundColor(QColor(0xe0, 0xa0, 0x10), m_warningIndicator);
    setAnnotationDisplay(AnnotationBoxed);

    m_apis = new QsciAPIs(m_lexer);
    setAutoCompletionSource(AcsAll);
    setAutoCompletionThreshold(2);
    setAutoCompletionCaseSensitivity(true);
    setCallTipsStyle(CallTipsNoContext);
    setCallTipsVisible(0);
    setCompletionFunctions({}, {});
}

namespace {

// GLSL built-in functions with their parameters, for completion and call tips.
const char* const kBuiltins[] = {"abs(x)",
                                 "acos(x)",
                                 "all(bvec x)",
                                 "any(bvec x)",
                                 "asin(x)",
                                 "atan(y, x)",
                                 "atan(y_over_x)",
                                 "ceil(x)",
                                 "clamp(x, minVal, maxVal)",
                                 "cos(x)",
                                 "cosh(x)",
                                 "cross(vec3 x, vec3 y)",
                                 "degrees(radians)",
                                 "determinant(m)",
                                 "distance(p0, p1)",
                                 "dot(x, y)",
                                 "exp(x)",
                                 "exp2(x)",
                                 "faceforward(N, I, Nref)",
                                 "floor(x)",
                                 "fma(a, b, c)",
                                 "fract(x)",
                                 "inverse(m)",
                                 "inversesqrt(x)",
                                 "isinf(x)",
                                 "isnan(x)",
                                 "length(x)",
                                 "log(x)",
                                 "log2(x)",
                                 "max(x, y)",
                                 "min(x, y)",
                                 "mix(x, y, a)",
                                 "mod(x, y)",
                                 "normalize(x)",
                                 "pow(x, y)",
                                 "radians(degrees)",
                                 "reflect(I, N)",
                                 "refract(I, N, eta)",
                                 "round(x)",
                                 "sign(x)",
                                 "sin(x)",
                                 "sinh(x)",
                                 "smoothstep(edge0, edge1, x)",
                                 "sqrt(x)",
                                 "step(edge, x)",
                                 "tan(x)",
                                 "tanh(x)",
                                 "transpose(m)",
                                 "trunc(x)",
                                 "texture(sampler, P)",
                                 "vec2(x, y)",
                                 "vec3(x, y, z)",
                                 "vec4(x, y, z, w)",
                                 "mat2(...)",
                                 "mat3(...)",
                                 "mat4(...)",
                                 "sdf(vec3 p)",
                                 "sdf(vec3 p, float time)"};
const char* const kKeywords[] = {"float",  "vec2",    "vec3",   "vec4", "int",   "uint", "bool", "mat2",  "mat3",
                                 "mat4",   "const",   "return", "for",  "while", "if",   "else", "break", "continue",
                                 "struct", "uniform", "in",     "out",  "inout", "true", "false"};

} // namespace

void GlslEditor::setCompletionFunctions(const QStringList& librarySignatures, const QStringList& fileSignatures) {
    QStringList all;
    for (const char* builtin : kBuiltins) all << builtin;
    for (const char* keyword : kKeywords) all << keyword;
    all << librarySignatures << fileSignatures;
    all.removeDuplicates();
    all.sort();
    if (all == m_completions) return;
    m_completions = all;
    m_apis->clear();
    for (const QString& entry : all) m_apis->add(entry);
    m_apis->prepare();
}

bool GlslEditor::findNext(const QString& text, bool caseSensitive) {
    if (text.isEmpty()) return false;
    return findFirst(text, false, caseSensitive, false, true, true);
}

int GlslEditor::replaceAll(const QString& text, const QString& replacement, bool caseSensitive) {
    if (text.isEmpty()) return 0;
    int count = 0;
    beginUndoAction();
    setCursorPosition(0, 0);
    bool found = findFirst(text, false, caseSensitive, false, false, true, 0, 0);
    while (found) {
        replace(replacement);
        ++count;
        found = QsciScintilla::findNext();
    }
    endUndoAction();
    return count;
}

void GlslEditor::goToLine(int line, int column) {
    int target = std::clamp(line - 1, 0, std::max(lines() - 1, 0));
    setCursorPosition(target, std::max(column - 1, 0));
    ensureLineVisible(target);
    setFocus();
}

void GlslEditor::setDiagnostics(const std::vector<shaders::Diagnostic>& diagnostics, const QString& fileName) {
    markerDeleteAll(m_errorMarker);
    markerDeleteAll(m_warningMarker);
    clearIndicatorRange(0, 0, lines(), 0, m_errorIndicator);
    clearIndicatorRange(0, 0, lines(), 0, m_warningIndicator);
    clearAnnotations();
    m_diagnosticCount = 0;

    QString canonical = QFileInfo(fileName).canonicalFilePath();
    std::map<int, QString> annotationsByLine;
    for (const shaders::Diagnostic& d : diagnostics) {
        QString file = QString::fromStdString(d.file);
        bool mine = file == fileName || (!canonical.isEmpty() && QFileInfo(file).canonicalFilePath() == canonical);
        if (!mine || d.line < 1 || d.line > lines()) continue;
        int line = d.line - 1;
        bool error = d.severity == shaders::Severity::Error;
        markerAdd(line, error ? m_errorMarker : m_warningMarker);
        int length = text(line).length();
        int column = d.column > 0 ? std::min(d.column - 1, std::max(length - 1, 0)) : 0;
        int end = length;
        // Underline the token at the column (identifier characters), else the rest of the line.
        if (d.column > 0) {
            const QString lineText = text(line);
            end = column + 1;
            while (end < lineText.length() && (lineText[end].isLetterOrNumber() || lineText[end] == '_')) ++end;
        }
        fillIndicatorRange(line, column, line, end, error ? m_errorIndicator : m_warningIndicator);
        QString& annotation = annotationsByLine[line];
        if (!annotation.isEmpty()) annotation += "\n";
        annotation += QString(error ? "error: " : "warning: ") + QString::fromStdString(d.message);
        ++m_diagnosticCount;
    }
    for (const auto& [line, annotationText] : annotationsByLine) annotate(line, annotationText, 0);
}

} // namespace sdfwb::widgets
