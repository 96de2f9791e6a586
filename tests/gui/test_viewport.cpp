// The viewport: shading modes, ambient occlusion, moving then refining, the march and cone choices at rest, timing frames, the
// camera panel, the precision floor, a stalling SDF capped then reverted (jobs follow), time. Under a real X server (Xvfb) with
// real input events; helpers in GuiTestSupport.h.

#include "GuiTestSupport.h"

using namespace sdfwb;
using namespace sdfwb::guitest;

TEST(Viewport, EveryShadingModeDrawsSomethingDifferent) {
    app::MainWindow window;
    window.resize(1000, 600);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    std::vector<QImage> frames;
    for (shaders::ShadingMode mode : {shaders::ShadingMode::Normals, shaders::ShadingMode::Gooch, shaders::ShadingMode::Matcap,
                                      shaders::ShadingMode::Curvature, shaders::ShadingMode::Steps}) {
        window.setShadingMode(mode);
        frames.push_back(frameOf(window));
        frames.back().save(QDir::temp().filePath(QString("sdfwb-gui-mode-%1.png").arg(shaders::shadingModeName(mode))));
    }
    for (std::size_t i = 0; i < frames.size(); ++i)
        for (std::size_t j = i + 1; j < frames.size(); ++j)
            EXPECT_GT(meanDifference(frames[i], frames[j]), 1.0) << i << " vs " << j;
}

TEST(Viewport, AmbientOcclusionDarkensCreases) {
    // A ball resting on a plate: the crease where they meet must get darker with AO on.
    QString path = QDir::temp().filePath("sdfwb-gui-ball-on-plate.glsl");
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("float sdf(vec3 p) {\n"
               "    vec3 q = abs(p - vec3(0.0, -0.5, 0.0)) - vec3(0.9, 0.05, 0.9);\n"
               "    float plate = length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);\n"
               "    return min(plate, length(p - vec3(0.0, -0.05, 0.0)) - 0.4);\n}\n");
    file.close();
    app::MainWindow window;
    window.show();
    ASSERT_TRUE(openFileAndWait(window, path));
    // The same view for both frames (not a camera restored from an earlier test's session), and
    // full-resolution frames only: a new SDF's first frame is a 5 % probe, and under ASan the frame
    // after the probe could be one too (the CI run of 2026-11-30 compared a probe with a full frame).
    window.viewport()->resetCamera();
    window.setShadingMode(shaders::ShadingMode::Gooch);
    window.setAmbientOcclusion(false);
    QImage plain = fullResolutionFrame(window);
    window.setAmbientOcclusion(true);
    QImage occluded = fullResolutionFrame(window);
    occluded.save(QDir::temp().filePath("sdfwb-gui-ao.png"));
    EXPECT_GT(meanDifference(plain, occluded), 0.2);
    // Occlusion only darkens (no pixel gets brighter), and it darkens where the ball meets the plate
    // far more than in the open: the strongest 1 % of the drops is over 5x the median drop.
    ASSERT_EQ(plain.size(), occluded.size());
    long brighter = 0;
    std::vector<int> drops;
    for (int y = 0; y < plain.height(); ++y)
        for (int x = 0; x < plain.width(); ++x) {
            const int before = qGray(plain.pixel(x, y)), after = qGray(occluded.pixel(x, y));
            if (after > before + 2) ++brighter;
            if (before != after) drops.push_back(before - after);
        }
    ASSERT_GT(drops.size(), std::size_t(1000)) << "AO changed almost nothing";
    EXPECT_LE(brighter, long(drops.size() / 1000)) << "AO made pixels brighter";
    std::sort(drops.begin(), drops.end());
    const int median = drops[drops.size() / 2], strong = drops[drops.size() * 99 / 100];
    EXPECT_GT(median, 0) << "the typical change is not darker";
    EXPECT_GT(strong, 5 * median) << "darkening is uniform, not in the crease (median " << median << ", 99th " << strong << ")";
    window.setAmbientOcclusion(false);
}

