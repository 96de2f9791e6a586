// The main window's menus: File, Edit, View (shading, tracing, the Shadertoy picture, overlays, docks,
// camera, playback) and Tools, and the recent-files list.

#include "MainWindow.h"

#include "CloudController.h"
#include "ExportController.h"
#include "FileController.h"
#include "JobWorker.h"
#include "MeshExportController.h"
#include "PlaneController.h"
#include "PlaybackController.h"
#include "ProbeController.h"
#include "SamplingController.h"
#include "SdfDocument.h"
#include "ThumbnailController.h"

#include <core/Log.h>
#include <core/TextFile.h>
#include <dataset/Metadata.h>
#include <jobs/Jobs.h>
#include <meshing/Mesh.h>
#include <widgets/CameraPanel.h>
#include <widgets/DatasetBrowser.h>
#include <widgets/GlslEditor.h>
#include <widgets/LogPanel.h>
#include <widgets/ParametersPanel.h>
#include <widgets/PlanePanel.h>
#include <widgets/ProbePanel.h>
#include <widgets/ProblemsPanel.h>
#include <widgets/SamplingDialog.h>

#include <core/Paths.h>
#include <shaders/SdfSource.h>

#include <QDir>
#include <QInputDialog>
#include <widgets/TimeBar.h>
#include <widgets/ViewportWidget.h>

#include <glm/geometric.hpp>

#include <QAction>
#include <QActionGroup>
#include <QColorDialog>
#include <QDateTime>
#include <QPointer>
#include <QStandardPaths>

#include <QApplication>
#include <QCloseEvent>
#include <QCompleter>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QRegularExpressionValidator>
#include <QSettings>
#include <QStatusBar>
#include <QStringListModel>
#include <QToolBar>
#include <array>
#include <fstream>
#include <memory>

namespace sdfwb::app {

namespace {

const shaders::ShadingMode kModes[] = {shaders::ShadingMode::Gooch, shaders::ShadingMode::Matcap, shaders::ShadingMode::Normals,
                                       shaders::ShadingMode::Curvature, shaders::ShadingMode::Steps};

QString modeLabel(shaders::ShadingMode mode) {
    switch (mode) {
    case shaders::ShadingMode::Gooch:
        return QObject::tr("&Gooch (warm/cool)");
    case shaders::ShadingMode::Matcap:
        return QObject::tr("&Matcap");
    case shaders::ShadingMode::Normals:
        return QObject::tr("&Normals as RGB");
    case shaders::ShadingMode::Curvature:
        return QObject::tr("&Curvature |H|");
    case shaders::ShadingMode::Steps:
        return QObject::tr("&Step-count heat map");
    }
    return {};
}

} // namespace

void MainWindow::updateRecentMenu() {
    m_recentMenu->clear();
    for (const QString& path : m_files->recentFiles())
        m_recentMenu->addAction(path, this, [this, path] {
            if (!m_document->isModified() || m_files->confirmClose()) m_files->load(path);
        });
    m_recentMenu->setEnabled(!m_recentMenu->isEmpty());
}

void MainWindow::createMenus() {
    createFileMenu();
    createEditMenu();
    createViewMenu();
    createToolsMenu();
}

void MainWindow::createFileMenu() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* create = file->addAction(tr("&New from template"), this, [this] {
        if (!m_document->isModified() || m_files->confirmClose()) m_files->newFromTemplate();
    });
    create->setShortcut(QKeySequence::New);
    QAction* open = file->addAction(tr("&Open..."), this, [this] {
        if (m_document->isModified() && !m_files->confirmClose()) return;
        QString path = QFileDialog::getOpenFileName(this, tr("Open SDF"), QString(),
                                                    tr("Shaders (*.glsl *.frag *.glslf *.fs *.fsh *.jxs);;All files (*)"));
        if (!path.isEmpty()) openFile(path);
    });
    open->setShortcut(QKeySequence::Open);
    // A triangle mesh as the SDF (meshfield/): traced, sliced, sampled and audited like GLSL.
    file->addAction(tr("Open &mesh..."), this, [this] {
        if (m_document->isModified() && !m_files->confirmClose()) return;
        QString path =
            QFileDialog::getOpenFileName(this, tr("Open a triangle mesh as an SDF"), QString(),
                                         tr("Meshes (*.obj *.ply *.stl *.off *.glb *.gltf *.fbx *.dae *.3ds);;All files (*)"));
        if (!path.isEmpty()) openFile(path);
    });
    m_recentMenu = file->addMenu(tr("Open &recent"));
    QAction* save = file->addAction(tr("&Save"), this, [this] {
        if (!m_files->save() && !m_document->isMesh()) saveAsWithDialog(); // a mesh's refusal says why
    });
    save->setShortcut(QKeySequence::Save);
    QAction* saveAs = file->addAction(tr("Save &as..."), this, &MainWindow::saveAsWithDialog);
    saveAs->setShortcut(QKeySequence::SaveAs);
    QAction* reload = file->addAction(tr("&Reload all shaders"), m_files, &FileController::reloadAll);
    reload->setShortcut(Qt::Key_F5);
    file->addSeparator();
    QAction* screenshot = file->addAction(tr("Save &screenshot..."), m_exports, &ExportController::showScreenshotDialog);
    screenshot->setShortcut(Qt::Key_F4);
    QAction* video = file->addAction(tr("Export &animation (MP4)..."), m_exports, &ExportController::showVideoDialog);
    file->addAction(tr("Export &mesh..."), m_meshExport, &MeshExportController::showDialog);
    video->setShortcut(Qt::Key_F6);
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
}

