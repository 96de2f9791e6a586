// The workbench window under a real X server (Xvfb): the default SDF is drawn by the same
// renderer as the batch path, and a typed error shows a diagnostic while the last good shape stays.

#include <gui/CloudController.h>
#include <gui/ExportController.h>
#include <gui/FileController.h>
#include <gui/GuiMain.h>
#include <gui/MainWindow.h>
#include <gui/MeshExportController.h>
#include <gui/PlaneController.h>
#include <gui/PlaybackController.h>
#include <gui/ProbeController.h>
#include <gui/SamplingController.h>
#include <gui/SdfDocument.h>
#include <gui/ThumbnailController.h>
#include <jobs/Requests.h>
#include <renderer/ImageIO.h>
#include <sampling/SampleFile.h>
#include <widgets/CameraPanel.h>
#include <widgets/DatasetBrowser.h>
#include <widgets/ExportDialog.h>
#include <widgets/GlslEditor.h>
#include <widgets/LogPanel.h>
#include <widgets/ParametersPanel.h>
#include <widgets/PlanePanel.h>
#include <widgets/ProbePanel.h>
#include <widgets/ProblemsPanel.h>
#include <widgets/SamplingDialog.h>
#include <widgets/TimeBar.h>
#include <widgets/ViewportWidget.h>

#include <gtest/gtest.h>

#include <filesystem>

#include "common/NetworkSockets.h"
#include <QApplication>
#include <QDialog>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <Qsci/qsciscintilla.h>
#include <core/Log.h>
#include <mutex>
#include <renderer/GlInfo.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>
#include <QThread>
#include <QToolBar>
#include <QTreeWidget>
#include <QtTest/QTest>
#include <csignal>

#include <cmath>
#include <cstring>
#include <functional>

#include <glm/geometric.hpp>

using namespace sdfwb;

namespace {

bool waitFor(const std::function<bool()>& condition, int timeoutMilliseconds = 20000) {
    QElapsedTimer timer;
    timer.start();
    while (!condition()) {
        if (timer.elapsed() > timeoutMilliseconds) return false;
        QApplication::processEvents(QEventLoop::AllEvents, 50);
        QThread::msleep(10);
    }
    return true;
}

long foreground(const QImage& image, QColor background) {
    long count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            QColor c = image.pixelColor(x, y);
            if (std::abs(c.red() - background.red()) > 3 || std::abs(c.green() - background.green()) > 3 ||
                std::abs(c.blue() - background.blue()) > 3)
                ++count;
        }
    return count;
}

const QColor kBackground = QColor::fromRgbF(0.16f, 0.17f, 0.19f);

QString datasetFile(const char* relative) { return QDir(SDFWB_SOURCE_DIR "/dataset").filePath(relative); }

QImage frameOf(app::MainWindow& window) {
    window.viewport()->update();
    return window.viewport()->grabFramebuffer();
}

// A frame at full resolution: a new slow-looking SDF's first frame, and frames right after a
// resize or a camera move, are drawn at a reduced scale and the full one follows.
QImage fullResolutionFrame(app::MainWindow& window) {
    float lastScale = 0.0f;
    QMetaObject::Connection connection = QObject::connect(window.viewport(), &widgets::ViewportWidget::frameRendered,
                                                          [&](double, float scale) { lastScale = scale; });
    QImage frame = frameOf(window);
    for (int k = 0; k < 20 && lastScale < 1.0f; ++k) {
        waitFor([&] { return !window.viewport()->isInteracting(); }, 2000);
        frame = frameOf(window);
    }
    QObject::disconnect(connection);
    EXPECT_EQ(lastScale, 1.0f) << "no full-resolution frame";
    return frame;
}

} // namespace

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

TEST(SamplingDialog, SamplesTheOpenSdfAndCancelsCleanly) {
    app::MainWindow window;
    window.show();
    ASSERT_TRUE(window.openFile(datasetFile("Geometry/Torus.glsl")));
    app::SamplingController* sampling = window.sampling();
    sampling->setExecutable(SDFWB_BINARY);
    sampling->showDialog();
    widgets::SamplingDialog* dialog = sampling->dialog();
    ASSERT_NE(dialog, nullptr);

    QString output = QDir::temp().filePath("sdfwb-gui-samples.npz");
    QFile::remove(output);
    widgets::SamplingSettings settings;
    settings.pattern = "near";
    settings.count = 20000;
    settings.output = output;
    dialog->setSettings(settings);
    bool done = false, ok = false;
    QObject::connect(sampling, &app::SamplingController::finished, [&](bool success, const QString&) {
        done = true;
        ok = success;
    });
    dialog->findChild<QPushButton*>("start")->click();
    ASSERT_TRUE(waitFor([&] { return done; }, 60000));
    EXPECT_TRUE(ok) << dialog->findChild<QLabel*>("message")->text().toStdString();
    EXPECT_TRUE(QFile::exists(output));
    EXPECT_TRUE(dialog->findChild<QLabel*>("message")->text().contains("20000 samples"));
    dialog->grab().save(QDir::temp().filePath("sdfwb-gui-sampling-dialog.png"));

    // A long run, cancelled: no file.
    QString cancelled = QDir::temp().filePath("sdfwb-gui-cancelled.npz");
    QFile::remove(cancelled);
    settings.pattern = "metropolis";
    settings.count = 400000000;
    settings.output = cancelled;
    dialog->setSettings(settings);
    done = false;
    quint64 written = 0;
    QObject::connect(sampling, &app::SamplingController::progress, [&](quint64 d, quint64) { written = d; });
    dialog->findChild<QPushButton*>("start")->click();
    // Cancel once the child has written samples (its output is open), while it still runs.
    ASSERT_TRUE(waitFor([&] { return written > 0; }, 60000)) << "no progress from the sampling child";
    ASSERT_TRUE(sampling->isRunning()) << "the job ended before Cancel";
    dialog->findChild<QPushButton*>("cancel")->click();
    ASSERT_TRUE(waitFor([&] { return done; }, 30000));
    EXPECT_FALSE(ok);
    EXPECT_TRUE(dialog->findChild<QLabel*>("message")->text().contains("Cancelled"));
    EXPECT_FALSE(QFile::exists(cancelled));
    QFile::remove(output);
}

namespace {

// Opens `file` and waits until the viewport shows it.
bool openAndWait(app::MainWindow& window, const char* file) {
    bool applied = false;
    auto connection = QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    bool ok = window.openFile(datasetFile(file)) && waitFor([&] { return applied; });
    QObject::disconnect(connection);
    // A slow-looking new SDF is first drawn at the moving scale: wait for the full frame after it.
    return ok && waitFor([&] { return window.viewport()->lastFrameMilliseconds() > 0.0 && !window.viewport()->isInteracting(); });
}

double meanDifference(const QImage& a, const QImage& b) {
    if (a.size() != b.size()) return 255.0;
    double sum = 0.0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            QColor p = a.pixelColor(x, y), q = b.pixelColor(x, y);
            sum += std::abs(p.red() - q.red()) + std::abs(p.green() - q.green()) + std::abs(p.blue() - q.blue());
        }
    return sum / (3.0 * a.width() * a.height());
}

// Pixels whose colour differs from the other image's by more than a rounding step.
long changedPixels(const QImage& a, const QImage& b) {
    long changed = 0;
    for (int y = 0; y < std::min(a.height(), b.height()); ++y)
        for (int x = 0; x < std::min(a.width(), b.width()); ++x) {
            QColor p = a.pixelColor(x, y), q = b.pixelColor(x, y);
            changed += std::abs(p.red() - q.red()) + std::abs(p.green() - q.green()) + std::abs(p.blue() - q.blue()) > 12;
        }
    return changed;
}

} // namespace