TEST(Viewport, MovingRendersCheaplyThenRefines) {
    app::MainWindow window;
    window.resize(1000, 600);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    widgets::ViewportWidget* viewport = window.viewport();
    // openAndWait may return on the new SDF's timing frame; the frame it sizes comes next, at the
    // budget in force then. Drawn at the default budget first, so that one is full resolution.
    viewport->grabFramebuffer();
    viewport->setFrameBudget(0.5); // unreachable on purpose: the scale must drop while moving
    ASSERT_TRUE(waitFor([&] { return !viewport->isInteracting(); }, 3000));
    viewport->grabFramebuffer(); // a full-resolution frame: the scale while moving starts from its cost
    ASSERT_EQ(viewport->lastFrameScale(), 1.0f);
    values::Camera before = viewport->camera();
    QPoint start(300, 300);
    QMouseEvent press(QEvent::MouseButtonPress, start, viewport->mapToGlobal(start), Qt::LeftButton, Qt::LeftButton,
                      Qt::NoModifier);
    QApplication::sendEvent(viewport, &press);
    for (int i = 1; i <= 5; ++i) {
        QPoint at = start + QPoint(10 * i, 0);
        QMouseEvent move(QEvent::MouseMove, at, viewport->mapToGlobal(at), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(viewport, &move);
        viewport->grabFramebuffer();
    }
    EXPECT_TRUE(viewport->isInteracting());
    EXPECT_LT(viewport->lastFrameScale(), 1.0f);
    EXPECT_NE(viewport->camera().position.x, before.position.x) << "left drag orbits";
    EXPECT_NEAR(window.cameraPanel()->camera().position.x, viewport->camera().position.x, 1e-3) << "the camera panel follows";
    ASSERT_TRUE(waitFor([&] { return !viewport->isInteracting(); }, 3000));
    viewport->grabFramebuffer();
    EXPECT_EQ(viewport->lastFrameScale(), 1.0f) << "a full-resolution frame follows when still";
}

// The same picture within 0.1 % of the pixels, with the shape on at least `minimumShare` of it.
void expectSamePicture(const QImage& before, const QImage& after, long minimumShare) {
    EXPECT_LT(changedPixels(before, after), long(before.width()) * before.height() / 1000);
    EXPECT_GT(foreground(after, kBackground), long(after.width()) * after.height() / minimumShare);
}

// A long SDF that is cheap per evaluation opens with the fused march (the quickest code generation
// after an edit); a while after its full frame at rest the viewport tries the separate march and
// keeps whichever drew the faster full frame, and the picture stays the same. The frame times the
// choice is made from are injected (ViewportWidget::setSettleTiming), so the outcome follows them
// and not this machine's load; both outcomes are checked.
TEST(Viewport, AtRestALongSdfKeepsTheFasterOfTheFusedAndTheSeparateMarch) {
    for (const bool separateFaster : {true, false}) {
        app::MainWindow window;
        window.resize(1000, 600);
        widgets::ViewportWidget* viewport = window.viewport();
        // The cone pass always costs more here, so only the march is traded.
        viewport->setSettleTiming([separateFaster](bool fused, bool cones, bool compute, double) {
            return (fused ? 60.0 : separateFaster ? 30.0 : 90.0) + (cones ? 20.0 : 0.0) + (compute ? 10.0 : 0.0);
        });
        window.show();
        ASSERT_TRUE(openAndWait(window, "Manufactured/Mug.glsl"));
        EXPECT_TRUE(viewport->fusedMarch()) << "a long SDF opens with the fused march";
        const QImage fused = fullResolutionFrame(window);
        ASSERT_TRUE(waitFor([&] { return viewport->marchSettled(); }, 30000)) << "never settled at rest";
        EXPECT_EQ(viewport->fusedMarch(), !separateFaster)
            << (separateFaster ? "the faster separate march was not kept" : "the slower separate march was kept");
        EXPECT_FALSE(viewport->conePass()) << "the slower cone pass was kept";
        EXPECT_FALSE(viewport->computeTracer()) << "the slower compute tracer was kept";
        EXPECT_FALSE(viewport->isInteracting());
        expectSamePicture(fused, fullResolutionFrame(window), 50);
    }
}

// An SDF that is dear per evaluation (the trefoil knot solves cubics) opens without the cone
// pass; a while after its full frame at rest the viewport tries it and keeps it when the full
// frame got faster (injected timings: both outcomes), and the picture stays the same.
TEST(Viewport, AtRestTheConePassIsKeptOnlyWhenItMakesFramesFaster) {
    for (const bool conesFaster : {false, true}) {
        app::MainWindow window;
        window.resize(1000, 600);
        widgets::ViewportWidget* viewport = window.viewport();
        viewport->setSettleTiming([conesFaster](bool, bool cones, bool compute, double) {
            return compute ? 500.0 : cones ? (conesFaster ? 50.0 : 150.0) : 100.0;
        });
        window.show();
        ASSERT_TRUE(openAndWait(window, "Geometry/TrefoilKnot.glsl"));
        EXPECT_FALSE(viewport->conePass()) << "a new SDF opens without the cone pass";
        const QImage without = fullResolutionFrame(window);
        ASSERT_TRUE(waitFor([&] { return viewport->marchSettled(); }, 30000)) << "never settled at rest";
        EXPECT_EQ(viewport->conePass(), conesFaster)
            << (conesFaster ? "the faster cone pass was dropped" : "the slower cone pass was kept");
        EXPECT_FALSE(viewport->isInteracting());
        expectSamePicture(without, fullResolutionFrame(window), 20);
        if (!conesFaster) continue;
        // View > Cone pass forces it either way.
        auto* off = window.findChild<QAction*>("cones_off");
        auto* on = window.findChild<QAction*>("cones_on");
        ASSERT_TRUE(off && on);
        off->trigger();
        EXPECT_FALSE(viewport->conePass());
        expectSamePicture(without, fullResolutionFrame(window), 20);
        on->trigger();
        EXPECT_TRUE(viewport->conePass());
        // Automatic again: an edit of the same file keeps the pass from its first frame on.
        window.findChild<QAction*>("cones_auto")->trigger();
        ASSERT_TRUE(waitFor([&] { return viewport->marchSettled() && viewport->conePass(); }, 30000));
        bool applied = false;
        QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
        window.editor()->setText(window.editor()->text() + "\n// edited\n"); // as if typed
        ASSERT_TRUE(waitFor([&] { return applied; }));
        EXPECT_TRUE(viewport->conePass()) << "the edit dropped the cone pass its file had kept";
    }
}

// The compute tracer is tried last at rest and kept when its full frame is faster (injected
// timings: both outcomes); it draws the same picture; View > Tracer forces either tracer.
TEST(Viewport, AtRestTheComputeTracerIsKeptOnlyWhenItMakesFramesFaster) {
    for (const bool computeFaster : {false, true}) {
        app::MainWindow window;
        window.resize(1000, 600);
        widgets::ViewportWidget* viewport = window.viewport();
        viewport->setSettleTiming([computeFaster](bool, bool cones, bool compute, double) {
            return compute ? (computeFaster ? 50.0 : 150.0) : cones ? 200.0 : 100.0;
        });
        window.show();
        ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
        EXPECT_FALSE(viewport->computeTracer()) << "a new SDF opens with the fragment tracer";
        const QImage fragment = fullResolutionFrame(window);
        ASSERT_TRUE(waitFor([&] { return viewport->marchSettled(); }, 30000)) << "never settled at rest";
        EXPECT_EQ(viewport->computeTracer(), computeFaster)
            << (computeFaster ? "the faster compute tracer was dropped" : "the slower compute tracer was kept");
        EXPECT_FALSE(viewport->conePass()) << "the slower cone pass was kept";
        expectSamePicture(fragment, fullResolutionFrame(window), 20);
        if (!computeFaster) continue;
        auto* forceFragment = window.findChild<QAction*>("tracer_fragment");
        auto* forceCompute = window.findChild<QAction*>("tracer_compute");
        ASSERT_TRUE(forceFragment && forceCompute);
        forceFragment->trigger();
        EXPECT_FALSE(viewport->computeTracer());
        forceCompute->trigger();
        EXPECT_TRUE(viewport->computeTracer());
        expectSamePicture(fragment, fullResolutionFrame(window), 20);
        // SDFWB_SCREENSHOT_DIR keeps the window as the compute tracer draws it (to look at).
        if (const char* folder = std::getenv("SDFWB_SCREENSHOT_DIR"))
            window.grab().save(QDir(folder).filePath("compute_tracer.png"));
    }
}

// Frames timed by queries read at later paints (a GPU's default; forced here on llvmpipe): the
// viewport draws without glFinish, its frame times come from the queries, and the march still
// settles at rest from the full frame's time once its query is back.
TEST(Viewport, QueryTimedFramesNeedNoGlFinishAndStillSettle) {
    app::MainWindow window;
    window.resize(1000, 600);
    widgets::ViewportWidget* viewport = window.viewport();
    viewport->setFrameTiming(widgets::ViewportWidget::FrameTiming::Query);
    std::vector<double> settleTimes;
    viewport->setSettleTiming([&settleTimes](bool, bool cones, bool compute, double measured) {
        settleTimes.push_back(measured);
        return cones || compute ? 200.0 : 100.0;
    });
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    const QImage picture = fullResolutionFrame(window);
    ASSERT_TRUE(waitFor([&] { return viewport->marchSettled(); }, 30000)) << "never settled at rest";
    EXPECT_FALSE(viewport->computeTracer());
    EXPECT_FALSE(viewport->conePass());
    for (int paint = 0; paint < 5; ++paint) viewport->repaint();
    EXPECT_EQ(viewport->finishedFrames(), 0u) << "a paint waited for the GPU";
    EXPECT_EQ(viewport->frameTiming(), widgets::ViewportWidget::FrameTiming::Query);
    EXPECT_GE(viewport->lastFrameMilliseconds(), 0.0);
    ASSERT_FALSE(settleTimes.empty()) << "no full frame's query came back";
    for (double time : settleTimes) EXPECT_GE(time, 0.0);
    expectSamePicture(picture, fullResolutionFrame(window), 20);
}

// A new SDF whose full frame would take longer than the frame budget shows its last timing frame
// (15 % of the side, the same paint) as its first frame, then the full-resolution frame; the
// timing frame's picture is the new shape, read from the viewport's framebuffer as it is drawn.
TEST(Viewport, ASlowSdfShowsItsTimingFrameAsItsFirstFrameThenTheFullOne) {
    app::MainWindow window;
    window.resize(1000, 600);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Sphere.glsl"));
    (void)fullResolutionFrame(window);
    widgets::ViewportWidget* viewport = window.viewport();
    viewport->setFrameBudget(0.01); // every SDF is slow against it
    std::vector<float> scales;
    long shapePixels = -1;
    QObject::connect(viewport, &widgets::ViewportWidget::frameRendered, [&](double, float scale) {
        scales.push_back(scale);
        if (scale != 3.0f * renderer::FrameScaler::kTimingScale || shapePixels >= 0) return;
        // In the paint: the viewport's framebuffer is bound, the frame about to be shown.
        const qreal ratio = viewport->devicePixelRatioF();
        const int width = int(std::lround(viewport->width() * ratio)), height = int(std::lround(viewport->height() * ratio));
        std::vector<std::uint8_t> rgba(std::size_t(width) * height * 4);
        QOpenGLContext::currentContext()->functions()->glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        shapePixels = 0;
        for (std::size_t i = 0; i < rgba.size(); i += 4)
            shapePixels += std::abs(rgba[i] - kBackground.red()) + std::abs(rgba[i + 1] - kBackground.green()) +
                               std::abs(rgba[i + 2] - kBackground.blue()) >
                           30;
    });
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    ASSERT_TRUE(waitFor([&] { return !scales.empty() && scales.back() == 1.0f; })) << "no full-resolution frame";
    // The timing frame (5 %), the larger timing frame shown as the first frame (15 %), the full frame (after
    // any repaint of the sphere before the torus arrived).
    const auto timing = std::find(scales.begin(), scales.end(), renderer::FrameScaler::kTimingScale);
    ASSERT_GE(std::distance(timing, scales.end()), 3) << "no timing frame, or nothing after it";
    EXPECT_EQ(timing[1], 3.0f * renderer::FrameScaler::kTimingScale);
    EXPECT_EQ(timing[2], 1.0f);
    const long pixels =
        long(viewport->width() * viewport->height() * viewport->devicePixelRatioF() * viewport->devicePixelRatioF());
    EXPECT_GT(shapePixels, pixels / 20) << "the first frame does not show the torus";
    viewport->setFrameBudget(33.0);
}

TEST(Viewport, CameraPanelMovesTheCameraAndTheSessionKeepsIt) {
    values::Camera edited;
    {
        app::MainWindow window;
        window.show();
        ASSERT_TRUE(openAndWait(window, "Geometry/Box.glsl"));
        QImage before = frameOf(window);
        window.cameraPanel()->findChild<QDoubleSpinBox*>("position_y")->setValue(-2.5);
        window.cameraPanel()->findChild<QDoubleSpinBox*>("fov")->setValue(30.0);
        edited = window.viewport()->camera();
        EXPECT_FLOAT_EQ(edited.position.y, -2.5f);
        EXPECT_FLOAT_EQ(edited.fovYDegrees, 30.0f);
        EXPECT_GT(meanDifference(before, frameOf(window)), 1.0);
        window.close(); // saves the session
    }
    app::MainWindow again;
    EXPECT_FLOAT_EQ(again.viewport()->camera().position.y, -2.5f);
    EXPECT_FLOAT_EQ(again.viewport()->camera().fovYDegrees, 30.0f);
    again.viewport()->resetCamera();
    EXPECT_FLOAT_EQ(again.cameraPanel()->camera().position.y, values::Camera{}.position.y);
    again.close();
}

TEST(Viewport, StatusBarShowsTheFloat32PrecisionFloor) {
    app::MainWindow window;
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Sphere.glsl"));
    auto* label = window.findChild<QLabel*>("precision");
    ASSERT_NE(label, nullptr);
    window.viewport()->resetCamera();
    EXPECT_TRUE(label->text().startsWith("float32 floor")) << label->text().toStdString();
    // 1e4 away with a 0.001 degree lens: positions are known to ~1e-3, far coarser than a pixel.
    values::Camera far;
    far.position = {0.0f, 0.0f, 1e4f};
    far.fovYDegrees = 0.001f;
    far.farPlane = 2e4f;
    window.viewport()->setCamera(far); // the next frame updates the readout
    EXPECT_TRUE(waitFor([&] { return label->text().contains("below float32 precision"); }, 10000)) << label->text().toStdString();
    // SDFWB_SCREENSHOT_DIR=folder keeps a picture of the window to look at.
    if (const char* folder = std::getenv("SDFWB_SCREENSHOT_DIR"))
        window.grab().save(QDir(folder).filePath("precision_floor.png"));
    window.viewport()->resetCamera();
    EXPECT_TRUE(waitFor([&] { return !label->text().contains("below"); }, 10000)) << label->text().toStdString();
    window.close();
}

// A shader with a long loop (llvmpipe cuts loops near 65 000 iterations, so this one costs
// ~80 us a pixel: over a minute for a full frame) must not freeze the window.
const char* const kRunawayLoop = "float sdf(vec3 p) { float d = 0.0; for (int i = 0; i < 100000000; ++i) d += sin(float(i)) * "
                                 "1e-9; return length(p) - 0.5 + d; }\n";

TEST(Viewport, SlowShaderIsCappedThenRevertedNeverFreezesTheWindow) {
    QTemporaryDir folder;
    const QString loop = folder.filePath("loop.glsl");
    {
        QFile file(loop);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(kRunawayLoop);
    }
    app::MainWindow window;
    window.resize(900, 650);
    window.show();
    QStringList warnings;
    QObject::connect(window.viewport(), &widgets::ViewportWidget::performanceWarning, [&](const QString& m) { warnings << m; });
    ASSERT_TRUE(openAndWait(window, "Geometry/Sphere.glsl"));
    const QImage sphere = frameOf(window);

    // Limit 1.5 s: the timing frame (5 % resolution) predicts a minute-long frame; the cap keeps
    // every frame near the limit.
    ASSERT_TRUE(window.openFile(loop));
    ASSERT_TRUE(waitFor([&] { return !warnings.isEmpty(); }, 60000)) << "no warning for a minute-long frame";
    EXPECT_TRUE(warnings.back().contains("resolution")) << warnings.back().toStdString();
    EXPECT_LT(window.viewport()->resolutionCap(), 0.5f);
    QElapsedTimer timer;
    timer.start();
    frameOf(window);
    EXPECT_LT(timer.elapsed(), 4000) << "a capped frame must stay near the 1.5 s limit";

    // Limit 20 ms: even the probe is too slow, so the last good SDF (the sphere) comes back.
    ASSERT_TRUE(openAndWait(window, "Geometry/Sphere.glsl"));
    window.viewport()->setStallLimit(20.0);
    warnings.clear();
    ASSERT_TRUE(window.openFile(loop));
    ASSERT_TRUE(waitFor([&] { return !warnings.isEmpty(); }, 60000));
    EXPECT_TRUE(warnings.back().contains("previous SDF")) << warnings.back().toStdString();
    // Jobs run what the viewport shows: the sphere, not the loop the editor holds (issue 34, point 3).
    ASSERT_TRUE(waitFor([&] { return window.document()->reverted(); }));
    const values::SdfInput input = window.document()->input();
    EXPECT_TRUE(QString::fromStdString(input.sdf).endsWith("Sphere.glsl")) << input.sdf;
    EXPECT_EQ(QString::fromStdString(input.source), window.document()->lastGoodText());
    EXPECT_FALSE(QString::fromStdString(input.source).contains("100000000")) << "the loop's text went to the jobs";
    EXPECT_TRUE(window.editor()->text().contains("100000000")) << "the editor keeps the new text";
    EXPECT_TRUE(window.statusBar()->currentMessage().contains("run it too (Sphere.glsl)"))
        << window.statusBar()->currentMessage().toStdString();
    // Back to the normal limit (at 20 ms the sphere's own full frame may be capped too), then
    // compare a full-resolution frame; the corner overlay names the open file, so a small
    // difference remains.
    window.viewport()->setStallLimit(1500.0);
    QImage back = fullResolutionFrame(window);
    EXPECT_LT(meanDifference(sphere, back), 5.0) << "the sphere is back on screen";
    window.close();
}

TEST(Viewport, TimeScrubsAnimatedSdfs) {
    QString path = QDir::temp().filePath("sdfwb-gui-pulse.glsl");
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("float sdf(vec3 p, float t) { return length(p) - 0.4 - 0.3 * sin(t); }\n");
    file.close();
    app::MainWindow window;
    window.show();
    ASSERT_TRUE(openFileAndWait(window, path));
    // A new SDF's first frame is a 5 % probe: compare full-resolution frames only.
    window.viewport()->resetCamera(); // not a camera restored from an earlier test's session
    window.document()->setTime(0.0f);
    long small = foreground(fullResolutionFrame(window), kBackground);
    window.document()->setTime(1.5f);
    EXPECT_FLOAT_EQ(window.viewport()->time(), 1.5f) << "the viewport draws at the document's time";
    EXPECT_DOUBLE_EQ(window.timeBar()->time(), 1.5) << "and the time bar shows it";
    long large = foreground(fullResolutionFrame(window), kBackground);
    EXPECT_GT(large, small * 2) << "sin(1.5) grows the sphere from 0.4 to 0.7";
    window.playback()->setPlaying(true);
    float startTime = window.document()->time();
    ASSERT_TRUE(waitFor([&] { return window.document()->time() > startTime + 0.2f; }, 3000));
    window.playback()->setPlaying(false);
    EXPECT_NEAR(window.timeBar()->time(), window.document()->time(), 1e-3);
    EXPECT_FLOAT_EQ(window.viewport()->time(), window.document()->time());
    // Jobs run at the document's time: the probe's frame and a video's first frame.
    EXPECT_FLOAT_EQ(window.document()->frame(window.viewport()->frameSettings(), 64, 48).time, window.document()->time());
    values::AnimateRequest video;
    video.frame.width = 64;
    video.frame.height = 48;
    EXPECT_FLOAT_EQ(window.exports()->videoRequest(video).frame.time, window.document()->time());
}