void MainWindow::createEditMenu() {
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* find = edit->addAction(tr("&Find..."), this, [this] {
        bool ok = false;
        QString text = QInputDialog::getText(this, tr("Find"), tr("Find:"), QLineEdit::Normal, m_lastSearch, &ok);
        if (ok && !text.isEmpty()) {
            m_lastSearch = text;
            if (!m_editor->findNext(text)) statusBar()->showMessage(tr("'%1' not found").arg(text), 3000);
        }
    });
    find->setShortcut(QKeySequence::Find);
    QAction* findNext = edit->addAction(tr("Find &next"), this, [this] {
        if (!m_lastSearch.isEmpty() && !m_editor->findNext(m_lastSearch))
            statusBar()->showMessage(tr("'%1' not found").arg(m_lastSearch), 3000);
    });
    findNext->setShortcut(QKeySequence::FindNext);
    QAction* replace = edit->addAction(tr("&Replace all..."), this, [this] {
        bool ok = false;
        QString text = QInputDialog::getText(this, tr("Replace"), tr("Find:"), QLineEdit::Normal, m_lastSearch, &ok);
        if (!ok || text.isEmpty()) return;
        QString with =
            QInputDialog::getText(this, tr("Replace"), tr("Replace '%1' with:").arg(text), QLineEdit::Normal, QString(), &ok);
        if (ok) statusBar()->showMessage(tr("%1 replacement(s)").arg(m_editor->replaceAll(text, with)), 3000);
    });
    replace->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_H));
    QAction* goTo = edit->addAction(tr("&Go to line..."), this, [this] {
        bool ok = false;
        int line = QInputDialog::getInt(this, tr("Go to line"), tr("Line:"), 1, 1, std::max(1, m_editor->lines()), 1, &ok);
        if (ok) m_editor->goToLine(line);
    });
    goTo->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
}