TEST(Viewport, EveryShadingModeDrawsSomethingDifferent) {
    app::MainWindow window;
    window.resize(1000, 600);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    std::vector<QImage> frames;
    for (renderer::ShadingMode mode :
         {renderer::ShadingMode::Normals, renderer::ShadingMode::Gooch, renderer::ShadingMode::Matcap,
          renderer::ShadingMode::Curvature, renderer::ShadingMode::Steps}) {
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
    bool applied = false;
    QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    ASSERT_TRUE(window.openFile(path));
    ASSERT_TRUE(waitFor([&] { return applied; }));
    window.setShadingMode(renderer::ShadingMode::Gooch);
    window.setAmbientOcclusion(false);
    QImage plain = frameOf(window);
    window.setAmbientOcclusion(true);
    QImage occluded = frameOf(window);
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
    viewport->setFrameBudget(0.5); // unreachable on purpose: the scale must drop while moving
    ASSERT_TRUE(waitFor([&] { return !viewport->isInteracting(); }, 3000));
    viewport->grabFramebuffer(); // a full-resolution frame: the scale while moving starts from its cost
    ASSERT_EQ(viewport->lastFrameScale(), 1.0f);
    renderer::Camera before = viewport->camera();
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
        viewport->setSettleTiming([separateFaster](bool fused, bool cones, double) {
            return (fused ? 60.0 : separateFaster ? 30.0 : 90.0) + (cones ? 20.0 : 0.0);
        });
        window.show();
        ASSERT_TRUE(openAndWait(window, "Manufactured/Mug.glsl"));
        EXPECT_TRUE(viewport->fusedMarch()) << "a long SDF opens with the fused march";
        const QImage fused = fullResolutionFrame(window);
        ASSERT_TRUE(waitFor([&] { return viewport->marchSettled(); }, 30000)) << "never settled at rest";
        EXPECT_EQ(viewport->fusedMarch(), !separateFaster)
            << (separateFaster ? "the faster separate march was not kept" : "the slower separate march was kept");
        EXPECT_FALSE(viewport->conePass()) << "the slower cone pass was kept";
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
        viewport->setSettleTiming(
            [conesFaster](bool, bool cones, double) { return cones ? (conesFaster ? 50.0 : 150.0) : 100.0; });
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
    renderer::Camera edited;
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
    EXPECT_FLOAT_EQ(again.cameraPanel()->camera().position.y, renderer::Camera{}.position.y);
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
    renderer::Camera far;
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
    const jobs::SdfInput input = window.document()->input();
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
    const renderer::ShadingMode modes[] = {renderer::ShadingMode::Gooch, renderer::ShadingMode::Matcap,
                                           renderer::ShadingMode::Curvature, renderer::ShadingMode::Steps,
                                           renderer::ShadingMode::Normals};
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
    for (int i = 12; clock.elapsed() < 60000; ++i) act(i);
    window.resize(1000, 700);
    if (dock->isFloating()) dock->setFloating(false);
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    window.setShadingMode(renderer::ShadingMode::Normals);
    const QImage last = frameOf(window);
    log::removeSink(sink);
    std::printf("abuse: %d actions (%d keystrokes, %d float/re-docks, %d dialogs) in %.0f s; GL objects %ld -> %ld\n", actions,
                typed, docked, dialogs, clock.elapsed() / 1000.0, baseline, renderer::liveGlObjects());
    EXPECT_GT(actions, 60);
    EXPECT_GT(docked, 10);
    EXPECT_TRUE(glErrors.empty()) << glErrors.size() << " GL errors, first: " << glErrors.front();
    EXPECT_LE(renderer::liveGlObjects(), baseline + 8) << "GL objects pile up";
    EXPECT_GT(foreground(last, kBackground), 1000) << "the torus is still drawn";
    auto sockets = sdfwb::testing::networkSockets("self");
    EXPECT_TRUE(sockets.empty()) << "the workbench opened a network socket: " << sockets.front();
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
    bool applied = false;
    QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    ASSERT_TRUE(window.openFile(path));
    ASSERT_TRUE(waitFor([&] { return applied; }));
    // A new SDF's first frame is a 5 % probe: compare full-resolution frames only.
    window.viewport()->resetCamera(); // not a camera restored from an earlier test's session
    window.timeBar()->setTime(0.0);
    window.viewport()->setTime(0.0f);
    long small = foreground(fullResolutionFrame(window), kBackground);
    window.viewport()->setTime(1.5f);
    long large = foreground(fullResolutionFrame(window), kBackground);
    EXPECT_GT(large, small * 2) << "sin(1.5) grows the sphere from 0.4 to 0.7";
    window.playback()->setPlaying(true);
    float startTime = window.viewport()->time();
    ASSERT_TRUE(waitFor([&] { return window.viewport()->time() > startTime + 0.2f; }, 3000));
    window.playback()->setPlaying(false);
    EXPECT_NEAR(window.timeBar()->time(), window.viewport()->time(), 1e-3);
}

TEST(Export, ScreenshotAtAChosenSizeAndAnMp4) {
    app::MainWindow window;
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    QString png = QDir::temp().filePath("sdfwb-gui-screenshot.png");
    QFile::remove(png);
    EXPECT_EQ(window.exports()->saveScreenshot(png, 640, 400), QString());
    auto image = renderer::readImage(png.toStdString());
    ASSERT_TRUE(image.hasValue());
    EXPECT_EQ(image->width, 640);
    EXPECT_EQ(image->height, 400);
    // The torus is in it: between a twentieth and half of the pixels differ from the background.
    long drawn = 0;
    for (int y = 0; y < image->height; ++y)
        for (int x = 0; x < image->width; ++x) {
            const std::uint8_t* pixel = image->pixel(x, y);
            drawn += std::abs(pixel[0] - kBackground.red()) + std::abs(pixel[1] - kBackground.green()) +
                         std::abs(pixel[2] - kBackground.blue()) >
                     6;
        }
    EXPECT_GT(drawn, 640L * 400 / 20);
    EXPECT_LT(drawn, 640L * 400 / 2);

    window.exports()->setExecutable(SDFWB_BINARY);
    window.exports()->showVideoDialog();
    QString mp4 = QDir::temp().filePath("sdfwb-gui-turntable.mp4");
    QFile::remove(mp4);
    widgets::ExportSettings settings;
    settings.output = mp4;
    settings.width = 160;
    settings.height = 90;
    settings.seconds = 1.0;
    settings.framesPerSecond = 10;
    window.exports()->videoDialog()->setSettings(settings);
    bool done = false, ok = false;
    QObject::connect(window.exports(), &app::ExportController::videoFinished, [&](bool success, const QString&) {
        done = true;
        ok = success;
    });
    window.exports()->videoDialog()->findChild<QPushButton*>("start")->click();
    ASSERT_TRUE(waitFor([&] { return done; }, 60000));
    EXPECT_TRUE(ok) << window.exports()->videoDialog()->findChild<QLabel*>("message")->text().toStdString();
    // FFmpeg's own reader decodes it: H.264, 160x90, 10 frames (1 s at 10 fps).
    QProcess probe;
    probe.start("ffprobe", {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                            "stream=codec_name,width,height,nb_read_frames", "-of", "csv=p=0", mp4});
    ASSERT_TRUE(probe.waitForFinished(30000));
    EXPECT_EQ(QString::fromUtf8(probe.readAllStandardOutput()).trimmed(), QString("h264,160,90,10"));
    window.grab().save(QDir::temp().filePath("sdfwb-gui-window.png"));
}

TEST(CuttingPlane, PanelDrawsThePlaneAndShowsReadouts) {
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Sphere.glsl"));
    window.plane()->setExecutable(SDFWB_BINARY);
    QImage before = frameOf(window);
    bool readout = false;
    QObject::connect(window.plane(), &app::PlaneController::readoutUpdated, [&] { readout = true; });
    window.planePanel()->findChild<QPushButton*>("axis_Z")->click();
    EXPECT_TRUE(window.viewport()->plane().enabled);
    QImage with = frameOf(window);
    EXPECT_GT(meanDifference(before, with), 2.0) << "the plane must show";
    with.save(QDir::temp().filePath("sdfwb-gui-plane.png"));
    ASSERT_TRUE(waitFor([&] { return readout; }, 30000))
        << window.planePanel()->findChild<QLabel*>("readouts")->text().toStdString();
    const widgets::PlaneReadoutView& r = window.planePanel()->readout();
    EXPECT_NEAR(r.minimum, -0.8f, 0.03f);
    EXPECT_NEAR(r.lipschitzMax, 1.0f, 0.01f);
    EXPECT_EQ(r.nanCount, 0u);

    // Ctrl + drag moves the plane along its normal, and the panel follows.
    widgets::ViewportWidget* viewport = window.viewport();
    QPoint start(400, 300), end(400, 250);
    QMouseEvent press(QEvent::MouseButtonPress, start, viewport->mapToGlobal(start), Qt::LeftButton, Qt::LeftButton,
                      Qt::ControlModifier);
    QApplication::sendEvent(viewport, &press);
    QMouseEvent move(QEvent::MouseMove, end, viewport->mapToGlobal(end), Qt::NoButton, Qt::LeftButton, Qt::ControlModifier);
    QApplication::sendEvent(viewport, &move);
    EXPECT_NEAR(viewport->plane().offset, 0.2f, 1e-3f);
    EXPECT_NEAR(window.planePanel()->plane().offset, 0.2f, 1e-3f);

    window.planePanel()->findChild<QPushButton*>("apply_step_factor")->click();
    EXPECT_NEAR(viewport->trace().stepFactor, r.safeStepFactor, 1e-6f);
    window.grab().save(QDir::temp().filePath("sdfwb-gui-plane-window.png"));
}

// Issue 15: the video export is a typed request built from the viewport's whole state and the
// document's current text, so its frame is the screenshot of the same state (up to H.264's loss).
TEST(Export, Mp4FrameEqualsAScreenshotOfTheSameUnsavedState) {
    app::MainWindow window;
    window.resize(1000, 640);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Sphere.glsl"));
    // State the old argument list dropped: trace settings, the cutting plane, markers; and an
    // unsaved edit (the sphere becomes a box).
    bool applied = false;
    QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    QString text = window.editor()->text();
    text.replace("return length(p) - radius;",
                 "vec3 q = abs(p) - vec3(0.55); return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);");
    window.editor()->setText(text);
    ASSERT_TRUE(waitFor([&] { return applied; }));
    ASSERT_TRUE(window.editor()->isModified());
    renderer::ShadingSettings shading = window.viewport()->shading();
    shading.mode = renderer::ShadingMode::Gooch;
    shading.markers = {{0.55f, 0.55f, 0.55f}};
    window.viewport()->setShading(shading);
    renderer::TraceSettings trace = window.viewport()->trace();
    trace.maxSteps = 24; // few steps: the box's silhouette shows the budget
    trace.stepFactor = 0.6f;
    window.viewport()->setTrace(trace);
    renderer::CuttingPlane plane = window.viewport()->plane();
    plane.enabled = true;
    plane.normal = {0.3f, 0.2f, 1.0f};
    plane.offset = 0.2f;
    window.viewport()->setPlane(plane);

    widgets::ExportSettings settings;
    settings.output = QDir::temp().filePath(QString("sdfwb-gui-state-%1.mp4").arg(QCoreApplication::applicationPid()));
    QFile::remove(settings.output);
    settings.width = 320;
    settings.height = 200;
    settings.seconds = 0.1;
    settings.framesPerSecond = 10;
    const jobs::AnimateRequest request = window.exports()->videoRequest(settings);
    EXPECT_TRUE(request.frame.trace == trace);
    EXPECT_TRUE(request.frame.plane == plane);
    EXPECT_TRUE(request.frame.shading == shading);
    EXPECT_TRUE(request.frame.camera == window.viewport()->camera());
    EXPECT_NE(request.frame.sdf.source.find("vec3(0.55)"), std::string::npos) << "the export must run the editor's text";

    window.exports()->setExecutable(SDFWB_BINARY);
    window.exports()->showVideoDialog();
    window.exports()->videoDialog()->setSettings(settings);
    bool done = false, ok = false;
    QObject::connect(window.exports(), &app::ExportController::videoFinished, [&](bool success, const QString&) {
        done = true;
        ok = success;
    });
    window.exports()->videoDialog()->findChild<QPushButton*>("start")->click();
    ASSERT_TRUE(waitFor([&] { return done; }, 60000));
    ASSERT_TRUE(ok) << window.exports()->videoDialog()->findChild<QLabel*>("message")->text().toStdString();

    // The video's first frame, decoded by the real FFmpeg.
    const QString decoded = settings.output + ".png";
    QProcess ffmpeg;
    ffmpeg.start("ffmpeg", {"-v", "error", "-y", "-i", settings.output, "-frames:v", "1", decoded});
    ASSERT_TRUE(ffmpeg.waitForFinished(30000));
    ASSERT_EQ(ffmpeg.exitCode(), 0) << ffmpeg.readAllStandardError().toStdString();
    QImage frame(decoded);
    ASSERT_EQ(frame.size(), QSize(320, 200));

    auto screenshot = [&](const QString& name) {
        const QString path = QDir::temp().filePath(name);
        EXPECT_EQ(window.exports()->saveScreenshot(path, 320, 200), QString());
        return QImage(path).convertToFormat(QImage::Format_RGB32);
    };
    const QImage same = screenshot("sdfwb-gui-state-same.png");
    plane.enabled = false;
    window.viewport()->setPlane(plane);
    const QImage withoutPlane = screenshot("sdfwb-gui-state-noplane.png");
    window.viewport()->setTrace(renderer::TraceSettings{});
    shading.mode = renderer::ShadingMode::Normals;
    window.viewport()->setShading(shading);
    const QImage defaults = screenshot("sdfwb-gui-state-defaults.png");

    const double error = meanDifference(frame.convertToFormat(QImage::Format_RGB32), same);
    const double planeEffect = meanDifference(same, withoutPlane);
    const double settingsEffect = meanDifference(same, defaults);
    std::printf("mp4 frame vs screenshot: mean |difference| %.2f / 255; the plane alone changes %.2f, the settings %.2f\n", error,
                planeEffect, settingsEffect);
    EXPECT_LT(error, 3.0) << "the video frame differs from the screenshot of the same state";
    EXPECT_GT(planeEffect, 4.0 * error) << "the comparison cannot tell the plane apart";
    EXPECT_GT(settingsEffect, 4.0 * error) << "the comparison cannot tell the settings apart";
    QFile::remove(settings.output);
    QFile::remove(decoded);
}

// Issue 15: the plane readouts describe the text on screen, not the file on disk.
TEST(CuttingPlane, AnUnsavedEditChangesTheReadouts) {
    app::MainWindow window;
    window.resize(1000, 640);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Sphere.glsl"));
    window.plane()->setExecutable(SDFWB_BINARY);
    int readouts = 0;
    QObject::connect(window.plane(), &app::PlaneController::readoutUpdated, [&] { ++readouts; });
    window.planePanel()->findChild<QPushButton*>("axis_Z")->click();
    ASSERT_TRUE(waitFor([&] { return readouts > 0; }, 30000))
        << window.planePanel()->findChild<QLabel*>("readouts")->text().toStdString();
    EXPECT_NEAR(window.planePanel()->readout().minimum, -0.8f, 0.03f);

    const QByteArray onDisk = [] {
        QFile file(datasetFile("Geometry/Sphere.glsl"));
        return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
    }();
    QString text = window.editor()->text();
    text.replace("return length(p) - radius;", "return length(p) - 0.4;");
    const int before = readouts;
    window.editor()->setText(text); // not saved
    ASSERT_TRUE(waitFor([&] { return readouts > before && window.planePanel()->readout().minimum > -0.5f; }, 30000))
        << "readouts still describe the file on disk: minimum " << window.planePanel()->readout().minimum;
    EXPECT_NEAR(window.planePanel()->readout().minimum, -0.4f, 0.03f);
    EXPECT_TRUE(window.editor()->isModified());
    QFile file(datasetFile("Geometry/Sphere.glsl"));
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_EQ(file.readAll(), onDisk) << "the file on disk must be untouched";
}

// Issue 14: foreign code in the workbench: a Shadertoy map() opens as it is, the entry field picks
// another function, and "show where" rings the audit's example points and moves the plane there.
TEST(ForeignCode, EntryFieldAndShowWhere) {
    QDir folder(QDir::temp().filePath("sdfwb-gui-foreign"));
    folder.mkpath(".");
    const QString file = folder.filePath("toy.glsl");
    {
        QFile out(file);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
        out.write("// Shadertoy style: map() with a material id; the ball jumps by 0.2 across x = 0.2\n"
                  "#define PI 3.14159265\n"
                  "mat2 rot(float a) { return mat2(cos(a), -sin(a), sin(a), cos(a)); }\n"
                  "vec2 map(vec3 p) { return vec2(length(p) - 0.5 + (p.x > 0.2 ? 0.2 : 0.0), 1.0); }\n"
                  "// the paper's snake in small: steeper than a distance, capped at 0.25\n"
                  "float snake(vec3 p) { p.xz *= rot(PI / 8.0); return min(0.25, 1.9 * (length(vec3(p.x, p.y * 1.6, p.z)) - "
                  "0.45)); }\n");
    }
    app::MainWindow window;
    window.resize(1400, 800);
    window.show();
    bool applied = false;
    QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    ASSERT_TRUE(window.openFile(file));
    ASSERT_TRUE(waitFor([&] { return applied; })) << "map() was not taken as the entry point";
    EXPECT_EQ(window.document()->signature().entry, "map");
    auto* entry = window.findChild<QLineEdit*>("entry");
    ASSERT_TRUE(entry);
    EXPECT_TRUE(entry->placeholderText().contains("map")) << entry->placeholderText().toStdString();
    window.plane()->setExecutable(SDFWB_BINARY);
    int readouts = 0;
    QObject::connect(window.plane(), &app::PlaneController::readoutUpdated, [&] { ++readouts; });
    auto findingsNamed = [&](const char* name) {
        for (const auto& f : window.planePanel()->readout().findings)
            if (f.name == name) return true;
        return false;
    };
    window.planePanel()->findChild<QPushButton*>("axis_Z")->click();
    ASSERT_TRUE(waitFor([&] { return readouts > 0 && findingsNamed("discontinuous"); }, 30000))
        << window.planePanel()->findChild<QLabel*>("readouts")->text().toStdString();
    auto* findings = window.planePanel()->findChild<QComboBox*>("findings");
    auto* showWhere = window.planePanel()->findChild<QPushButton*>("show_where");
    ASSERT_TRUE(findings && showWhere && showWhere->isEnabled());
    findings->setCurrentIndex(findings->findText("discontinuous"));
    auto showAndCheck = [&](const char* name, const char* screenshot) {
        std::vector<glm::vec3> examples;
        for (const auto& f : window.planePanel()->readout().findings)
            if (f.name == name) examples = f.examples;
        ASSERT_FALSE(examples.empty());
        const QImage before = window.viewport()->grabFramebuffer();
        const int seen = readouts;
        showWhere->click();
        EXPECT_EQ(window.viewport()->shading().markers, examples);
        const renderer::CuttingPlane plane = window.viewport()->plane();
        EXPECT_NEAR(glm::dot(glm::normalize(plane.normal), examples.front()), plane.offset, 1e-4f)
            << "the plane goes through the first point";
        EXPECT_NEAR(window.planePanel()->plane().offset, plane.offset, 1e-3f);
        EXPECT_GT(meanDifference(before, window.viewport()->grabFramebuffer()), 0.05) << "the rings show";
        ASSERT_TRUE(waitFor([&] { return readouts > seen; }, 30000)) << "readouts for the moved plane";
        if (auto* dock = qobject_cast<QDockWidget*>(window.planePanel()->parentWidget())) dock->raise();
        if (const char* folder = std::getenv("SDFWB_SCREENSHOT_DIR")) window.grab().save(QDir(folder).filePath(screenshot));
    };
    showAndCheck("discontinuous", "foreign_discontinuity.png");
    for (const auto& e : window.viewport()->shading().markers) EXPECT_NEAR(e.x, 0.2f, 0.03f) << "on the jump";

    // The entry field: typed, Return; the viewport and the readouts follow the new function.
    applied = false;
    entry->setFocus();
    for (QChar c : QString("snake")) {
        QKeyEvent press(QEvent::KeyPress, 0, Qt::NoModifier, QString(c));
        QApplication::sendEvent(entry, &press);
    }
    QKeyEvent enter(QEvent::KeyPress, Qt::Key_Return, Qt::NoModifier);
    QApplication::sendEvent(entry, &enter);
    EXPECT_EQ(entry->text(), "snake");
    ASSERT_TRUE(waitFor([&] { return applied; }));
    EXPECT_EQ(window.document()->signature().entry, "snake");
    renderer::CuttingPlane throughOrigin = window.viewport()->plane();
    throughOrigin.offset = 0.0f;
    window.planePanel()->setPlane(throughOrigin);
    window.planePanel()->findChild<QPushButton*>("axis_Z")->click(); // emits the panel's plane: z = 0
    ASSERT_TRUE(waitFor([&] { return findingsNamed("truncated") && findingsNamed("non-conservative"); }, 30000))
        << window.planePanel()->findChild<QLabel*>("readouts")->text().toStdString();
    findings->setCurrentIndex(findings->findText("truncated"));
    showAndCheck("truncated", "foreign_truncated.png");

    // Another file gets its own entry point: the field clears and sdf() is found.
    applied = false;
    ASSERT_TRUE(window.openFile(datasetFile("Geometry/Sphere.glsl")));
    ASSERT_TRUE(waitFor([&] { return applied; }));
    EXPECT_TRUE(entry->text().isEmpty());
    EXPECT_EQ(window.document()->signature().entry, "sdf");
}

namespace {

QString writeScratch(const QString& name, const QByteArray& text) {
    QDir folder(QDir::temp().filePath("sdfwb-gui-files"));
    folder.mkpath(".");
    QFile file(folder.filePath(name));
    file.open(QIODevice::WriteOnly | QIODevice::Truncate);
    file.write(text);
    return folder.filePath(name);
}

QByteArray readAll(const QString& path) {
    QFile file(path);
    file.open(QIODevice::ReadOnly);
    return file.readAll();
}

} // namespace

TEST(Files, SaveAutosaveRecoverAndPromptOnClose) {
    QString path = writeScratch("saved.glsl", "float sdf(vec3 p) { return length(p) - 0.5; }\n");
    for (const QString& stale : app::FileController::recoveryFiles()) QFile::remove(stale);
    {
        app::MainWindow window;
        window.show();
        ASSERT_TRUE(window.openFile(path));
        EXPECT_EQ(window.files()->recentFiles().value(0), QFileInfo(path).absoluteFilePath());
        window.editor()->setText("float sdf(vec3 p) { return length(p) - 0.6; }\n");
        EXPECT_TRUE(window.editor()->isModified());
        EXPECT_TRUE(window.windowTitle().contains("*"));
        // Autosave: the recovery file holds the edit; the real file does not change.
        window.files()->autosaveNow();
        ASSERT_TRUE(QFile::exists(window.files()->recoveryPath()));
        EXPECT_TRUE(readAll(window.files()->recoveryPath()).contains("0.6"));
        EXPECT_TRUE(readAll(path).contains("0.5"));
        // Closing asks; Cancel keeps the window and the edit.
        int asked = 0;
        window.files()->setPrompt([&](const QString&) {
            ++asked;
            return app::FileController::Answer::Cancel;
        });
        EXPECT_FALSE(window.close());
        EXPECT_EQ(asked, 1);
        EXPECT_TRUE(window.editor()->isModified());
        // The window goes away without a clean close, as in a crash: the recovery file stays.
    }
    QStringList recovery = app::FileController::recoveryFiles();
    ASSERT_FALSE(recovery.isEmpty());
    {
        app::MainWindow window;
        ASSERT_TRUE(window.files()->restoreRecovery(recovery.first()));
        EXPECT_TRUE(window.editor()->text().contains("0.6"));
        EXPECT_EQ(window.document()->path(), QFileInfo(path).absoluteFilePath());
        EXPECT_TRUE(window.editor()->isModified());
        // Save writes atomically and clears the recovery file; then closing asks nothing.
        ASSERT_TRUE(window.files()->save());
        EXPECT_TRUE(readAll(path).contains("0.6"));
        EXPECT_FALSE(QFile::exists(window.files()->recoveryPath()));
        int asked = 0;
        window.files()->setPrompt([&](const QString&) {
            ++asked;
            return app::FileController::Answer::Cancel;
        });
        EXPECT_TRUE(window.close());
        EXPECT_EQ(asked, 0);
    }
}

// Not a test of its own: the child process of the test below (hence DISABLED_, which the parent
// turns on). It edits, lets the real autosave timer fire, then dies by SIGKILL, as a crash would.
TEST(CrashChild, DISABLED_EditThenDie) {
    QString path = writeScratch("crashed.glsl", "float sdf(vec3 p) { return length(p) - 0.5; }\n");
    app::MainWindow window;
    window.show();
    ASSERT_TRUE(window.openFile(path));
    window.files()->setAutosaveInterval(200);
    window.editor()->setText("float sdf(vec3 p) { return length(p) - 0.25; } // typed before the crash\n");
    QString recovery = window.files()->recoveryPath();
    ASSERT_TRUE(waitFor([&] { return QFile::exists(recovery); }, 5000));
    ::raise(SIGKILL);
}

TEST(Files, RecoversAfterTheProcessIsKilled) {
    for (const QString& stale : app::FileController::recoveryFiles()) QFile::remove(stale);
    QProcess child;
    child.start(QCoreApplication::applicationFilePath(),
                {"--gtest_also_run_disabled_tests", "--gtest_filter=CrashChild.DISABLED_EditThenDie"});
    ASSERT_TRUE(child.waitForFinished(60000));
    EXPECT_EQ(child.exitStatus(), QProcess::CrashExit) << "the child must have been killed";
    QStringList recovery = app::FileController::recoveryFiles();
    ASSERT_EQ(recovery.size(), 1);
    app::MainWindow window;
    ASSERT_TRUE(window.files()->restoreRecovery(recovery.first()));
    EXPECT_TRUE(window.editor()->text().contains("typed before the crash"));
    EXPECT_TRUE(window.document()->path().endsWith("crashed.glsl"));
    window.files()->setPrompt([](const QString&) { return app::FileController::Answer::No; });
    EXPECT_TRUE(window.close());
    EXPECT_TRUE(app::FileController::recoveryFiles().isEmpty()) << "a clean close (discarding) removes the recovery file";
}

// File > Open mesh: a triangle mesh is the document's field. A 6-unit cube far outside the box
// opens scaled into it (unit-cube); the viewport traces it; the plane's readouts, computed by a
// child job from the document's input, see the same scaled field; text over the mesh (an offset
// shell) reaches the viewport and the jobs; and nothing ever writes over the mesh.
TEST(Files, OpenMeshTracesItAndItsJobsSeeTheSameField) {
    QByteArray cube =
        "v 2 2 2\nv 8 2 2\nv 8 8 2\nv 2 8 2\nv 2 2 8\nv 8 2 8\nv 8 8 8\nv 2 8 8\n"
        "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
    const QString path = writeScratch("far_cube.obj", cube);
    app::MainWindow window;
    window.resize(900, 560); // llvmpipe traces a mesh slowly (docs/mesh-sdf.md): a small viewport
    window.show();
    window.plane()->setExecutable(SDFWB_BINARY);
    bool applied = false;
    QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    int readouts = 0;
    QObject::connect(window.plane(), &app::PlaneController::readoutUpdated, [&] { ++readouts; });
    ASSERT_TRUE(window.openFile(path));
    ASSERT_TRUE(waitFor([&] { return applied; })) << "the mesh never reached the viewport";
    EXPECT_TRUE(window.document()->isMesh());
    EXPECT_EQ(window.document()->meshSign(), "winding");
    EXPECT_EQ(window.document()->meshNormalize(), "unit-cube");
    EXPECT_TRUE(window.windowTitle().contains("mesh: sign winding, normalize unit-cube")) << window.windowTitle().toStdString();
    EXPECT_TRUE(window.editor()->text().contains("sdfwb_meshSdf(p)"));
    const jobs::SdfInput input = window.document()->input();
    EXPECT_EQ(input.sdf, QFileInfo(path).absoluteFilePath().toStdString());
    EXPECT_EQ(input.normalize, "unit-cube");
    // At whatever resolution the viewport settles on for this field on this machine.
    ASSERT_TRUE(waitFor([&] { return window.viewport()->lastFrameMilliseconds() > 0.0 && !window.viewport()->isInteracting(); }));
    const QImage frame = frameOf(window);
    const double share = double(foreground(frame, kBackground)) / double(frame.width() * frame.height());
    // The cube fills the traced box, so from the default camera it covers most of the frame (91.5 %
    // of a 443x476 viewport): background shows only around its silhouette.
    EXPECT_GT(share, 0.05) << "the scaled cube fills part of the viewport";
    EXPECT_LT(share, 0.97) << "background shows around the cube";
    frame.save(QDir::temp().filePath("sdfwb-gui-mesh.png"));

    // The plane through the middle: the scaled cube is [-1, 1]^3, so the field's minimum there is
    // -1 at the centre (unscaled, the plane would lie outside the cube, all positive).
    window.planePanel()->findChild<QPushButton*>("axis_Z")->click();
    ASSERT_TRUE(waitFor([&] { return readouts > 0; }, 60000))
        << window.planePanel()->findChild<QLabel*>("readouts")->text().toStdString();
    EXPECT_NEAR(window.planePanel()->readout().minimum, -1.0f, 0.03f);
    EXPECT_EQ(window.planePanel()->readout().nanCount, 0u);

    // Text over the mesh: an offset shell 0.25 thicker, in the viewport and in the next readout.
    applied = false;
    const int before = readouts;
    window.editor()->setText("float sdf(vec3 p) { return sdfwb_meshSdf(p) - 0.25; }\n");
    window.document()->checkNow(window.editor()->text());
    ASSERT_TRUE(waitFor([&] { return applied; })) << "the offset shell did not compile";
    ASSERT_TRUE(waitFor([&] { return readouts > before; }, 60000));
    EXPECT_NEAR(window.planePanel()->readout().minimum, -1.25f, 0.03f);

    // Save and Save As write nothing: not over the mesh, and not the text elsewhere.
    EXPECT_FALSE(window.files()->save());
    EXPECT_EQ(readAll(path), cube);
    const QString elsewhere = QDir::temp().filePath("sdfwb-gui-files/far_cube_text.glsl");
    QFile::remove(elsewhere);
    EXPECT_FALSE(window.files()->saveAs(elsewhere));
    EXPECT_FALSE(QFile::exists(elsewhere));
    window.files()->setPrompt([](const QString&) { return app::FileController::Answer::No; });
}

TEST(Files, ReloadsWhenTheFileChangesOnDiskAndAsksWhenEdited) {
    QString path = writeScratch("watched.glsl", "float sdf(vec3 p) { return length(p) - 0.5; }\n");
    app::MainWindow window;
    window.show();
    ASSERT_TRUE(window.openFile(path));
    writeScratch("watched.glsl", "float sdf(vec3 p) { return length(p) - 0.3; }\n");
    ASSERT_TRUE(waitFor([&] { return window.editor()->text().contains("0.3"); }, 5000)) << "an unmodified file reloads by itself";
    EXPECT_FALSE(window.editor()->isModified());

    window.editor()->setText("float sdf(vec3 p) { return length(p) - 0.4; } // my edit\n");
    int asked = 0;
    window.files()->setPrompt([&](const QString&) {
        ++asked;
        return app::FileController::Answer::No;
    });
    writeScratch("watched.glsl", "float sdf(vec3 p) { return length(p) - 0.2; }\n");
    ASSERT_TRUE(waitFor([&] { return asked > 0; }, 5000)) << "local edits: ask before reloading";
    EXPECT_TRUE(window.editor()->text().contains("my edit")) << "answered no: the edit stays";
    window.files()->setPrompt([](const QString&) { return app::FileController::Answer::No; });
    window.editor()->setModified(false);
}

TEST(Editor, ProblemsListJumpsToTheLineAndOpensIncludedFiles) {
    QString helper =
        writeScratch("helper.glsl", "// helper\n\nfloat helperDistance(vec3 p) {\n    return length(p) - missingRadius;\n}\n");
    QString main = writeScratch("main.glsl", "#include \"helper.glsl\"\nfloat sdf(vec3 p) {\n    return helperDistance(p);\n}\n");
    app::MainWindow window;
    window.show();
    int updates = 0;
    QObject::connect(window.document(), &app::SdfDocument::diagnosticsChanged, [&] { ++updates; });
    ASSERT_TRUE(window.openFile(main));
    ASSERT_TRUE(waitFor([&] { return updates > 0 && window.problems()->count() > 0; }));
    window.problems()->activate(0);
    EXPECT_EQ(window.document()->path(), QFileInfo(helper).absoluteFilePath()) << "the included file opens";
    int line = 0, column = 0;
    window.editor()->getCursorPosition(&line, &column);
    EXPECT_EQ(line + 1, 4);
    window.grab().save(QDir::temp().filePath("sdfwb-gui-problems.png"));
}

TEST(Editor, FindReplaceGoToAndCompletion) {
    QString path = writeScratch("edit.glsl", "float bump(vec3 p, float height) { return p.y - height; }\n"
                                             "float sdf(vec3 p) {\n    return min(bump(p, 0.1), length(p) - 0.5);\n}\n");
    app::MainWindow window;
    window.show();
    int updates = 0;
    QObject::connect(window.document(), &app::SdfDocument::diagnosticsChanged, [&] { ++updates; });
    ASSERT_TRUE(window.openFile(path));
    ASSERT_TRUE(waitFor([&] { return updates > 0; }));
    EXPECT_TRUE(window.editor()->findNext("length"));
    EXPECT_EQ(window.editor()->selectedText(), "length");
    EXPECT_EQ(window.editor()->replaceAll("0.5", "0.45"), 1);
    EXPECT_TRUE(window.editor()->text().contains("0.45"));
    window.editor()->goToLine(3, 5);
    int line = 0, column = 0;
    window.editor()->getCursorPosition(&line, &column);
    EXPECT_EQ(line, 2);
    EXPECT_EQ(column, 4);
    // Completion knows the file's own functions (with signatures for call tips) and the library's.
    // The file's functions arrive after the diagnostics (they are not on the latency path).
    ASSERT_TRUE(waitFor([&] { return window.editor()->completionEntries().contains("bump(vec3 p, float height)"); }, 10000));
    QStringList names = window.editor()->completionEntries();
    EXPECT_TRUE(names.contains("sdBox(vec3 p, vec3 halfSize)"));
    EXPECT_TRUE(names.contains("smoothstep(edge0, edge1, x)"));
    window.editor()->setModified(false);
}

TEST(Editor, F5ReloadsIncludesFromDisk) {
    QString helper = writeScratch("radius.glsl", "const float kRadius = 0.3;\n");
    QString main =
        writeScratch("uses_radius.glsl", "#include \"radius.glsl\"\nfloat sdf(vec3 p) { return length(p) - kRadius; }\n");
    app::MainWindow window;
    window.show();
    bool applied = false;
    QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    ASSERT_TRUE(window.openFile(main));
    ASSERT_TRUE(waitFor([&] { return applied; }));
    long small = foreground(frameOf(window), kBackground);
    writeScratch("radius.glsl", "const float kRadius = 0.6;\n");
    applied = false;
    window.files()->reloadAll();
    ASSERT_TRUE(waitFor([&] { return applied; }));
    long large = foreground(frameOf(window), kBackground);
    EXPECT_GT(large, 3 * small) << "F5 re-reads the included file";
}

// On llvmpipe (which ends every loop after 65535 iterations without an error) a loop that runs
// longer is a warning at its line in the editor; elsewhere nothing is said (docs/stability.md).
TEST(Editor, ALoopTheDriverWouldCutShortIsAWarningAtItsLine) {
    app::MainWindow window;
    window.show();
    const QString path = writeScratch("long_loop.glsl", "// 0.5 / 200000 added 200000 times\n"
                                                        "float sdf(vec3 p) {\n"
                                                        "    float s = 0.0;\n"
                                                        "    for (int i = 0; i < 200000; ++i) s += 0.5 / 200000.0;\n"
                                                        "    return length(p) - s;\n"
                                                        "}\n");
    bool applied = false;
    QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    ASSERT_TRUE(window.openFile(path));
    ASSERT_TRUE(waitFor([&] { return applied; }));
    // The viewport's context is up by now: edit once so the check runs knowing its driver.
    int updates = 0;
    QObject::connect(window.document(), &app::SdfDocument::diagnosticsChanged, [&] { ++updates; });
    window.editor()->setText(window.editor()->text() + "\n// edited\n");
    ASSERT_TRUE(waitFor([&] { return updates > 0; }));
    const bool llvmpipe = window.viewport()->contextDescription().contains("llvmpipe");
    const auto& diagnostics = window.document()->diagnostics();
    const auto warning = std::find_if(diagnostics.begin(), diagnostics.end(),
                                      [](const shaders::Diagnostic& d) { return d.message.find("65535") != std::string::npos; });
    if (llvmpipe) {
        ASSERT_NE(warning, diagnostics.end()) << "no warning on llvmpipe";
        EXPECT_EQ(warning->line, 4);
        EXPECT_EQ(warning->severity, shaders::Severity::Warning);
        EXPECT_GE(window.editor()->diagnosticCount(), 1);
    } else {
        EXPECT_EQ(warning, diagnostics.end()) << "a warning on a driver without the limit";
    }
    EXPECT_TRUE(applied) << "a warning does not keep the SDF from the viewport";
}

TEST(DatasetBrowser, ListsTheDatasetAndOpensAnEntry) {
    app::MainWindow window;
    window.show();
    // Every dataset file with a metadata block (dataset/<Category>/<Name>.glsl; dataset/lib holds
    // includes), counted here from the folder.
    int files = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(SDFWB_SOURCE_DIR "/dataset"))
        if (entry.path().extension() == ".glsl" && entry.path().parent_path().filename() != "lib") ++files;
    EXPECT_GE(files, 63);
    EXPECT_EQ(window.datasetBrowser()->count(), files);
    bool applied = false;
    QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    ASSERT_TRUE(window.datasetBrowser()->activate("menger sponge"));
    EXPECT_TRUE(window.document()->path().endsWith("Fractal/MengerSponge.glsl"));
    ASSERT_TRUE(waitFor([&] { return applied; }));
    EXPECT_FALSE(window.datasetBrowser()->activate("no such shape"));
}

