// The workbench window under a real X server (Xvfb): the default SDF is drawn by the same
// renderer as the batch path, and a typed error shows a diagnostic while the last good shape stays.

#include <gui/MainWindow.h>
#include <gui/SamplingController.h>
#include <gui/SdfDocument.h>
#include <widgets/SamplingDialog.h>
#include <widgets/GlslEditor.h>
#include <widgets/ViewportWidget.h>

#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QPushButton>
#include <QImage>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QThread>

#include <functional>

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
    long before = foreground(window.viewport()->grabFramebuffer(), kBackground);
    ASSERT_GT(before, 1000);

    int updates = diagnosticUpdates;
    QString text = window.editor()->text();
    text.replace("return length(p) - 0.8;", "return length(p) - radius;");
    window.editor()->setText(text);  // as if typed: goes through the debounce and the worker
    ASSERT_TRUE(waitFor([&] { return diagnosticUpdates > updates; }));
    EXPECT_GE(window.editor()->diagnosticCount(), 1);
    ASSERT_FALSE(window.document()->diagnostics().empty());
    EXPECT_NE(window.document()->diagnostics().front().message.find("radius"), std::string::npos);
    EXPECT_EQ(window.document()->diagnostics().front().line, 11);

    window.viewport()->update();
    long after = foreground(window.viewport()->grabFramebuffer(), kBackground);
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
    QObject::connect(sampling, &app::SamplingController::finished, [&](bool success, const QString&) { done = true; ok = success; });
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
    dialog->findChild<QPushButton*>("start")->click();
    ASSERT_TRUE(waitFor([&] { return sampling->isRunning(); }));
    QThread::msleep(1500);
    dialog->findChild<QPushButton*>("cancel")->click();
    ASSERT_TRUE(waitFor([&] { return done; }, 30000));
    EXPECT_FALSE(ok);
    EXPECT_TRUE(dialog->findChild<QLabel*>("message")->text().contains("Cancelled"));
    EXPECT_FALSE(QFile::exists(cancelled));
    QFile::remove(output);
}

int main(int argc, char** argv) {
    QStandardPaths::setTestModeEnabled(true);  // no user settings read or written
    QSurfaceFormat format;
    format.setVersion(4, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    QSurfaceFormat::setDefaultFormat(format);
    QApplication application(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
