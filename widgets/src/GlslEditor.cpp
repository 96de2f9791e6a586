#include <widgets/GlslEditor.h>

#include "GlslLexer.h"

#include <QColor>
#include <QFileInfo>
#include <QFontMetrics>

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
