// Cold edits: for every dataset SDF, the time from the keystroke that makes it valid to its first
// visible frame in the workbench (and to its first full-resolution frame), with Mesa's shader cache off (every program is
// compiled and, on llvmpipe, code-generated at its first draw). The editor holds the SDF with one stray character at its end (a
// compile error); the keystroke deletes it. Measured in the real window: the editor's debounce, include resolution and glslang
// off the UI thread, the GL compile and link, the timing frame that sizes the resolution (the driver's code generation happens
// there), then the first frame: at full resolution, or for an SDF whose full frame would take longer than the 33 ms frame budget
// the probe's second measurement at 15 % of the side, with the full-resolution frame after it. The reference in the same run is
// the editor's debounce itself, which every edit waits for by design.
//
//   scripts/with-display build/bench/bench_cold_edit [NAME|FILE ...]   (dataset names or .glsl files; default: every
//   dataset SDF)

#include <gui/GuiMain.h>
#include <gui/MainWindow.h>
#include <gui/SdfDocument.h>
#include <widgets/GlslEditor.h>
#include <widgets/ViewportWidget.h>

#include <core/Paths.h>
#include <dataset/Catalogue.h>
#include <renderer/FrameScaler.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QStandardPaths>

#include <Qsci/qsciscintillabase.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace sdfwb;

namespace {

// Runs the event loop until `done` or `limit` ms; returns whether `done` happened.
template <class F> bool waitFor(F done, int limit) {
    QElapsedTimer timer;
    timer.start();
    while (!done()) {
        if (timer.elapsed() > limit) return false;
        QApplication::processEvents(QEventLoop::AllEvents, 1);
    }
    return true;
}

} // namespace

int main(int argc, char** argv) {
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1); // cold: before any GL context exists
    QStandardPaths::setTestModeEnabled(true);
    app::setDefaultSurfaceFormat();
    QApplication application(argc, argv);
    std::vector<std::string> names(argv + 1, argv + argc);

    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    widgets::ViewportWidget* viewport = window.viewport();
    // Times from the keystroke, taken as the frames are drawn (a new SDF's probe and its first
    // frame come in the same paint). Negative: not drawn yet.
    QElapsedTimer timer;
    int frames = 0;
    double probeAt = -1.0, firstAt = -1.0, fullAt = -1.0;
    float firstScale = 1.0f;
    QObject::connect(viewport, &widgets::ViewportWidget::frameRendered, [&](double, float scale) {
        ++frames;
        const double now = timer.isValid() ? timer.nsecsElapsed() / 1e6 : 0.0;
        if (scale == renderer::FrameScaler::kTimingScale) {
            if (probeAt < 0.0) probeAt = now;
            return;
        }
        if (probeAt < 0.0) return; // a frame of the text before the keystroke
        if (firstAt < 0.0) {
            firstAt = now;
            firstScale = scale;
        }
        if (scale >= 1.0f && fullAt < 0.0) fullAt = now;
    });
    bool diagnosed = false;
    QObject::connect(window.document(), &app::SdfDocument::diagnosticsChanged, [&] { diagnosed = true; });
    if (!waitFor([&] { return frames > 0; }, 60000)) {
        std::fprintf(stderr, "bench_cold_edit: the viewport drew no frame\n");
        return 1;
    }

    std::printf("cold edit to first full frame, every dataset SDF (Mesa shader cache off), window 1200x700 (viewport %dx%d); "
                "debounce %d ms\n\n",
                viewport->width(), viewport->height(), window.document()->debounceMilliseconds());
    std::printf(
        "| SDF | keystroke to timing frame (ms) | keystroke to first frame (ms) | its scale | keystroke to full-resolution frame "
        "(ms) |\n|---|---|---|---|---|\n");
    const dataset::Catalogue catalogue = dataset::Catalogue::scan(paths::datasetRoot());
    std::vector<std::pair<double, std::string>> results; // keystroke to first frame
    std::vector<double> fullResults;
    // What to time: (name, file); an argument that names a file is timed as it is (foreign code).
    std::vector<std::pair<std::string, std::filesystem::path>> targets;
    for (const dataset::Entry& entry : catalogue.entries())
        if (names.empty() || std::find(names.begin(), names.end(), entry.metadata.name) != names.end())
            targets.emplace_back(entry.metadata.name, entry.path);
    for (const std::string& name : names)
        if (std::filesystem::is_regular_file(name)) targets.emplace_back(std::filesystem::path(name).filename().string(), name);
    for (const auto& [name, path] : targets) {
        // Opened as a user opens it (its includes resolve from its folder), then a line the
        // driver has never seen and a stray character: a compile error. The keystroke deletes it,
        // and the text that becomes valid is new, so its program is compiled cold.
        bool applied = false;
        auto connection = QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
        if (!window.openFile(QString::fromStdString(path.string())) || !waitFor([&] { return applied; }, 60000)) {
            std::printf("| %s | does not open | | | |\n", name.c_str());
            QObject::disconnect(connection);
            continue;
        }
        QObject::disconnect(connection);
        diagnosed = false;
        window.editor()->append(QString("\n// cold edit %1\nx").arg(results.size()));
        waitFor([&] { return diagnosed; }, 20000);
        waitFor([] { return false; }, 150); // let the window settle
        window.editor()->setCursorPosition(window.editor()->lines() - 1,
                                           window.editor()->text(window.editor()->lines() - 1).size());
        probeAt = firstAt = fullAt = -1.0;
        timer.start();
        window.editor()->SendScintilla(QsciScintillaBase::SCI_DELETEBACK); // the keystroke
        if (!waitFor([&] { return fullAt >= 0.0; }, 60000)) {
            std::printf("| %s | no full frame within 60 s | | | |\n", name.c_str());
            continue;
        }
        const double probe = probeAt, first = firstAt, full = fullAt;
        std::printf("| %s | %.0f | %.0f | %.0f %% | %.0f |\n", name.c_str(), probe, first, firstScale * 100.0, full);
        std::fflush(stdout);
        results.emplace_back(first, name);
        fullResults.push_back(full);
    }
    if (!results.empty()) {
        std::sort(results.begin(), results.end());
        std::sort(fullResults.begin(), fullResults.end());
        std::printf("\n%zu SDFs: keystroke to first frame median %.0f ms, worst %.0f ms (%s), %zu over 300 ms; keystroke to "
                    "full-resolution frame median %.0f ms, worst %.0f ms\n",
                    results.size(), results[results.size() / 2].first, results.back().first, results.back().second.c_str(),
                    std::size_t(std::count_if(results.begin(), results.end(), [](const auto& r) { return r.first > 300.0; })),
                    fullResults[fullResults.size() / 2], fullResults.back());
    }
    window.editor()->setModified(false);
    return 0;
}
