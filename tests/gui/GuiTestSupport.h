#pragma once
// What the workbench's GUI tests share: the includes, waiting on a condition (events processed
// meanwhile, never a bare sleep), frames and their comparison, opening a dataset file and waiting
// for it on screen, scratch files, window shots, activation and hovering.

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
#include <renderer/ImageIO.h>
#include <sampling/SampleFile.h>
#include <values/Requests.h>
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

namespace sdfwb::guitest {

inline bool waitFor(const std::function<bool()>& condition, int timeoutMilliseconds = 20000) {
    QElapsedTimer timer;
    timer.start();
    while (!condition()) {
        if (timer.elapsed() > timeoutMilliseconds) return false;
        QApplication::processEvents(QEventLoop::AllEvents, 50);
        QThread::msleep(10);
    }
    return true;
}

inline long foreground(const QImage& image, QColor background) {
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

inline const QColor kBackground = QColor::fromRgbF(0.16f, 0.17f, 0.19f);

inline QString datasetFile(const char* relative) { return QDir(SDFWB_SOURCE_DIR "/dataset").filePath(relative); }

inline QImage frameOf(app::MainWindow& window) {
    window.viewport()->update();
    return window.viewport()->grabFramebuffer();
}

// A frame at full resolution: a new slow-looking SDF's first frame, and frames right after a
// resize or a camera move, are drawn at a reduced scale and the full one follows.
inline QImage fullResolutionFrame(app::MainWindow& window) {
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

// Opens `path` and waits until the document has applied it (the viewport has its program).
inline bool openFileAndWait(app::MainWindow& window, const QString& path) {
    bool applied = false;
    auto connection = QObject::connect(window.document(), &app::SdfDocument::sdfApplied, [&] { applied = true; });
    const bool ok = window.openFile(path) && waitFor([&] { return applied; });
    QObject::disconnect(connection);
    return ok;
}

// Opens dataset `file` and waits until the viewport shows it at full scale.
inline bool openAndWait(app::MainWindow& window, const char* file) {
    // A slow-looking new SDF is first drawn at the moving scale: wait for the full frame after it.
    return openFileAndWait(window, datasetFile(file)) &&
           waitFor([&] { return window.viewport()->lastFrameMilliseconds() > 0.0 && !window.viewport()->isInteracting(); });
}

inline double meanDifference(const QImage& a, const QImage& b) {
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
inline long changedPixels(const QImage& a, const QImage& b) {
    long changed = 0;
    for (int y = 0; y < std::min(a.height(), b.height()); ++y)
        for (int x = 0; x < std::min(a.width(), b.width()); ++x) {
            QColor p = a.pixelColor(x, y), q = b.pixelColor(x, y);
            changed += std::abs(p.red() - q.red()) + std::abs(p.green() - q.green()) + std::abs(p.blue() - q.blue()) > 12;
        }
    return changed;
}

inline QString writeScratch(const QString& name, const QByteArray& text) {
    QDir folder(QDir::temp().filePath("sdfwb-gui-files"));
    folder.mkpath(".");
    QFile file(folder.filePath(name));
    file.open(QIODevice::WriteOnly | QIODevice::Truncate);
    file.write(text);
    return folder.filePath(name);
}

inline QByteArray readAll(const QString& path) {
    QFile file(path);
    file.open(QIODevice::ReadOnly);
    return file.readAll();
}

inline QString screenshotPath(const char* name) {
    const char* folder = std::getenv("SDFWB_SCREENSHOT_DIR");
    return folder ? QDir(folder).filePath(name) : QString();
}

inline QPoint centreOf(QWidget* widget) { return QPoint(widget->width() / 2, widget->height() / 2); }

// The window as the screen shows it. QWidget::grab() draws the viewport's GL frame without what
// paintGL paints over it with QPainter (the probe's cross-hair, the name/author/license text), so
// the viewport's own framebuffer is laid over its place.
inline QImage windowShot(app::MainWindow& window) {
    QPixmap shot = window.grab();
    widgets::ViewportWidget* viewport = window.viewport();
    if (viewport->isVisible()) {
        QPainter painter(&shot);
        painter.drawImage(QRect(viewport->mapTo(&window, QPoint(0, 0)), viewport->size()), viewport->grabFramebuffer());
    }
    return shot.toImage();
}

// Shortcuts reach only the active window (keyboard focus is the window system's to give).
inline bool activate(QWidget& window) {
    window.activateWindow();
    if (!waitFor([&] { return window.isActiveWindow(); }, 3000)) QApplication::setActiveWindow(&window);
    return window.isActiveWindow();
}

// A mouse move with no button over `widget` (what hovering sends).
inline void hover(QWidget* widget, QPoint position) {
    QMouseEvent move(QEvent::MouseMove, position, widget->mapToGlobal(position), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(widget, &move);
}

} // namespace sdfwb::guitest