// Shading and tracing options, the Shadertoy picture, overlays, the docks, camera and playback.
void MainWindow::createViewMenu() {
    QMenu* view = menuBar()->addMenu(tr("&View"));
    QMenu* shadingMenu = view->addMenu(tr("&Shading"));
    m_shadingGroup = new QActionGroup(this);
    for (shaders::ShadingMode mode : kModes) {
        QAction* action = shadingMenu->addAction(modeLabel(mode));
        action->setCheckable(true);
        action->setData(int(mode));
        action->setObjectName(QString("shading_") + shaders::shadingModeName(mode));
        m_shadingGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, mode] { setShadingMode(mode); });
    }
    QMenu* matcaps = shadingMenu->addMenu(tr("Matcap &material"));
    for (const char* name : {"clay", "chrome", "jade", "wax"}) {
        matcaps->addAction(QString(name), this, [this, name] {
            values::ShadingSettings shading = m_viewport->shading();
            shading.matcap = name;
            m_viewport->setShading(shading);
            setShadingMode(shaders::ShadingMode::Matcap);
        });
    }
    m_aoAction = view->addAction(tr("&Ambient occlusion"), this, &MainWindow::setAmbientOcclusion);
    m_aoAction->setCheckable(true);
    m_aoAction->setObjectName("ambient_occlusion");
    QAction* relaxation = view->addAction(tr("Over-&relaxed tracing"), this, [this](bool on) {
        values::TraceSettings trace = m_viewport->trace();
        trace.overRelaxation = on ? 1.6f : 1.0f;
        m_viewport->setTrace(trace);
    });
    relaxation->setCheckable(true);
    // A choice among a trace setting's values, one checkable item each (objectName prefix + name).
    auto addChoices = [this, view](const QString& title, const QString& prefix, auto member, auto nameOf, auto choices) {
        QMenu* menu = view->addMenu(title);
        auto* group = new QActionGroup(this);
        for (auto [value, label] : choices) {
            QAction* action = menu->addAction(label, this, [this, member, value] {
                values::TraceSettings trace = m_viewport->trace();
                trace.*member = value;
                m_viewport->setTrace(trace);
            });
            action->setCheckable(true);
            action->setChecked(value == m_viewport->trace().*member);
            action->setObjectName(prefix + nameOf(value));
            group->addAction(action);
        }
    };
    // The cone pass and the compute tracer: tried at rest and kept when they make frames faster
    // (auto), or forced.
    using Cones = values::TraceSettings::Cones;
    using Tracer = values::TraceSettings::Tracer;
    addChoices(tr("&Cone pass"), "cones_", &values::TraceSettings::cones, values::conesName,
               std::array{std::pair{Cones::Auto, tr("&Automatic (kept when faster)")}, std::pair{Cones::On, tr("&On")},
                          std::pair{Cones::Off, tr("O&ff")}});
    addChoices(tr("&Tracer"), "tracer_", &values::TraceSettings::tracer, values::tracerName,
               std::array{std::pair{Tracer::Auto, tr("&Automatic (compute shader kept when faster)")},
                          std::pair{Tracer::Fragment, tr("&Fragment shader")},
                          std::pair{Tracer::Compute, tr("&Compute shader (not with the cutting plane)")}});
    m_overlayAction = view->addAction(tr("Show name, author and &license"), this, [this] { updateOverlay(); });
    m_overlayAction->setCheckable(true);
    m_overlayAction->setObjectName("overlay");
    view->addSeparator();
    addShadertoyItems(view);
    addOverlayItems(view);
    view->addSeparator();
    view->addAction(m_editorDock->toggleViewAction());
    view->addAction(m_viewportDock->toggleViewAction());
    view->addAction(m_cameraDock->toggleViewAction());
    view->addAction(m_timeDock->toggleViewAction());
    view->addAction(m_planeDock->toggleViewAction());
    view->addAction(m_problemsDock->toggleViewAction());
    view->addAction(m_browserDock->toggleViewAction());
    view->addAction(m_parametersDock->toggleViewAction());
    view->addAction(m_probeDock->toggleViewAction());
    view->addAction(m_logDock->toggleViewAction());
    view->addSeparator();
    QAction* reset = view->addAction(tr("&Reset camera"), m_viewport, &widgets::ViewportWidget::resetCamera);
    reset->setShortcut(Qt::Key_Home);
    QAction* play = view->addAction(tr("&Play / pause"), this, [this] { m_playback->setPlaying(!m_playback->isPlaying()); });
    play->setShortcut(Qt::Key_F8);
}