// Parameters as live controls, on a Shadertoy-style map() with annotated uniforms: real key and
// mouse events on the Parameters dock redraw the viewport with no recompile, the document's jobs
// carry the values (and the clip-end keyframe), reset and "Save values as defaults" work.
TEST(Parameters, DockControlsRedrawWithoutRecompilingAndReachJobsAndTheFile) {
    app::MainWindow window;
    window.show();
    ASSERT_TRUE(openAndWait(window, "../tests/params/iq_torus_map.glsl"));
    widgets::ParametersPanel* panel = window.parametersPanel();
    ASSERT_TRUE(waitFor([&] { return panel->values().size() == 4; })) << "the four declared parameters";
    window.findChild<QDockWidget*>("ParametersDock")->raise();
    auto* slider = panel->findChild<QSlider*>("slider_majorRadius");
    auto* number = panel->findChild<QDoubleSpinBox*>("number_majorRadius");
    auto* capped = panel->findChild<QCheckBox*>("param_capped");
    ASSERT_TRUE(slider && number && capped);
    ASSERT_EQ(panel->findChildren<QDoubleSpinBox*>(QRegularExpression("number_offset_\\d")).size(), 3)
        << "a number per component";
    ASSERT_TRUE(waitFor([&] { return !window.viewport()->isInteracting(); }, 5000));
    const QImage before = frameOf(window);
    const std::uint64_t programs = window.viewport()->programsBuilt();

    // Keyboard on the slider: PageDown twice (real key events through the application).
    slider->setFocus();
    for (int i = 0; i < 2; ++i) {
        QKeyEvent press(QEvent::KeyPress, Qt::Key_PageDown, Qt::NoModifier);
        QApplication::sendEvent(slider, &press);
    }
    const float dragged = panel->values()[0].value[0];
    EXPECT_LT(dragged, 0.6f);
    EXPECT_NEAR(number->value(), dragged, 1e-3) << "the number follows the slider";
    ASSERT_TRUE(waitFor([&] { return !window.viewport()->isInteracting(); }, 5000));
    const QImage smaller = frameOf(window);
    EXPECT_GT(meanDifference(before, smaller), 1.0) << "the viewport shows the new radius";
    EXPECT_EQ(window.viewport()->programsBuilt(), programs) << "a parameter change must not recompile";
    jobs::SdfInput input = window.document()->input();
    ASSERT_EQ(input.params.size(), 4u);
    EXPECT_EQ(input.params[0].name, "majorRadius");
    EXPECT_EQ(input.params[0].value[0], dragged) << "jobs run with the dock's values";

    // Drag on the number: 40 pixels right is 20 steps up.
    QLineEdit* edit = number->findChild<QLineEdit*>();
    ASSERT_TRUE(edit);
    const QPointF start(edit->width() / 2.0, edit->height() / 2.0);
    QMouseEvent press(QEvent::MouseButtonPress, start, edit->mapToGlobal(start), Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(edit, &press);
    const QPointF end = start + QPointF(40.0, 0.0);
    QMouseEvent move(QEvent::MouseMove, end, edit->mapToGlobal(end), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(edit, &move);
    QMouseEvent release(QEvent::MouseButtonRelease, end, edit->mapToGlobal(end), Qt::LeftButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(edit, &release);
    EXPECT_NEAR(panel->values()[0].value[0], dragged + 20.0f * float(number->singleStep()), 1e-4);

    // The bool: a click on the checkbox cuts the torus in half.
    capped->click();
    EXPECT_EQ(panel->values()[3].value[0], 1.0f);
    ASSERT_TRUE(waitFor([&] { return !window.viewport()->isInteracting(); }, 5000));
    EXPECT_GT(meanDifference(smaller, frameOf(window)), 1.0);
    EXPECT_EQ(window.viewport()->programsBuilt(), programs);
    if (const char* folder = std::getenv("SDFWB_SCREENSHOT_DIR"))
        window.grab().save(QDir(folder).filePath("parameters_dock.png"));

    // The clip-end keyframe reaches the MP4 request.
    panel->findChild<QPushButton*>("setClipEnd")->click();
    widgets::ExportSettings settings;
    settings.output = "/tmp/clip.mp4";
    jobs::AnimateRequest request = window.exports()->videoRequest(settings);
    ASSERT_EQ(request.paramsEnd.size(), 4u);
    EXPECT_EQ(request.paramsEnd[3].value[0], 1.0f);
    EXPECT_EQ(request.frame.sdf.params[0].value[0], panel->values()[0].value[0]);

    // Reset one row, then write the others into the file's initializers.
    panel->findChild<QPushButton*>("reset_capped")->click();
    EXPECT_EQ(panel->values()[3].value[0], 0.0f);
    const float saved = panel->values()[0].value[0];
    panel->findChild<QPushButton*>("saveParameterDefaults")->click();
    const std::string text = window.editor()->text().toStdString();
    EXPECT_NE(text.find("uniform float majorRadius = " + shaders::glslLiteral(shaders::ParameterType::Float, {saved}) +
                        "; // @range 0.2 0.8"),
              std::string::npos)
        << text;
    EXPECT_TRUE(window.editor()->isModified());
    // After the recompile the new default is the value: the row is at its default.
    ASSERT_TRUE(waitFor([&] { return window.document()->lastGoodSource().parameters[0].defaultValue[0] == saved; }));
    EXPECT_FALSE(panel->findChild<QPushButton*>("reset_majorRadius")->isEnabled());
    EXPECT_EQ(panel->values()[0].value[0], saved);
}

// The cutting-plane readouts follow a parameter (they run on the document's values), and the
// values come back with the session for the same file.
TEST(Parameters, PlaneReadoutsFollowAndTheSessionKeepsTheValues) {
    {
        app::MainWindow window;
        window.resize(1000, 640);
        window.show();
        ASSERT_TRUE(openAndWait(window, "Geometry/Sphere.glsl"));
        window.plane()->setExecutable(SDFWB_BINARY);
        int readouts = 0;
        QObject::connect(window.plane(), &app::PlaneController::readoutUpdated, [&] { ++readouts; });
        window.planePanel()->findChild<QPushButton*>("axis_Z")->click();
        ASSERT_TRUE(waitFor([&] { return readouts > 0; }, 30000));
        EXPECT_NEAR(window.planePanel()->readout().minimum, -0.8f, 0.03f);
        auto* radius = window.parametersPanel()->findChild<QDoubleSpinBox*>("number_radius");
        ASSERT_TRUE(radius);
        const int before = readouts;
        radius->setValue(0.4);
        ASSERT_TRUE(waitFor([&] { return readouts > before && window.planePanel()->readout().minimum > -0.5f; }, 30000))
            << "the readouts still describe radius 0.8: minimum " << window.planePanel()->readout().minimum;
        EXPECT_NEAR(window.planePanel()->readout().minimum, -0.4f, 0.03f);
        EXPECT_FALSE(window.editor()->isModified()) << "a parameter is not an edit of the text";
        window.close(); // saves the session
    }
    app::MainWindow again;
    again.show();
    ASSERT_TRUE(openAndWait(again, "Geometry/Sphere.glsl"));
    ASSERT_TRUE(waitFor([&] { return !again.parametersPanel()->values().empty(); }));
    EXPECT_FLOAT_EQ(again.parametersPanel()->values()[0].value[0], 0.4f);
    EXPECT_FLOAT_EQ(again.document()->input().params[0].value[0], 0.4f);
    again.parametersPanel()->resetAll();
    again.close();
}

// File > Export mesh: the unsaved text with its parameter values, meshed in a child; Cancel leaves
// nothing behind, a finished export is a watertight mesh of what the viewport shows.
TEST(MeshExport, ExportsTheUnsavedStateAndCancelsCleanly) {
    app::MainWindow window;
    window.show();
    ASSERT_TRUE(openAndWait(window, "../tests/params/iq_torus_map.glsl"));
    window.parametersPanel()->setValues({{"minorRadius", {0.1f}}});
    app::MeshExportController* exporter = window.meshExport();
    exporter->setExecutable(SDFWB_BINARY);
    exporter->showDialog();
    QDialog* dialog = exporter->dialog();
    ASSERT_TRUE(dialog);
    QTemporaryDir folder;
    const QString path = folder.filePath("torus.ply");
    dialog->findChild<QLineEdit*>("meshOutput")->setText(path);
    const jobs::MeshRequest request = exporter->request(path, 64);
    ASSERT_EQ(request.sdf.params.size(), 4u);
    EXPECT_EQ(request.sdf.params[1].value[0], 0.1f) << "the dock's value goes with the export";
    EXPECT_FALSE(request.sdf.source.empty()) << "the viewport's text, not the file";

    // Cancel a large export once it reports progress: no file, no temporary.
    bool done = false, ok = false, cancelled = false;
    quint64 progressed = 0;
    QObject::connect(exporter, &app::MeshExportController::progress,
                     [&](quint64 d, quint64) { progressed = std::max(progressed, d); });
    QObject::connect(exporter, &app::MeshExportController::finished, [&](bool good, bool stopped, const QString&) {
        done = true;
        ok = good;
        cancelled = stopped;
    });
    dialog->findChild<QSpinBox*>("meshResolution")->setValue(1024);
    dialog->findChild<QPushButton*>("meshExport")->click();
    ASSERT_TRUE(waitFor([&] { return progressed > 0 || done; }, 60000)) << "no progress from the mesh child";
    dialog->findChild<QPushButton*>("meshCancel")->click();
    ASSERT_TRUE(waitFor([&] { return done; }, 60000));
    EXPECT_TRUE(cancelled);
    EXPECT_FALSE(QFile::exists(path));
    EXPECT_TRUE(QDir(folder.path()).entryList(QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot).isEmpty()) << "no partial file";

    // A finished export at 64.
    done = false;
    dialog->findChild<QSpinBox*>("meshResolution")->setValue(64);
    dialog->findChild<QPushButton*>("meshExport")->click();
    ASSERT_TRUE(waitFor([&] { return done; }, 60000));
    const QString message = dialog->findChild<QLabel*>("meshMessage")->text();
    ASSERT_TRUE(ok) << message.toStdString();
    EXPECT_TRUE(QFile::exists(path));
    EXPECT_TRUE(message.contains("watertight")) << message.toStdString();
    EXPECT_TRUE(waitFor([&] { return window.viewport()->hasMeshOverlay(); })) << "the export shows over the surface";
    // The tube radius is the dock's 0.1: the file is no thicker than that.
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray bytes = file.readAll();
    const int header = bytes.indexOf("end_header\n") + 11;
    const int vertices = bytes.mid(bytes.indexOf("element vertex ") + 15, 12).split('\n').first().toInt();
    ASSERT_GT(vertices, 100);
    float maxY = 0.0f;
    for (int v = 0; v < vertices; ++v) {
        float p[3];
        std::memcpy(p, bytes.constData() + header + 12 * v, 12);
        maxY = std::max(maxY, std::abs(p[1]));
    }
    EXPECT_NEAR(maxY, 0.1f, 2e-3f);
}

// View > Show mesh deviation on a foreign mesh (a UV sphere written here, not by our mesher) over
// the Sphere: coloured per pixel by the field at the mesh, it stays grey where it lies on the
// surface, turns red when 10 % too large and blue when 10 % too small. A file that is not a mesh
// is refused with a message, and Hide brings the plain frame back.
TEST(MeshDeviation, ColoursAForeignMeshByItsDistanceFromTheField) {
    app::MainWindow window;
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Sphere.glsl"));
    QTemporaryDir folder;
    auto writeSphere = [&](const QString& name, float radius, int rings = 48) {
        const int segments = 2 * rings;
        QString text;
        for (int r = 0; r <= rings; ++r)
            for (int s = 0; s < segments; ++s) {
                const double theta = M_PI * r / rings, phi = 2.0 * M_PI * s / segments;
                text += QString("v %1 %2 %3\n")
                            .arg(radius * std::sin(theta) * std::cos(phi), 0, 'g', 9)
                            .arg(radius * std::cos(theta), 0, 'g', 9)
                            .arg(radius * std::sin(theta) * std::sin(phi), 0, 'g', 9);
            }
        for (int r = 0; r < rings; ++r)
            for (int s = 0; s < segments; ++s) {
                const int a = r * segments + s + 1, b = r * segments + (s + 1) % segments + 1;
                text += QString("f %1 %2 %3\nf %2 %4 %3\n").arg(a).arg(b).arg(a + segments).arg(b + segments);
            }
        const QString path = folder.filePath(name);
        QFile file(path);
        EXPECT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(text.toUtf8());
        return path;
    };
    // Pixels strongly red and strongly blue in `image` that were neither in the plain frame (the
    // tracer's own shading may have red or blue pixels of its own).
    auto strong = [](QColor c) {
        const bool red = c.red() > 60 && c.red() > 2 * c.green() && c.red() > 2 * c.blue();
        const bool blue = c.blue() > 60 && c.blue() > 2 * c.red() && c.blue() > 2 * c.green();
        return std::pair<bool, bool>{red, blue};
    };
    const QImage plain = frameOf(window);
    const long pixels = long(plain.width()) * plain.height();
    auto newColours = [&](const QImage& image) {
        std::pair<long, long> count{0, 0};
        EXPECT_EQ(image.size(), plain.size());
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const auto [red, blue] = strong(image.pixelColor(x, y));
                const auto [wasRed, wasBlue] = strong(plain.pixelColor(x, y));
                count.first += red && !wasRed;
                count.second += blue && !wasBlue;
            }
        return count;
    };

    ASSERT_TRUE(window.showMeshDeviation(writeSphere("on.obj", 0.8f)));
    EXPECT_TRUE(window.viewport()->hasMeshOverlay());
    EXPECT_GT(window.viewport()->meshOverlayScale(), 0.0f);
    const QImage onSurface = frameOf(window);
    EXPECT_GT(meanDifference(plain, onSurface), 1.0) << "the mesh is drawn";
    const auto [redOn, blueOn] = newColours(onSurface);
    EXPECT_LT(redOn + blueOn, pixels / 100) << "a mesh on the surface stays grey";

    ASSERT_TRUE(window.showMeshDeviation(writeSphere("large.obj", 0.88f)));
    const auto [redLarge, blueLarge] = newColours(frameOf(window));
    EXPECT_GT(redLarge, pixels / 20) << "outside the surface: red";
    EXPECT_LT(blueLarge, pixels / 100);

    ASSERT_TRUE(window.showMeshDeviation(writeSphere("small.obj", 0.72f)));
    const auto [redSmall, blueSmall] = newColours(frameOf(window));
    EXPECT_GT(blueSmall, pixels / 20) << "inside the surface: blue";
    EXPECT_LT(redSmall, pixels / 100);

    const QString bad = folder.filePath("bad.obj");
    {
        QFile file(bad);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write("this is not a mesh\n");
    }
    EXPECT_FALSE(window.showMeshDeviation(bad));
    EXPECT_TRUE(window.statusBar()->currentMessage().contains("bad.obj")) << window.statusBar()->currentMessage().toStdString();
    EXPECT_TRUE(window.viewport()->hasMeshOverlay()) << "the last overlay stays";

    window.hideMeshDeviation();
    EXPECT_FALSE(window.viewport()->hasMeshOverlay());
    EXPECT_LT(meanDifference(plain, frameOf(window)), 0.01) << "the plain frame is back";

    // A coarse sphere on the surface: its vertices lie on it (grey), its flat facets dip inside
    // towards their middles (blue). SDFWB_SCREENSHOT_DIR keeps the picture for the docs.
    ASSERT_TRUE(window.showMeshDeviation(writeSphere("coarse.obj", 0.8f, 14)));
    const auto [redCoarse, blueCoarse] = newColours(frameOf(window));
    EXPECT_LT(redCoarse, pixels / 100) << "the chords never leave the sphere";
    EXPECT_GT(blueCoarse, pixels / 200) << "facet middles lie inside";
    if (const char* folder = std::getenv("SDFWB_SCREENSHOT_DIR")) window.grab().save(QDir(folder).filePath("mesh_deviation.png"));
}

// ---- #19: the march debugger, sample clouds, the dataset browser, exports, the log ----

namespace {

QString screenshotPath(const char* name) {
    const char* folder = std::getenv("SDFWB_SCREENSHOT_DIR");
    return folder ? QDir(folder).filePath(name) : QString();
}

QPoint centreOf(QWidget* widget) { return QPoint(widget->width() / 2, widget->height() / 2); }

// The window as the screen shows it. QWidget::grab() draws the viewport's GL frame without what
// paintGL paints over it with QPainter (the probe's cross-hair, the name/author/license text), so
// the viewport's own framebuffer is laid over its place.
QImage windowShot(app::MainWindow& window) {
    QPixmap shot = window.grab();
    widgets::ViewportWidget* viewport = window.viewport();
    if (viewport->isVisible()) {
        QPainter painter(&shot);
        painter.drawImage(QRect(viewport->mapTo(&window, QPoint(0, 0)), viewport->size()), viewport->grabFramebuffer());
    }
    return shot.toImage();
}

// Shortcuts reach only the active window (keyboard focus is the window system's to give).
bool activate(QWidget& window) {
    window.activateWindow();
    if (!waitFor([&] { return window.isActiveWindow(); }, 3000)) QApplication::setActiveWindow(&window);
    return window.isActiveWindow();
}

// A mouse move with no button over `widget` (what hovering sends).
void hover(QWidget* widget, QPoint position) {
    QMouseEvent move(QEvent::MouseMove, position, widget->mapToGlobal(position), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(widget, &move);
}

} // namespace

// Tools > Probe pixel from its toolbar button, then clicks in the viewport: the dock shows the
// centre pixel's march ending in a hit on the sphere (table and plot), a corner pixel's miss, and
// the camera does not move. With the cutting plane on, hovering shows f and |grad f| under the
// cursor in the status bar, equal to the sphere's closed form at the position it names.
TEST(MarchDebugger, ClickingAPixelShowsItsMarchAndHoveringThePlaneShowsTheField) {
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Sphere.glsl"));
    window.probe()->setExecutable(SDFWB_BINARY);
    auto* bar = window.findChild<QToolBar*>("SdfToolBar");
    ASSERT_NE(bar, nullptr);
    QWidget* button = bar->widgetForAction(window.probeAction());
    ASSERT_NE(button, nullptr);
    QTest::mouseClick(button, Qt::LeftButton);
    ASSERT_TRUE(window.viewport()->probeTool());

    widgets::ViewportWidget* viewport = window.viewport();
    const renderer::Camera camera = viewport->camera();
    int probes = 0;
    QObject::connect(window.probe(), &app::ProbeController::probed, [&] { ++probes; });
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, centreOf(viewport));
    ASSERT_TRUE(waitFor([&] { return probes == 1; }, 30000)) << window.probePanel()->summary().toStdString();
    EXPECT_EQ(viewport->camera(), camera) << "a probe click does not orbit";
    {
        // The cross-hair: a yellow ring of radius 6 around the probed pixel.
        const QImage frame = frameOf(window);
        const QPoint centre = centreOf(viewport);
        int yellow = 0;
        for (int dy = -13; dy <= 13; ++dy)
            for (int dx = -13; dx <= 13; ++dx) {
                const QColor c = frame.pixelColor(centre + QPoint(dx, dy));
                yellow += c.red() > 200 && c.green() > 180 && c.blue() < 90;
            }
        EXPECT_GT(yellow, 20) << "the probed pixel is marked";
    }
    const widgets::ProbeView& hit = window.probePanel()->view();
    EXPECT_EQ(hit.outcome, "hit") << hit.reason.toStdString();
    EXPECT_EQ(hit.x, viewport->width() / 2);
    ASSERT_FALSE(hit.rows.empty());
    EXPECT_EQ(hit.rows.front().event, "step");
    EXPECT_TRUE(std::any_of(hit.rows.begin(), hit.rows.end(), [](const auto& r) { return r.event == "hit"; }));
    EXPECT_EQ(hit.oversteps, 0) << "an exact field never oversteps";
    ASSERT_TRUE(hit.hitT.has_value());
    // The hit lies on the sphere of radius 0.8: the distance from the camera along the ray.
    const auto& last = *std::find_if(hit.rows.begin(), hit.rows.end(), [](const auto& r) { return r.event == "hit"; });
    EXPECT_NEAR(glm::length(last.position), 0.8f, 2e-3f);
    EXPECT_EQ(window.probePanel()->table()->rowCount(), int(hit.rows.size()));
    EXPECT_GE(window.probePanel()->plot()->markerCount(), hit.steps);
    // Selecting a row (a click on its cell) rings it in the plot.
    const QRect cell = window.probePanel()->table()->visualItemRect(window.probePanel()->table()->item(1, 1));
    QTest::mouseClick(window.probePanel()->table()->viewport(), Qt::LeftButton, Qt::NoModifier, cell.center());
    EXPECT_EQ(window.probePanel()->table()->currentRow(), 1);
    if (QString path = screenshotPath("march_debugger.png"); !path.isEmpty()) windowShot(window).save(path);

    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, QPoint(2, 2));
    ASSERT_TRUE(waitFor([&] { return probes == 2; }, 30000));
    const widgets::ProbeView& miss = window.probePanel()->view();
    EXPECT_TRUE(miss.outcome == "missed the box" || miss.outcome == "left the box") << miss.outcome.toStdString();
    EXPECT_TRUE(window.probePanel()->summary().contains(miss.outcome));

    // The probe tool off: a drag orbits again.
    QTest::mouseClick(button, Qt::LeftButton);
    EXPECT_FALSE(viewport->probeTool());

    // The plane readout under the cursor.
    window.planePanel()->findChild<QPushButton*>("axis_Z")->click();
    ASSERT_TRUE(viewport->plane().enabled);
    frameOf(window);
    hover(viewport, centreOf(viewport) + QPoint(40, -25));
    const QString text = window.planeReadout()->text();
    ASSERT_TRUE(text.contains("f = ")) << text.toStdString();
    widgets::ViewportWidget::PlaneValue value;
    ASSERT_TRUE(viewport->planeValueAt(centreOf(viewport) + QPoint(40, -25), value));
    EXPECT_NEAR(value.position.z, 0.0f, 1e-4f) << "on the plane z = 0";
    EXPECT_NEAR(value.value, glm::length(value.position) - 0.8f, 1e-4f);
    EXPECT_NEAR(value.gradientLength, 1.0f, 1e-2f);
    EXPECT_TRUE(text.contains(QString::number(double(value.value), 'g', 5))) << text.toStdString();
    hover(viewport, QPoint(2, 2)); // off the plane (outside the box)
    EXPECT_TRUE(window.planeReadout()->text().isEmpty());
}

// The sampling dialog's Preview draws the run's first points in the viewport, coloured by
// gradient, and its point size spin box (arrow keys) grows them; a sample file with NaN rows
// shows its cloud with the bad rows counted, not drawn.
TEST(SampleCloud, PreviewDrawsTheRunAndAFileShowsItsCloudCountingNaNRows) {
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    window.sampling()->setExecutable(SDFWB_BINARY);
    // Gooch shading: under normals shading the front points' gradient colours match the surface.
    window.findChild<QAction*>("shading_gooch")->trigger();
    const QImage plain = frameOf(window);
    ASSERT_TRUE(activate(window));
    QTest::keyClick(&window, Qt::Key_M, Qt::ControlModifier | Qt::ShiftModifier);
    ASSERT_TRUE(waitFor([&] { return window.sampling()->dialog() && window.sampling()->dialog()->isVisible(); }));
    widgets::SamplingDialog* dialog = window.sampling()->dialog();
    auto* count = dialog->findChild<QLineEdit*>("count");
    count->selectAll();
    QTest::keyClicks(count, "20000");
    auto* pattern = dialog->findChild<QComboBox*>("pattern");
    pattern->lineEdit()->selectAll();
    QTest::keyClicks(pattern->lineEdit(), "surface");
    QTest::mouseClick(dialog->findChild<QPushButton*>("preview"), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return window.viewport()->pointCloudSize() > 0; }, 60000))
        << dialog->findChild<QLabel*>("message")->text().toStdString();
    EXPECT_EQ(window.viewport()->pointCloudSize(), 20000u) << "surface points on a torus all hit";
    const QImage small = frameOf(window);
    EXPECT_GT(meanDifference(plain, small), 1.0) << "the points are drawn";
    auto* size = dialog->findChild<QSpinBox*>("pointSize");
    const float before = window.viewport()->pointSize();
    for (int i = 0; i < 3; ++i) QTest::keyClick(size, Qt::Key_Up);
    EXPECT_FLOAT_EQ(window.viewport()->pointSize(), before + 3.0f);
    const QImage large = frameOf(window);
    EXPECT_GT(changedPixels(plain, large), changedPixels(plain, small) * 6 / 5) << "larger points cover more";
    dialog->close();
    if (QString path = screenshotPath("sample_cloud.png"); !path.isEmpty()) windowShot(window).save(path);

    // A file of 1000 rows, 37 of them NaN (as surface/near write misses).
    QTemporaryDir folder;
    sampling::SampleSet set;
    for (int i = 0; i < 1000; ++i) {
        const float angle = float(i) * 0.01f, nan = std::nanf("");
        const bool bad = i % 27 == 0;
        set.positions.insert(set.positions.end(), {bad ? nan : 0.5f * std::cos(angle), bad ? nan : 0.0f, 0.5f * std::sin(angle)});
        set.distances.push_back(bad ? nan : 0.0f);
        set.gradients.insert(set.gradients.end(), {std::cos(angle), 0.0f, std::sin(angle)});
    }
    const QString file = folder.filePath("cloud.npz");
    ASSERT_TRUE(sampling::writeSamples(file.toStdString(), sampling::SampleFormat::Npz, set, {}));
    auto loaded = window.clouds()->show(file);
    ASSERT_TRUE(loaded);
    EXPECT_EQ(loaded->rows, 1000u);
    EXPECT_EQ(loaded->badRows, 38u);
    EXPECT_EQ(loaded->drawn, 962u);
    EXPECT_EQ(window.viewport()->pointCloudSize(), 962u);
    EXPECT_TRUE(window.statusBar()->currentMessage().contains("38 NaN")) << window.statusBar()->currentMessage().toStdString();
    // A file that is not samples leaves the cloud as it was.
    const QString broken = folder.filePath("broken.npz");
    {
        QFile f(broken);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("not a zip");
    }
    EXPECT_FALSE(window.clouds()->show(broken));
    EXPECT_TRUE(window.statusBar()->currentMessage().contains("broken.npz"));
    EXPECT_EQ(window.viewport()->pointCloudSize(), 962u);
    window.clouds()->hide();
    EXPECT_EQ(window.viewport()->pointCloudSize(), 0u);
}

