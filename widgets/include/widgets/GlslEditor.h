#pragma once
// The GLSL editor: QScintilla with GLSL highlighting, line numbers, folding and brace matching,
// and diagnostics drawn as margin markers, column underlines and inline annotations.
// UI thread only.

#include <shaders/Diagnostic.h>

#include <Qsci/qsciscintilla.h>

#include <vector>

class QsciAPIs;

namespace sdfwb::widgets {

class GlslLexer;

class GlslEditor : public QsciScintilla {
    Q_OBJECT
public:
    explicit GlslEditor(QWidget* parent = nullptr);

    // Autocompletion and call tips: GLSL built-ins always; library and file functions as given
    // ("name(type a, type b)").
    void setCompletionFunctions(const QStringList& librarySignatures, const QStringList& fileSignatures);

    const QStringList& completionEntries() const { return m_completions; }

    // Selects the next match of `text` after the cursor (wrapping); false when there is none.
    bool findNext(const QString& text, bool caseSensitive = false);
    // Replaces every match; returns how many.
    int replaceAll(const QString& text, const QString& replacement, bool caseSensitive = false);
    void goToLine(int line, int column = 1);

    // Shows the diagnostics that belong to `fileName` (others are ignored); clears old ones.
    void setDiagnostics(const std::vector<shaders::Diagnostic>& diagnostics, const QString& fileName);
    int diagnosticCount() const { return m_diagnosticCount; }

private:
    GlslLexer* m_lexer = nullptr;
    QsciAPIs* m_apis = nullptr;
    QStringList m_completions;
    int m_errorMarker = -1;
    int m_warningMarker = -1;
    int m_errorIndicator = -1;
    int m_warningIndicator = -1;
    int m_diagnosticCount = 0;
};

} // namespace sdfwb::widgets
