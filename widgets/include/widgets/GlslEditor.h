#pragma once
// The GLSL editor: QScintilla with GLSL highlighting, line numbers, folding and brace matching,
// and diagnostics drawn as margin markers, column underlines and inline annotations.
// UI thread only.

#include <shaders/Diagnostic.h>

#include <Qsci/qsciscintilla.h>

#include <vector>

namespace sdfwb::widgets {

class GlslLexer;

class GlslEditor : public QsciScintilla {
    Q_OBJECT
public:
    explicit GlslEditor(QWidget* parent = nullptr);

    // Shows the diagnostics that belong to `fileName` (others are ignored); clears old ones.
    void setDiagnostics(const std::vector<shaders::Diagnostic>& diagnostics, const QString& fileName);
    int diagnosticCount() const { return m_diagnosticCount; }

private:
    GlslLexer* m_lexer = nullptr;
    int m_errorMarker = -1;
    int m_warningMarker = -1;
    int m_errorIndicator = -1;
    int m_warningIndicator = -1;
    int m_diagnosticCount = 0;
};

} // namespace sdfwb::widgets