// Thumbnails are rendered once per file content (an edit renders a new one, an unchanged file
// none), the browser shows the report's measured type, "New SDF from template" opens the
// template, and a shipped file typed into is saved only under a new name: the shipped file keeps
// its bytes, and saving onto it is refused.
TEST(DatasetBrowser, ThumbnailsMeasuredTypesTemplateAndReadOnlyShippedFiles) {
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    QTemporaryDir cache, mine;
    window.thumbnails()->setExecutable(SDFWB_BINARY);
    window.thumbnails()->setCacheFolder(cache.path());
    const QStringList three = {datasetFile("Geometry/Sphere.glsl"), datasetFile("Geometry/Torus.glsl"),
                               datasetFile("Geometry/Box.glsl")};
    window.thumbnails()->request(three);
    ASSERT_TRUE(waitFor([&] { return window.datasetBrowser()->thumbnailCount() >= 3; }, 60000));
    EXPECT_EQ(window.thumbnails()->rendered(), 3);
    const QImage torus(window.datasetBrowser()->thumbnailOf(three[1]));
    ASSERT_EQ(torus.size(), QSize(96, 96));
    EXPECT_GT(foreground(torus, kBackground), 96 * 96 / 10) << "the thumbnail shows the shape";
    window.thumbnails()->request(three);
    EXPECT_EQ(window.thumbnails()->rendered(), 3) << "cached: nothing rendered again";
    // An SDF of the user's: edited, it gets a new thumbnail.
    const QString own = mine.filePath("own.glsl");
    auto write = [](const QString& path, const QByteArray& text) {
        QFile f(path);
        return f.open(QIODevice::WriteOnly) && f.write(text) == text.size();
    };
    ASSERT_TRUE(write(own, "float sdf(vec3 p) { return length(p) - 0.5; }\n"));
    window.thumbnails()->request({own});
    ASSERT_TRUE(waitFor([&] { return window.thumbnails()->rendered() == 4; }, 60000));
    const QString first = window.thumbnails()->cachedThumbnail(own);
    ASSERT_TRUE(write(own, "float sdf(vec3 p) { return length(p) - 0.9; }\n"));
    EXPECT_TRUE(window.thumbnails()->cachedThumbnail(own).isEmpty()) << "the old thumbnail is not this content's";
    window.thumbnails()->request({own});
    ASSERT_TRUE(waitFor([&] { return window.thumbnails()->rendered() == 5; }, 60000));
    EXPECT_NE(window.thumbnails()->cachedThumbnail(own), first);
    EXPECT_GT(foreground(QImage(window.thumbnails()->cachedThumbnail(own)), kBackground), foreground(QImage(first), kBackground))
        << "the larger sphere covers more";

    // Measured types and render times come from the dataset report (the layout
    // scripts/dataset_report.py writes): two entries measured, the rest shown as declared.
    const QString reportPath = mine.filePath("report.json");
    ASSERT_TRUE(write(reportPath, R"({"machine": "test machine", "date": "2026-11-24", "sdfs": [
        {"name": "Torus", "measured_type": "exact", "render_ms": 12.5},
        {"name": "Snail", "measured_type": "truncated", "render_ms": 242.6}]})"));
    window.loadDatasetItems(reportPath);
    int measuredRows = 0, declaredRows = 0;
    QTreeWidget* tree = window.datasetBrowser()->tree();
    for (int c = 0; c < tree->topLevelItemCount(); ++c)
        for (int i = 0; i < tree->topLevelItem(c)->childCount(); ++i) {
            QTreeWidgetItem* item = tree->topLevelItem(c)->child(i);
            if (item->text(0) == "Torus") {
                EXPECT_EQ(item->text(1), "exact");
                EXPECT_EQ(item->text(2), "12.5");
                ++measuredRows;
            } else if (item->text(0) == "Snail") {
                EXPECT_EQ(item->text(1), "truncated (declared conservative)") << "a disagreement is shown";
                EXPECT_EQ(item->text(2), "242.6");
                ++measuredRows;
            } else {
                EXPECT_TRUE(item->text(1).endsWith("(declared)")) << item->text(0).toStdString();
                EXPECT_TRUE(item->text(2).isEmpty());
                ++declaredRows;
            }
        }
    EXPECT_EQ(measuredRows, 2);
    EXPECT_EQ(declaredRows, window.datasetBrowser()->count() - 2);
    EXPECT_TRUE(window.datasetBrowser()->findChild<QLabel*>("reportNote")->text().contains("test machine"));

    // New SDF from template, by its button.
    window.findChild<QDockWidget*>("DatasetDock")->raise();
    QTest::mouseClick(window.datasetBrowser()->findChild<QPushButton*>("newFromTemplate"), Qt::LeftButton);
    EXPECT_TRUE(window.editor()->text().contains("name: New Shape"));
    EXPECT_TRUE(window.document()->path().isEmpty());
    if (QString path = screenshotPath("dataset_browser.png"); !path.isEmpty()) {
        window.thumbnails()->request(window.datasetBrowser()->paths());
        waitFor([&] { return window.datasetBrowser()->thumbnailCount() == window.datasetBrowser()->count(); }, 240000);
        windowShot(window).save(path);
    }
    window.files()->setPrompt([](const QString&) { return app::FileController::Answer::No; });

    // A shipped file: typed into, Ctrl+S asks for a new name in the user's folder.
    const QString shipped = datasetFile("Geometry/Torus.glsl");
    QFile original(shipped);
    ASSERT_TRUE(original.open(QIODevice::ReadOnly));
    const QByteArray bytes = original.readAll();
    original.close();
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    EXPECT_TRUE(window.windowTitle().contains("read-only"));
    window.editor()->setFocus();
    window.editor()->setCursorPosition(0, 0);
    QTest::keyClicks(window.editor(), "// ---"); // no word characters: no completion popup
    QTest::keyClick(window.editor(), Qt::Key_Return);
    ASSERT_TRUE(window.editor()->isModified());
    QString suggested;
    const QString target = mine.filePath("MyTorus.glsl");
    window.setSavePathChooser([&](const QString& path) {
        suggested = path;
        return target;
    });
    ASSERT_TRUE(activate(window));
    QTest::keyClick(window.editor(), Qt::Key_S, Qt::ControlModifier);
    ASSERT_TRUE(waitFor([&] { return QFile::exists(target); }, 5000)) << "Save asked for a new name";
    EXPECT_TRUE(suggested.endsWith("sdfwb/Torus.glsl")) << suggested.toStdString();
    EXPECT_FALSE(app::FileController::isShipped(suggested));
    QFile after(shipped);
    ASSERT_TRUE(after.open(QIODevice::ReadOnly));
    EXPECT_EQ(after.readAll(), bytes) << "the shipped file is untouched";
    QFile saved(target);
    ASSERT_TRUE(saved.open(QIODevice::ReadOnly));
    EXPECT_TRUE(saved.readAll().startsWith("// ---\n"));
    EXPECT_EQ(window.document()->path(), QFileInfo(target).absoluteFilePath());
    EXPECT_FALSE(window.files()->saveAs(shipped)) << "never onto a shipped file";
    QFile again(shipped);
    ASSERT_TRUE(again.open(QIODevice::ReadOnly));
    EXPECT_EQ(again.readAll(), bytes);
}

