// Exports: screenshots, MP4s, EXR, mesh export of the unsaved state, and the mesh deviation overlay.
// Under a real X server (Xvfb) with real input events; helpers in GuiTestSupport.h.

#include "GuiTestSupport.h"

using namespace sdfwb;
using namespace sdfwb::guitest;

namespace {

// Starts the video dialog's export with `settings` (a real click) and waits for its end: success,
// or a failure carrying the dialog's message.
::testing::AssertionResult exportVideo(app::MainWindow& window, const values::AnimateRequest& settings) {
    window.exports()->videoDialog()->setRequest(settings);
    bool done = false, ok = false;
    auto connection =
        QObject::connect(window.exports(), &app::ExportController::videoFinished, [&](bool success, const QString&) {
            done = true;
            ok = success;
        });
    window.exports()->videoDialog()->findChild<QPushButton*>("start")->click();
    const bool ended = waitFor([&] { return done; }, 60000);
    QObject::disconnect(connection);
    if (!ended) return ::testing::AssertionFailure() << "the export did not end within a minute";
    if (!ok)
        return ::testing::AssertionFailure()
               << window.exports()->videoDialog()->findChild<QLabel*>("message")->text().toStdString();
    return ::testing::AssertionSuccess();
}

} // namespace

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
    values::AnimateRequest settings;
    settings.output = mp4.toStdString();
    settings.frame.width = 160;
    settings.frame.height = 90;
    settings.seconds = 1.0f;
    settings.framesPerSecond = 10;
    settings.turntable = true;
    EXPECT_TRUE(exportVideo(window, settings));
    // FFmpeg's own reader decodes it: H.264, 160x90, 10 frames (1 s at 10 fps).
    QProcess probe;
    probe.start("ffprobe", {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                            "stream=codec_name,width,height,nb_read_frames", "-of", "csv=p=0", mp4});
    ASSERT_TRUE(probe.waitForFinished(30000));
    EXPECT_EQ(QString::fromUtf8(probe.readAllStandardOutput()).trimmed(), QString("h264,160,90,10"));
    window.grab().save(QDir::temp().filePath("sdfwb-gui-window.png"));
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
    values::ShadingSettings shading = window.viewport()->shading();
    shading.mode = shaders::ShadingMode::Gooch;
    shading.markers = {{0.55f, 0.55f, 0.55f}};
    window.viewport()->setShading(shading);
    values::TraceSettings trace = window.viewport()->trace();
    trace.maxSteps = 24; // few steps: the box's silhouette shows the budget
    trace.stepFactor = 0.6f;
    window.viewport()->setTrace(trace);
    values::CuttingPlane plane = window.document()->plane();
    plane.enabled = true;
    plane.normal = {0.3f, 0.2f, 1.0f};
    plane.offset = 0.2f;
    window.document()->setPlane(plane);
    EXPECT_TRUE(window.viewport()->plane() == plane) << "the viewport draws the document's plane";

    values::AnimateRequest settings;
    const QString mp4 = QDir::temp().filePath(QString("sdfwb-gui-state-%1.mp4").arg(QCoreApplication::applicationPid()));
    settings.output = mp4.toStdString();
    QFile::remove(mp4);
    settings.frame.width = 320;
    settings.frame.height = 200;
    settings.seconds = 0.1f;
    settings.framesPerSecond = 10;
    settings.turntable = true;
    const values::AnimateRequest request = window.exports()->videoRequest(settings);
    EXPECT_TRUE(request.frame.trace == trace);
    EXPECT_TRUE(request.frame.plane == plane);
    EXPECT_TRUE(request.frame.shading == shading);
    EXPECT_TRUE(request.frame.camera == window.viewport()->camera());
    // One frame-settings value: the viewport's, whole, in the video's and the probe's requests.
    const values::FrameSettings& view = window.viewport()->frameSettings();
    EXPECT_TRUE(view.shading == shading && view.trace == trace);
    EXPECT_TRUE(static_cast<const values::FrameSettings&>(request.frame) == view);
    EXPECT_TRUE(static_cast<const values::FrameSettings&>(window.probe()->request(10, 20, 320, 200).frame) == view);
    EXPECT_TRUE(window.probe()->request(10, 20, 320, 200).frame.plane == plane);
    EXPECT_NE(request.frame.sdf.source.find("vec3(0.55)"), std::string::npos) << "the export must run the editor's text";

    window.exports()->setExecutable(SDFWB_BINARY);
    window.exports()->showVideoDialog();
    ASSERT_TRUE(exportVideo(window, settings));

    // The video's first frame, decoded by the real FFmpeg.
    const QString decoded = mp4 + ".png";
    QProcess ffmpeg;
    ffmpeg.start("ffmpeg", {"-v", "error", "-y", "-i", mp4, "-frames:v", "1", decoded});
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
    window.document()->setPlane(plane);
    const QImage withoutPlane = screenshot("sdfwb-gui-state-noplane.png");
    window.viewport()->setTrace(values::TraceSettings{});
    shading.mode = shaders::ShadingMode::Normals;
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
    QFile::remove(mp4);
    QFile::remove(decoded);
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
    const values::MeshRequest request = exporter->request(path, 64);
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

    // A finished export at 64, refined once: four times the triangles of the same export unrefined.
    auto facesIn = [](const QByteArray& bytes) {
        return bytes.mid(bytes.indexOf("element face ") + 13, 12).split('\n').first().toLongLong();
    };
    done = false;
    dialog->findChild<QSpinBox*>("meshResolution")->setValue(64);
    dialog->findChild<QPushButton*>("meshExport")->click();
    ASSERT_TRUE(waitFor([&] { return done; }, 60000));
    ASSERT_TRUE(ok) << dialog->findChild<QLabel*>("meshMessage")->text().toStdString();
    qint64 coarseFaces = 0;
    {
        QFile coarse(path);
        ASSERT_TRUE(coarse.open(QIODevice::ReadOnly));
        coarseFaces = facesIn(coarse.readAll());
        ASSERT_GT(coarseFaces, 100);
    }
    done = false;
    dialog->findChild<QSpinBox*>("meshRefine")->setValue(1);
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
    EXPECT_EQ(facesIn(bytes), 4 * coarseFaces) << "refine 1 reached the child";
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

// A screenshot to .exr keeps values above 1 (an HDR background of (3, 2, 0.5) and Gooch's
// highlights), the overlay box darkens the lower-left corner, and a background image shows
// where rays miss.
TEST(Export, ExrKeepsValuesAboveOneBackgroundImageAndOverlay) {
    app::MainWindow window;
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(openAndWait(window, "Geometry/Torus.glsl"));
    window.setShadingMode(shaders::ShadingMode::Gooch);
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