// The file's own mainImage in place of the tracer, and the images of its channels.
void MainWindow::addShadertoyItems(QMenu* view) {
    // A whole Shadertoy shader's own picture (its mainImage) in place of the tracer, to compare.
    m_shadertoyAction = view->addAction(tr("Shadertoy &picture"), this, [this](bool on) {
        auto diagnostics = m_viewport->setShadertoyPicture(on);
        for (const shaders::Diagnostic& d : diagnostics)
            if (d.severity == shaders::Severity::Error) {
                statusBar()->showMessage(QString::fromStdString(d.message), 8000);
                break;
            }
        m_shadertoyAction->setChecked(m_viewport->shadertoyPicture());
    });
    m_shadertoyAction->setCheckable(true);
    m_shadertoyAction->setObjectName("shadertoy_picture");
    m_shadertoyAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Y));
    m_shadertoyAction->setToolTip(tr("Run the file's own mainImage (a whole Shadertoy shader) with the scene time and a mouse "
                                     "(left drag): the author's picture beside sdfwb's tracer"));
    QMenu* channels = view->addMenu(tr("Shadertoy c&hannels"));
    for (int n = 0; n < shaders::kShadertoyChannels; ++n) {
        QAction* pick = channels->addAction(tr("iChannel%1: image...").arg(n), this, [this, n] {
            const QString path = QFileDialog::getOpenFileName(this, tr("Image for iChannel%1").arg(n), QString(),
                                                              tr("Images (*.png *.jpg *.jpeg *.exr *.tif *.bmp);;All files (*)"));
            if (path.isEmpty()) return;
            m_document->setChannel(n, path);
            m_document->checkNow(m_document->text());
        });
        pick->setObjectName(QString("channel_%1").arg(n));
    }
    channels->addAction(tr("All channels: &noise texture"), this, [this] {
        for (int n = 0; n < shaders::kShadertoyChannels; ++n) m_document->setChannel(n, QString());
        m_document->checkNow(m_document->text());
    });
}

// Meshes, sample clouds and the background over the surface.
void MainWindow::addOverlayItems(QMenu* view) {
    view->addSeparator();
    view->addAction(tr("Show mesh &deviation..."), this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Mesh to grade against the field"), QString(),
                                                          tr("Meshes (*.ply *.obj *.stl *.glb *.gltf *.off);;All files (*)"));
        if (!path.isEmpty()) showMeshDeviation(path);
    });
    m_hideMeshAction = view->addAction(tr("&Hide mesh deviation"), this, &MainWindow::hideMeshDeviation);
    m_hideMeshAction->setEnabled(false);
    view->addAction(tr("Show sample &cloud..."), this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Sample file to show over the surface"), QString(),
                                                          tr("Samples (*.npz *.bin *.ply);;All files (*)"));
        if (!path.isEmpty()) (void)m_clouds->show(path);
    });
    view->addAction(tr("Hide sample c&loud"), m_clouds, &CloudController::hide);
    view->addAction(tr("Sample cloud point si&ze..."), this, [this] {
        bool ok = false;
        const int size = QInputDialog::getInt(this, tr("Point size"), tr("Pixels:"), int(m_viewport->pointSize()), 1, 32, 1, &ok);
        if (ok) m_viewport->setPointSize(float(size));
    });
    view->addSeparator();
    view->addAction(tr("Background &colour..."), this, [this] {
        const glm::vec3 b = m_viewport->shading().background;
        const QColor colour = QColorDialog::getColor(
            QColor::fromRgbF(std::min(b.r, 1.0f), std::min(b.g, 1.0f), std::min(b.b, 1.0f)), this, tr("Background colour"));
        if (colour.isValid()) setBackgroundColour({float(colour.redF()), float(colour.greenF()), float(colour.blueF())});
    });
    view->addAction(tr("Background &image..."), this, [this] {
        const QString path =
            QFileDialog::getOpenFileName(this, tr("Background image"), QString(), tr("Images (*.png *.jpg *.jpeg *.exr *.tif)"));
        if (!path.isEmpty()) setBackgroundImage(path);
    });
    view->addAction(tr("No background ima&ge"), this, [this] { setBackgroundImage({}); });
}

void MainWindow::createToolsMenu() {
    QMenu* tools = menuBar()->addMenu(tr("&Tools"));
    QAction* sample = tools->addAction(tr("&Sample SDF..."), m_sampling, &SamplingController::showDialog);
    sample->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_M));
    m_probeAction = tools->addAction(tr("&Probe pixel (march debugger)"), this, [this](bool on) {
        m_viewport->setProbeTool(on);
        if (on) {
            m_probeDock->show();
            m_probeDock->raise();
            statusBar()->showMessage(tr("Click a pixel in the viewport: its whole march appears in the March debugger dock"),
                                     8000);
        }
    });
    m_probeAction->setObjectName("probeTool");
    m_probeAction->setCheckable(true);
    m_probeAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
    if (auto* bar = findChild<QToolBar*>("SdfToolBar")) bar->addAction(m_probeAction);
}

} // namespace sdfwb::app