// A screenshot to .exr keeps values above 1 (an HDR background of (3, 2, 0.5) and Gooch's
// highlights), the overlay box darkens the lower-left corner, and a background image shows
// where rays miss.
TEST(Export, ExrKeepsValuesAboveOneBackgroundImageAndOverlay) {
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    window.setShadingMode(renderer::ShadingMode::Gooch);
    window.setBackgroundColour({3.0f, 2.0f, 0.5f});
    QTemporaryDir folder;
    const QString exr = folder.filePath("frame.exr");
    ASSERT_TRUE(window.exports()->saveScreenshot(exr, 320, 180).isEmpty());
    auto image = renderer::readFloatImage(exr.toStdString());
    ASSERT_TRUE(image);
    const float* corner = image->pixel(319, 0);
    EXPECT_NEAR(corner[0], 3.0f, 0.01f);
    EXPECT_NEAR(corner[1], 2.0f, 0.01f);
    EXPECT_NEAR(corner[2], 0.5f, 0.01f);
    float brightestShape = 0.0f;
    for (int y = 0; y < 180; ++y)
        for (int x = 0; x < 320; ++x)
            if (const float* p = image->pixel(x, y); std::abs(p[1] - 2.0f) > 0.05f)
                brightestShape = std::max(brightestShape, p[0]);
    EXPECT_GT(brightestShape, 1.0f) << "Gooch highlights above 1 are kept";

    // The overlay, turned on from the View menu's action.
    window.findChild<QAction*>("overlay")->trigger();
    ASSERT_FALSE(window.viewport()->overlayText().isEmpty());
    ASSERT_TRUE(window.exports()->saveScreenshot(exr, 320, 180).isEmpty());
    auto labelled = renderer::readFloatImage(exr.toStdString());
    ASSERT_TRUE(labelled);
    EXPECT_LT(labelled->pixel(6, 172)[0], 2.0f) << "the label's box darkens the corner";
    EXPECT_NEAR(labelled->pixel(319, 0)[0], 3.0f, 0.01f);

    // A background image (solid magenta) where rays miss.
    const QString magenta = folder.filePath("magenta.png");
    QImage fill(64, 32, QImage::Format_RGB32);
    fill.fill(QColor(255, 0, 255));
    ASSERT_TRUE(fill.save(magenta));
    window.setBackgroundImage(magenta);
    const QImage frame = frameOf(window);
    const QColor c = frame.pixelColor(frame.width() - 3, 3);
    EXPECT_GT(c.red(), 240);
    EXPECT_LT(c.green(), 15);
    EXPECT_GT(c.blue(), 240);
    if (QString path = screenshotPath("background_overlay.png"); !path.isEmpty()) windowShot(window).save(path);
}

