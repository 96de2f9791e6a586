#pragma once
// QScintilla's C++ lexer taught GLSL 4.30: keywords in set 1, types and built-in functions in set 2.

#include <Qsci/qscilexercpp.h>

namespace sdfwb::widgets {

class GlslLexer : public QsciLexerCPP {
public:
    explicit GlslLexer(QObject* parent = nullptr);
    const char* language() const override { return "GLSL"; }
    const char* keywords(int set) const override;
};

} // namespace sdfwb::widgets
