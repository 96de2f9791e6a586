// The window itself: the opened SDF drawn, a typed error kept beside the last good shape, and a minute of abuse.
// Under a real X server (Xvfb) with real input events; helpers in GuiTestSupport.h.

#include "GuiTestSupport.h"

using namespace sdfwb;
using namespace sdfwb::guitest;

TEST(MainWindow, DrawsTheOpenedSdfInTheViewport) {
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    bool applied = false;
    QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    ASSERT_TRUE(window.openFile(datasetFile("Geometry/Torus.glsl")));
    ASSERT_TRUE(waitFor([&] { return applied; })) << "the SDF never reached the viewport";
    ASSERT_TRUE(waitFor([&] { return window.viewport()->lastFrameMilliseconds() > 0.0; }));

    QImage frame = window.viewport()->grabFramebuffer();
    ASSERT_FALSE(frame.isNull());
    double share = double(foreground(frame, kBackground)) / double(frame.width() * frame.height());
    EXPECT_GT(share, 0.05) << "too little of the viewport is shape";
    EXPECT_LT(share, 0.60) << "the viewport is mostly not background";
    window.grab().save(QDir::temp().filePath("sdfwb-gui-main-window.png"));
}

TEST(MainWindow, TypedErrorShowsADiagnosticAndKeepsTheLastGoodShape) {
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    bool applied = false;
    int diagnosticUpdates = 0;
    QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    QObject::connect(window.document(), &app::SdfDocument::diagnosticsChanged, [&] { ++diagnosticUpdates; });
    ASSERT_TRUE(window.openFile(datasetFile("Geometry/Sphere.glsl")));
    ASSERT_TRUE(waitFor([&] { return applied; }));
    long before = foreground(fullResolutionFrame(window), kBackground);
    ASSERT_GT(before, 1000);

    int updates = diagnosticUpdates;
    QString text = window.editor()->text();
    text.replace("return length(p) - radius;", "return length(p) - radiu;");
    window.editor()->setText(text); // as if typed: goes through the debounce and the worker
    ASSERT_TRUE(waitFor([&] { return diagnosticUpdates > updates; }));
    EXPECT_GE(window.editor()->diagnosticCount(), 1);
    ASSERT_FALSE(window.document()->diagnostics().empty());
    EXPECT_NE(window.document()->diagnostics().front().message.find("radiu"), std::string::npos);
    EXPECT_EQ(window.document()->diagnostics().front().line, 13);

    long after = foreground(fullResolutionFrame(window), kBackground);
    EXPECT_NEAR(double(after), double(before), double(before) * 0.01) << "the last good shape must stay on screen";
    window.grab().save(QDir::temp().filePath("sdfwb-gui-diagnostic.png"));
}

// A minute of abuse: every few hundred milliseconds another SDF, shading mode, a floated and
// re-docked viewport (its GL context is destroyed and re-created), a 1x1 and a 3840x2160 window,
// dialogs opened and cancelled, and keystrokes into the editor all along (valid and broken
// text). Nothing may crash, no GL error may be logged, and the GL objects must not pile up.
TEST(Abuse, AMinuteOfSwitchingDockingResizingDialogsAndTyping) {
    std::mutex mutex;
    std::vector<std::string> glErrors;
    const int sink = log::addSink([&](log::Level level, std::string_view category, std::string_view message) {
        if (level != log::Level::Error || category != "gl") return;
        std::lock_guard lock(mutex);
        glErrors.emplace_back(message);
    });
    app::MainWindow window;
    window.files()->setPrompt([](const QString&) { return app::FileController::Answer::No; }); // discard typed edits
    window.resize(1000, 700);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    auto* dock = window.findChild<QDockWidget*>("ViewportDock");
    ASSERT_NE(dock, nullptr);
    const char* files[] = {"Geometry/Box.glsl", "Animal/Cat.glsl", "Fractal/Mandelbulb.glsl", "Geometry/Capsule.glsl",
                           "Geometry/Torus.glsl"};
    const shaders::ShadingMode modes[] = {shaders::ShadingMode::Gooch, shaders::ShadingMode::Matcap,
                                          shaders::ShadingMode::Curvature, shaders::ShadingMode::Steps,
                                          shaders::ShadingMode::Normals};
    const char* keystrokes[] = {" ", "+", "0", ".", "1", ")", ";", "\n", "x", "(", "/", "*"};
    int actions = 0, typed = 0, docked = 0, dialogs = 0;
    auto settle = [] {
        for (int k = 0; k < 5; ++k) QApplication::processEvents(QEventLoop::AllEvents, 20);
    };
    auto act = [&](int i) {
        // Keystrokes at the end of the text, every step (broken text is part of the abuse).
        for (int k = 0; k < 3; ++k) {
            window.editor()->SendScintilla(QsciScintilla::SCI_DOCUMENTEND);
            window.editor()->insert(keystrokes[(i * 3 + k) % 12]);
            window.editor()->SendScintilla(QsciScintilla::SCI_DOCUMENTEND);
            ++typed;
        }
        switch (i % 6) {
        case 0:
            window.openFile(datasetFile(files[(i / 6) % 5]));
            break;
        case 1:
            window.setShadingMode(modes[(i / 6) % 5]);
            break;
        case 2:
            dock->setFloating(true);
            settle();
            dock->resize(i % 12 == 2 ? QSize(3840, 2160) : QSize(1, 1));
            settle();
            dock->setFloating(false);
            ++docked;
            break;
        case 3:
            window.resize(i % 12 == 3 ? QSize(1, 1) : QSize(3840, 2160));
            break;
        case 4: {
            // As the menu does: the controllers create their dialogs on first use (modeless).
            QDialog* dialog = nullptr;
            if (i % 12 == 4) {
                window.sampling()->showDialog();
                dialog = window.sampling()->dialog();
            } else {
                window.exports()->showScreenshotDialog();
                dialog = window.exports()->screenshotDialog();
            }
            ASSERT_NE(dialog, nullptr);
            settle();
            dialog->reject();
            ++dialogs;
            break;
        }
        case 5:
            window.resize(1000, 700);
            break;
        }
        window.viewport()->update();
        settle();
        ++actions;
    };
    for (int i = 0; i < 12; ++i) act(i); // warm-up: every action twice, every variant cached once
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    const long baseline = renderer::liveGlObjects();
    QElapsedTimer clock;
    clock.start();
    // A minute of it, and at least every action 12 times over (72): a slower build (ASan) runs longer
    // rather than checking less.
    for (int i = 12; clock.elapsed() < 60000 || i < 12 + 72; ++i) act(i);
    window.resize(1000, 700);
    if (dock->isFloating()) dock->setFloating(false);
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    window.setShadingMode(shaders::ShadingMode::Normals);
    const QImage last = frameOf(window);
    log::removeSink(sink);
    std::printf("abuse: %d actions (%d keystrokes, %d float/re-docks, %d dialogs) in %.0f s; GL objects %ld -> %ld\n", actions,
                typed, docked, dialogs, clock.elapsed() / 1000.0, baseline, renderer::liveGlObjects());
    EXPECT_TRUE(glErrors.empty()) << glErrors.size() << " GL errors, first: " << glErrors.front();
    EXPECT_LE(renderer::liveGlObjects(), baseline + 8) << "GL objects pile up";
    EXPECT_GT(foreground(last, kBackground), 1000) << "the torus is still drawn";
    auto sockets = sdfwb::testing::networkSockets("self");
    EXPECT_TRUE(sockets.empty()) << "the workbench opened a network socket: " << sockets.front();
    window.close();
}