// The Log dock shows the log file's lines: the GL context, compile times, the first full frame's
// time, and an error (a file that cannot be opened) in both the dock and the file.
TEST(LogDock, ShowsTheLogFileLines) {
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Box.glsl"));
    ASSERT_TRUE(waitFor([&] { return window.logPanel()->text().contains("first full frame"); }));
    const QString text = window.logPanel()->text();
    EXPECT_TRUE(text.contains("viewport context:")) << "GL vendor, renderer and version";
    EXPECT_TRUE(text.contains("compiled ")) << "shader compile times";
    EXPECT_FALSE(window.openFile("/nonexistent/broken.glsl"));
    ASSERT_TRUE(waitFor([&] { return window.logPanel()->text().contains("broken.glsl"); }));
    QFile file(window.logFilePath());
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QString logged = QString::fromUtf8(file.readAll());
    EXPECT_TRUE(logged.contains("[error] app:") && logged.contains("broken.glsl"));
    EXPECT_TRUE(logged.contains("first full frame"));
    // The filter: errors only.
    auto* level = window.logPanel()->findChild<QComboBox*>("logLevel");
    level->setFocus();
    QTest::keyClick(level, Qt::Key_Down);
    QTest::keyClick(level, Qt::Key_Down);
    EXPECT_EQ(level->currentIndex(), 2);
    EXPECT_FALSE(window.logPanel()->text().contains("compiled "));
    EXPECT_TRUE(window.logPanel()->text().contains("broken.glsl"));
    window.findChild<QDockWidget*>("LogDock")->raise();
    if (QString path = screenshotPath("log_dock.png"); !path.isEmpty()) windowShot(window).save(path);
}

