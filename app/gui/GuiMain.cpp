#include "GuiMain.h"

#include "FileController.h"
#include "MainWindow.h"

#include <core/Log.h>
#include <core/Paths.h>
#include <dataset/Catalogue.h>

#include <QApplication>
#include <QMessageBox>
#include <QSurfaceFormat>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace sdfwb::app {

void setDefaultSurfaceFormat() {
    QSurfaceFormat format;
    format.setVersion(4, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(0);
    QSurfaceFormat::setDefaultFormat(format);
}

int runGui(int argc, char** argv, const char* file) {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    const char* platform = std::getenv("QT_QPA_PLATFORM");
    if ((!display || !*display) && (!wayland || !*wayland) && (!platform || !*platform)) {
        std::fprintf(stderr, "sdfwb: no display (DISPLAY is not set): the workbench needs a window system; "
                             "for headless work use sdfwb --batch (see sdfwb --help)\n");
        return 3;
    }
    if (file && !std::filesystem::is_regular_file(file)) {
        std::fprintf(stderr, "sdfwb: '%s': no such file\n", file);
        return 2;
    }

    setDefaultSurfaceFormat();
    QApplication application(argc, argv);
    QApplication::setOrganizationName("sdfwb");
    QApplication::setApplicationName("sdfwb");
    QApplication::setApplicationVersion(SDFWB_VERSION);

    MainWindow window;
    window.show();
    QString path;
    if (file) {
        path = QString::fromLocal8Bit(file);
    } else {
        dataset::Catalogue catalogue = dataset::Catalogue::scan(paths::datasetRoot());
        if (const dataset::Entry* entry = catalogue.find(dataset::kDefaultSdfName))
            path = QString::fromStdString(entry->path.string());
        else
            log::error("app", "default SDF '" + std::string(dataset::kDefaultSdfName) + "' not found in " +
                                  paths::datasetRoot().string());
    }
    if (!path.isEmpty()) window.openFile(path);
    // Unsaved work from a run that did not end cleanly (a crash, a kill): offer it back.
    QStringList recovery = FileController::recoveryFiles();
    if (!recovery.isEmpty()) {
        auto answer = QMessageBox::question(
            &window, QObject::tr("sdfwb"),
            QObject::tr("sdfwb did not close cleanly last time. Recover the unsaved text (%1 file(s))?").arg(recovery.size()));
        if (answer == QMessageBox::Yes) window.files()->restoreRecovery(recovery.first());
    }
    return application.exec();
}

} // namespace sdfwb::app
