// Editor latency: time from the last keystroke to diagnostics on screen for a 700-line SDF,
// including the debounce, with include resolution and glslang off the UI thread. Reported next to
// the debounce itself and to a direct in-thread glslang check of the same text (the reference).
//
//   scripts/with-display build/bench/bench_editor

#include <gui/GuiMain.h>
#include <gui/MainWindow.h>
#include <gui/SdfDocument.h>
#include <widgets/GlslEditor.h>

#include <core/Paths.h>
#include <shaders/GlslChecker.h>
#include <shaders/TracerComposer.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QStandardPaths>
#include <QThread>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

using namespace sdfwb;

namespace {

// 700 lines: 100 small helper functions of 6 lines each, then an sdf() that uses them.
std::string longSdf() {
    std::string text = "// generated: 700 lines\n";
    for (int i = 0; i < 100; ++i) {
        std::string n = std::to_string(i);
        text += "float part" + n + "(vec3 p) {\n";
        text += "    vec3 q = p - vec3(" + std::to_string(0.01 * i) + ", 0.0, 0.0);\n";
        text += "    float r = 0.1 + 0.001 * " + n + ".0;\n";
        text += "    return length(q) - r;\n";
        text += "}\n\n";
    }
    text += "float sdf(vec3 p) {\n    float d = part0(p);\n";
    for (int i = 1; i < 90; ++i) text += "    d = min(d, part" + std::to_string(i) + "(p));\n";
    text += "    return d;\n}\n";
    return text;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

} // namespace

int main(int argc, char** argv) {
    QStandardPaths::setTestModeEnabled(true);
    app::setDefaultSurfaceFormat();
    QApplication application(argc, argv);
    std::string text = longSdf();
    int lines = int(std::count(text.begin(), text.end(), '\n'));

    // Reference: the same check, directly on this thread.
    std::vector<double> direct;
    for (int i = 0; i < 5; ++i) {
        QElapsedTimer timer;
        timer.start();
        auto prepared = shaders::prepareSdf(text, "<bench>", {}, {});
        auto composed = shaders::composeTracer(prepared, {});
        (void)shaders::checkWithGlslang(*composed);
        direct.push_back(timer.nsecsElapsed() / 1e6);
    }

    app::MainWindow window;
    window.show();
    bool updated = false;
    QObject::connect(window.document(), &app::SdfDocument::diagnosticsChanged, [&] { updated = true; });
    window.editor()->setText(QString::fromStdString(text));
    QElapsedTimer settle;
    settle.start();
    while (!updated && settle.elapsed() < 20000) QApplication::processEvents(QEventLoop::AllEvents, 10);

    std::vector<double> latencies;
    for (int i = 0; i < 15; ++i) {
        updated = false;
        // A keystroke: one character typed inside sdf(), alternating error / fix.
        window.editor()->setCursorPosition(lines - 3, 4);
        window.editor()->insert(i % 2 ? " " : "x");
        QElapsedTimer timer;
        timer.start();
        while (!updated) {
            QApplication::processEvents(QEventLoop::AllEvents, 1);
            if (timer.elapsed() > 20000) break;
        }
        QApplication::processEvents(); // the frame that shows the diagnostics
        latencies.push_back(timer.nsecsElapsed() / 1e6);
        QThread::msleep(50);
    }
    std::printf("editor latency, %d-line SDF (%s)\n\n", lines, window.document()->path().isEmpty() ? "unsaved text" : "file");
    std::printf("| measure | ms |\n|---|---|\n");
    std::printf("| debounce (fixed) | %d |\n", window.document()->debounceMilliseconds());
    std::printf("| include resolution + glslang, in-thread reference (median of 5) | %.1f |\n", median(direct));
    std::printf("| keystroke to diagnostics on screen (median of 15) | %.1f |\n", median(latencies));
    std::printf("| keystroke to diagnostics on screen (worst of 15) | %.1f |\n",
                *std::max_element(latencies.begin(), latencies.end()));
    window.editor()->setModified(false);
    return 0;
}