int main(int argc, char** argv) {
    QStandardPaths::setTestModeEnabled(true); // no user settings read or written
    // Jobs the window starts on its own (thumbnails, probes) run the real sdfwb, never this binary.
    qputenv("SDFWB_BATCH_EXECUTABLE", SDFWB_BINARY);
    app::setDefaultSurfaceFormat();
    QApplication application(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}

// ---- #32: a whole Shadertoy shader, pasted as is ----

// A whole Shadertoy shader opens unmodified and sdfwb traces its map(); View > Shadertoy picture
// (its shortcut, a real key event) runs the file's own mainImage instead: the author's sky
// replaces sdfwb's background, a left drag sets iMouse as Shadertoy does (and moves the author's
// camera in a file that orbits with iMouse) without orbiting sdfwb's camera, and a file without
// mainImage turns the picture off and the action off. SDFWB_SCREENSHOT_DIR keeps
// shadertoy_pasted.png and shadertoy_picture.png for docs/foreign-code.md.
TEST(Shadertoy, PastedShaderTracesItsMapAndShowsItsOwnPicture) {
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(activate(window));
    auto open = [&](const QString& path) {
        bool applied = false;
        auto connection = QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
        const bool ok = window.openFile(path) && waitFor([&] { return applied; });
        QObject::disconnect(connection);
        return ok &&
               waitFor([&] { return window.viewport()->lastFrameMilliseconds() > 0.0 && !window.viewport()->isInteracting(); });
    };
    const QString corpus = QDir(SDFWB_SOURCE_DIR "/tests/foreign").absolutePath();
    ASSERT_TRUE(open(corpus + "/34_st_mouse_lattice.glsl"));
    EXPECT_EQ(window.document()->signature().entry, "map");
    EXPECT_TRUE(window.document()->lastGoodSource().shadertoyMainImage);
    auto* action = window.findChild<QAction*>("shadertoy_picture");
    ASSERT_NE(action, nullptr);
    EXPECT_TRUE(action->isEnabled());
    widgets::ViewportWidget* viewport = window.viewport();
    const QImage traced = fullResolutionFrame(window);
    if (QString path = screenshotPath("shadertoy_pasted.png"); !path.isEmpty()) windowShot(window).save(path);
    auto isBackground = [](QColor c) {
        return std::abs(c.redF() - kBackground.redF()) < 0.03 && std::abs(c.greenF() - kBackground.greenF()) < 0.03 &&
               std::abs(c.blueF() - kBackground.blueF()) < 0.03;
    };
    EXPECT_TRUE(isBackground(traced.pixelColor(2, 2))) << "sdfwb's tracer: its own background in the corner";

    QTest::keyClick(&window, Qt::Key_Y, Qt::ControlModifier | Qt::ShiftModifier);
    ASSERT_TRUE(viewport->shadertoyPicture()) << "the shortcut turns the picture on";
    EXPECT_TRUE(action->isChecked());
    const QImage picture = frameOf(window);
    EXPECT_FALSE(isBackground(picture.pixelColor(2, 2))) << "the author's picture has the author's background";
    EXPECT_GT(meanDifference(traced, picture), 10.0) << "the picture is not the tracer's frame";
    if (QString path = screenshotPath("shadertoy_picture.png"); !path.isEmpty()) windowShot(window).save(path);

    // A left drag: iMouse follows (pixels from the lower left, zw the press), the camera stays.
    const renderer::Camera camera = viewport->camera();
    const QPoint from = centreOf(viewport), to = from + QPoint(120, -40);
    QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, from);
    EXPECT_GT(viewport->shadertoyMouse().z, 0.0f) << "pressed: z is positive";
    QMouseEvent drag(QEvent::MouseMove, QPointF(to), viewport->mapToGlobal(QPointF(to)), Qt::NoButton, Qt::LeftButton,
                     Qt::NoModifier);
    QApplication::sendEvent(viewport, &drag);
    const qreal ratio = viewport->devicePixelRatioF();
    EXPECT_NEAR(viewport->shadertoyMouse().x, to.x() * ratio, 1.0);
    EXPECT_NEAR(viewport->shadertoyMouse().y, (viewport->height() - to.y()) * ratio, 1.0);
    EXPECT_NEAR(viewport->shadertoyMouse().z, from.x() * ratio, 1.0);
    QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, to);
    EXPECT_LT(viewport->shadertoyMouse().z, 0.0f) << "released: z is negative";
    EXPECT_EQ(viewport->camera(), camera) << "a drag in the picture does not orbit sdfwb's camera";
    EXPECT_GT(meanDifference(picture, frameOf(window)), 2.0) << "this file's author orbits with iMouse";

    // A file without mainImage: the tracer comes back, and the action cannot be turned on.
    ASSERT_TRUE(open(datasetFile("Geometry/Sphere.glsl")));
    EXPECT_FALSE(viewport->shadertoyPicture());
    EXPECT_FALSE(action->isChecked());
    EXPECT_FALSE(action->isEnabled());
    EXPECT_TRUE(isBackground(frameOf(window).pixelColor(2, 2)));
}
