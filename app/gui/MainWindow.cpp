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
#include <renderer/SdfRenderer.h>
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
#include <fstream>
#include <memory>

namespace sdfwb::app {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setObjectName("MainWindow");
    setDockNestingEnabled(true);
    resize(1400, 860);

    createDocks();
    createControllers();
    createEntryToolBar();
    connectFilesAndEditor();
    loadCompletions();
    connectDocument();
    connectParameters();
    createStatusBar();
    createMenus();
    updateRecentMenu();
    restoreSession();
    updateTitle();
}

// The widgets, each in a dock, and the docks' first layout.
void MainWindow::createDocks() {
    m_viewport = new widgets::ViewportWidget;
    m_viewport->setObjectName("Viewport");
    m_editor = new widgets::GlslEditor;
    m_editor->setObjectName("Editor");
    m_cameraPanel = new widgets::CameraPanel;
    m_timeBar = new widgets::TimeBar;
    m_planePanel = new widgets::PlanePanel;
    m_problems = new widgets::ProblemsPanel;
    m_browser = new widgets::DatasetBrowser;
    m_parametersPanel = new widgets::ParametersPanel;
    m_probePanel = new widgets::ProbePanel;
    m_logPanel = new widgets::LogPanel;
    m_viewportDock = addDock(tr("Viewport"), "ViewportDock", m_viewport, Qt::RightDockWidgetArea);
    m_editorDock = addDock(tr("Editor"), "EditorDock", m_editor, Qt::LeftDockWidgetArea);
    m_cameraDock = addDock(tr("Camera"), "CameraDock", m_cameraPanel, Qt::LeftDockWidgetArea);
    m_timeDock = addDock(tr("Time"), "TimeDock", m_timeBar, Qt::RightDockWidgetArea);
    m_planeDock = addDock(tr("Cutting plane"), "PlaneDock", m_planePanel, Qt::LeftDockWidgetArea);
    m_problemsDock = addDock(tr("Problems"), "ProblemsDock", m_problems, Qt::LeftDockWidgetArea);
    m_browserDock = addDock(tr("Dataset"), "DatasetDock", m_browser, Qt::LeftDockWidgetArea);
    m_parametersDock = addDock(tr("Parameters"), "ParametersDock", m_parametersPanel, Qt::LeftDockWidgetArea);
    m_probeDock = addDock(tr("March debugger"), "ProbeDock", m_probePanel, Qt::LeftDockWidgetArea);
    m_logDock = addDock(tr("Log"), "LogDock", m_logPanel, Qt::BottomDockWidgetArea);
    setUpLog();
    loadDatasetItems(QString::fromStdString((paths::datasetRoot() / "report.json").string()));
    splitDockWidget(m_editorDock, m_problemsDock, Qt::Vertical);
    resizeDocks({m_editorDock, m_problemsDock}, {640, 120}, Qt::Vertical);
    m_timeBar->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    splitDockWidget(m_viewportDock, m_timeDock, Qt::Vertical);
    tabifyDockWidget(m_editorDock, m_cameraDock);
    tabifyDockWidget(m_cameraDock, m_planeDock);
    tabifyDockWidget(m_planeDock, m_browserDock);
    tabifyDockWidget(m_browserDock, m_parametersDock);
    tabifyDockWidget(m_parametersDock, m_probeDock);
    tabifyDockWidget(m_problemsDock, m_logDock);
    m_problemsDock->raise();
    m_editorDock->raise();
    resizeDocks({m_editorDock, m_viewportDock}, {560, 840}, Qt::Horizontal);
}

// The document and the controllers that run jobs on it.
void MainWindow::createControllers() {
    m_document = new SdfDocument(this);
    // The document knows no view: the viewport draws what it emits and tells it what it drew.
    m_document->setTime(m_viewport->time());
    m_document->setPlane(m_viewport->plane());
    m_document->setTracerFeatures([this](const values::CuttingPlane& plane) {
        return renderer::tracerFeatures(m_viewport->shading(), m_viewport->trace(), plane);
    });
    connect(m_document, &SdfDocument::sdfReady, this,
            [this](const shaders::PreparedSdf& prepared) { m_document->driverCompiled(m_viewport->setSdf(prepared)); });
    connect(m_document, &SdfDocument::timeChanged, m_viewport, &widgets::ViewportWidget::setTime);
    connect(m_document, &SdfDocument::planeChanged, this, [this](const values::CuttingPlane& plane) {
        if (!(m_viewport->plane() == plane)) m_viewport->setPlane(plane); // not back after a drag in the viewport
    });
    connect(m_document, &SdfDocument::parameterValuesChanged, m_viewport, &widgets::ViewportWidget::setParameters);
    connect(m_viewport, &widgets::ViewportWidget::sdfTimed, m_document, &SdfDocument::shownSdfTimed);
    connect(m_viewport, &widgets::ViewportWidget::sdfReverted, m_document, &SdfDocument::shownSdfStalled);
    connect(m_viewport, &widgets::ViewportWidget::planeDragged, m_document, &SdfDocument::setPlane); // Ctrl + drag
    // Every job (sampling, video, plane readouts, probes) runs on the document's input: the text the
    // viewport shows (saved or not), its path for includes, its entry point; and its time and plane.
    auto currentSdf = [this] { return m_document->input(); };
    m_sampling = new SamplingController(this, currentSdf, this);
    m_exports = new ExportController(this, m_viewport, m_document, this);
    m_meshExport = new MeshExportController(this, currentSdf, this);
    connect(m_meshExport, &MeshExportController::meshWritten, this, &MainWindow::showMeshDeviation);
    m_playback = new PlaybackController(m_timeBar, m_document, this);
    // Plane readouts and probes: one persistent worker process (started at the first request).
    m_worker = new JobWorker(this);
    m_plane = new PlaneController(m_planePanel, m_viewport, m_document, m_worker, this);
    m_files = new FileController(this, m_editor, m_document, m_viewport, this);
    m_probe = new ProbeController(m_probePanel, m_viewport, m_document, m_worker, this);
    connect(m_probe, &ProbeController::probed, this, [this] {
        m_probeDock->show();
        m_probeDock->raise();
    });
    m_clouds = new CloudController(m_viewport, this);
    connect(m_clouds, &CloudController::message, this, [this](const QString& text) { statusBar()->showMessage(text, 15000); });
    connect(m_sampling, &SamplingController::cloudReady, this, [this](const QString& path) { (void)m_clouds->show(path); });
    connect(m_sampling, &SamplingController::pointSizeChanged, this,
            [this](int pixels) { m_viewport->setPointSize(float(pixels)); });
    m_thumbnails = new ThumbnailController(this);
    connect(m_thumbnails, &ThumbnailController::thumbnailReady, m_browser, &widgets::DatasetBrowser::setThumbnail);
    // Thumbnails are made when the browser is first looked at (cached after that).
    connect(m_browserDock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible) m_thumbnails->request(m_browser->paths());
    });
    connect(m_browser, &widgets::DatasetBrowser::newRequested, this, [this] {
        if (!m_document->isModified() || m_files->confirmClose()) m_files->newFromTemplate();
    });
}

// The SDF tool bar: the entry point's field.
void MainWindow::createEntryToolBar() {
    QToolBar* bar = addToolBar(tr("SDF"));
    bar->setObjectName("SdfToolBar");
    bar->addWidget(new QLabel(tr(" Entry point: ")));
    m_entry = new QLineEdit;
    m_entry->setObjectName("entry");
    m_entry->setMaximumWidth(220);
    m_entry->setPlaceholderText(tr("automatic"));
    m_entry->setToolTip(
        tr("The function that is the SDF: float NAME(vec3 p) or NAME(vec3 p, float time), or vec2/vec4 NAME(...) with the "
           "distance in .x. Empty: the file's `entry:` metadata, else sdf, else map, scene, sceneSDF, sdScene, de or DE."));
    m_entry->setValidator(new QRegularExpressionValidator(QRegularExpression("[A-Za-z_][A-Za-z0-9_]*"), m_entry));
    bar->addWidget(m_entry);
    connect(m_entry, &QLineEdit::editingFinished, this, [this] {
        if (m_entry->text() == m_document->entry()) return;
        m_document->setEntry(m_entry->text());
        m_document->checkNow(m_editor->text());
    });
}

// Files, the dataset browser and the Problems panel to the editor.
void MainWindow::connectFilesAndEditor() {
    connect(m_files, &FileController::pathChanged, this, [this] {
        m_entry->setText(m_document->entry());
        updateTitle();
        updateRecentMenu();
    });
    connect(m_files, &FileController::message, this, [this](const QString& text) { statusBar()->showMessage(text, 5000); });
    // The document owns the modified flag: the editor's undo history moves it; a save or a load
    // clears it (FileController), and the editor's save point with it.
    connect(m_editor, &QsciScintilla::modificationChanged, m_document, &SdfDocument::setModified);
    connect(m_document, &SdfDocument::modifiedChanged, this, [this](bool modified) {
        if (!modified && m_editor->isModified()) m_editor->setModified(false);
        updateTitle();
    });
    connect(m_browser, &widgets::DatasetBrowser::openRequested, this, [this](const QString& path) {
        if (!m_document->isModified() || m_files->confirmClose()) m_files->load(path);
    });
    connect(m_problems, &widgets::ProblemsPanel::locationActivated, this, [this](const QString& file, int line, int column) {
        bool here = file == m_document->path() || (m_document->path().isEmpty() && file == "<editor>");
        if (!here && QFileInfo::exists(file)) {
            if (m_document->isModified() && !m_files->confirmClose()) return;
            m_files->load(file);
        }
        m_editor->goToLine(line, column);
    });
    // What a job reports (a sampler file's error, a stage the editor's check does not compile) joins
    // the document's diagnostics, named by the job, until that job's next request ends.
    const std::pair<QString, JobClient*> jobs[] = {{tr("Sampling"), m_sampling->jobClient()},
                                                   {tr("Video export"), m_exports->jobClient()},
                                                   {tr("Mesh export"), m_meshExport->jobClient()},
                                                   {tr("Plane"), m_plane->jobClient()},
                                                   {tr("Probe"), m_probe->jobClient()}};
    for (const auto& [name, client] : jobs)
        connect(client, &JobClient::diagnosticsReported, this, [this, name](const std::vector<shaders::Diagnostic>& diagnostics) {
            m_problems->setJobDiagnostics(name, diagnostics);
            if (diagnostics.empty()) return;
            m_problemsDock->show();
            m_problemsDock->raise();
        });
}

// Completion: the helper libraries' functions once, the file's own after each check.
void MainWindow::loadCompletions() {
    QStringList librarySignatures;
    for (const QString& folder : {QString::fromStdString(paths::shaderLibraryRoot().string()),
                                  QString::fromStdString((paths::datasetRoot() / "lib").string())})
        for (const QFileInfo& info : QDir(folder).entryInfoList({"*.glsl"}, QDir::Files)) {
            auto text = readTextFile(info.absoluteFilePath().toStdString());
            if (text)
                for (const std::string& signature : shaders::functionSignatures(*text))
                    librarySignatures << QString::fromStdString(signature);
        }
    m_librarySignatures = librarySignatures;
    m_editor->setCompletionFunctions(m_librarySignatures, {});
}

// The document's checks to the editor, the Problems panel, the tool bar and the plane.
void MainWindow::connectDocument() {
    connect(m_editor, &QsciScintilla::textChanged, this, [this] {
        m_document->textEdited(m_editor->text());
        updateTitle();
    });
    connect(m_document, &SdfDocument::sdfApplied, this, &MainWindow::updateTitle); // the frame is decided with the check
    connect(m_document, &SdfDocument::diagnosticsChanged, this, [this](const std::vector<shaders::Diagnostic>& diagnostics) {
        QString path = m_document->path().isEmpty() ? QString("<editor>") : m_document->path();
        m_editor->setDiagnostics(diagnostics, path);
        int errors = 0, warnings = 0;
        for (const auto& d : diagnostics) (d.severity == shaders::Severity::Error ? errors : warnings)++;
        m_diagnosticSummary->setText(
            errors ? tr("%1 error(s), %2 warning(s): showing the last good shader").arg(errors).arg(warnings)
                   : tr("%1 warning(s)").arg(warnings));
        m_problems->setDiagnostics(diagnostics);
    });
    connect(m_document, &SdfDocument::sdfApplied, this, &MainWindow::updateOverlay);
    connect(m_document, &SdfDocument::sdfApplied, this, [this] {
        // Shows what "automatic" chose, and how its value is read.
        const shaders::SdfSignature& s = m_document->signature();
        const std::string& reason = m_document->lastGoodSource().entryReason; // a whole shader's march chose it
        m_entry->setPlaceholderText(tr("automatic: %1%2")
                                        .arg(QString::fromStdString(reason.empty() ? s.entry : reason),
                                             !s.member.empty()         ? QString(" (.%1)").arg(QString::fromStdString(s.member))
                                             : s.returnType == "float" ? QString()
                                                                       : QString(" (.x)")));
        // Another host's shader (glslViewer, Bonzomatic, Fragmentarium, ...): say how it was read.
        const std::string& host = m_document->lastGoodSource().host;
        if (!host.empty())
            statusBar()->showMessage(tr("Read as %1").arg(QString::fromStdString(shaders::hostDescription(host))), 8000);
    });
    // A whole shader whose march steps by two functions equally often: the entry box lists them.
    connect(m_document, &SdfDocument::entryCandidatesChanged, this, [this](const QStringList& names) {
        // One completer, made the first time, whose list follows the checks.
        auto* completer = m_entry->findChild<QCompleter*>("entry_choices");
        if (!completer) {
            completer = new QCompleter(new QStringListModel(m_entry), m_entry);
            completer->setObjectName("entry_choices");
            completer->setCompletionMode(QCompleter::UnfilteredPopupCompletion);
        }
        static_cast<QStringListModel*>(completer->model())->setStringList(names);
        m_entry->setCompleter(names.isEmpty() ? nullptr : completer);
        if (!names.isEmpty()) m_entry->setPlaceholderText(tr("choose: %1").arg(names.join(", ")));
    });
    connect(m_document, &SdfDocument::signaturesChanged, this,
            [this](const QStringList& signatures) { m_editor->setCompletionFunctions(m_librarySignatures, signatures); });
    connect(m_document, &SdfDocument::sdfApplied, m_plane, &PlaneController::refresh);
    // The picture switches off when the file loses its mainImage; a file with one may turn it on.
    connect(m_document, &SdfDocument::sdfApplied, this, [this] {
        m_shadertoyAction->setEnabled(m_document->lastGoodSource().shadertoyMainImage || m_viewport->shadertoyPicture());
        m_shadertoyAction->setChecked(m_viewport->shadertoyPicture());
    });
}

// Parameters: the declarations of the SDF on screen become controls; their values are uniforms
// of the viewport (no recompile) and of every job started from the document.
void MainWindow::connectParameters() {
    connect(m_document, &SdfDocument::sdfApplied, this, [this] {
        m_parametersPanel->setDeclarations(m_document->lastGoodSource().parameters);
        if (!m_sessionParameterValues.isEmpty() && m_sessionParameterFile == m_document->path()) {
            std::vector<shaders::ParameterValue> values;
            for (const QString& text : m_sessionParameterValues)
                if (auto value = shaders::parseParameterValue(text.toStdString())) values.push_back(std::move(*value));
            m_parametersPanel->setValues(values);
        }
        m_sessionParameterValues.clear();
        if (m_parametersPanel->values() != m_document->parameterValues())
            m_document->setParameterValues(m_parametersPanel->values());
    });
    connect(m_parametersPanel, &widgets::ParametersPanel::valuesChanged, this, [this] {
        m_document->setParameterValues(m_parametersPanel->values());
        m_plane->scheduleRefresh();
    });
    connect(m_parametersPanel, &widgets::ParametersPanel::saveDefaultsRequested, this, [this] {
        // Rewrites the initializers in the editor (one undo step); the file is saved as usual.
        const std::string text = m_editor->text().toStdString();
        const shaders::ParameterScan scan = shaders::parseParameters(text, "<editor>");
        const std::string saved = shaders::withDefaults(text, scan.parameters, m_parametersPanel->values());
        if (saved == text) return;
        m_editor->beginUndoAction();
        m_editor->selectAll();
        m_editor->replaceSelectedText(QString::fromStdString(saved));
        m_editor->endUndoAction();
        statusBar()->showMessage(tr("Parameter values written into the initializers (Ctrl+Z undoes it)"), 5000);
    });
}

// The camera panel, and the status bar's readouts: diagnostics, plane hover, precision, frame time.
void MainWindow::createStatusBar() {
    m_exports->setClipEnd([this] { return m_parametersPanel->clipEnd(); });
    connect(m_cameraPanel, &widgets::CameraPanel::cameraEdited, m_viewport, &widgets::ViewportWidget::setCamera);
    connect(m_cameraPanel, &widgets::CameraPanel::resetRequested, m_viewport, &widgets::ViewportWidget::resetCamera);
    connect(m_viewport, &widgets::ViewportWidget::cameraChanged, m_cameraPanel, &widgets::CameraPanel::setCamera);

    m_frameTime = new QLabel(this);
    m_diagnosticSummary = new QLabel(this);
    statusBar()->addWidget(m_diagnosticSummary, 1);
    m_planeReadout = new QLabel(this);
    m_planeReadout->setObjectName("planeReadout");
    statusBar()->addPermanentWidget(m_planeReadout);
    connect(m_viewport, &widgets::ViewportWidget::planeHovered, this,
            [this](bool valid, const widgets::ViewportWidget::PlaneValue& v) {
                m_planeReadout->setText(valid ? tr("plane (%1, %2, %3): f = %4, |grad f| = %5")
                                                    .arg(double(v.position.x), 0, 'f', 3)
                                                    .arg(double(v.position.y), 0, 'f', 3)
                                                    .arg(double(v.position.z), 0, 'f', 3)
                                                    .arg(double(v.value), 0, 'g', 5)
                                                    .arg(double(v.gradientLength), 0, 'g', 4)
                                              : QString());
            });
    m_precision = new QLabel(this);
    m_precision->setObjectName("precision");
    statusBar()->addPermanentWidget(m_precision);
    statusBar()->addPermanentWidget(m_frameTime);
    connect(m_viewport, &widgets::ViewportWidget::cameraChanged, this, &MainWindow::updatePrecision);
    connect(m_viewport, &widgets::ViewportWidget::performanceWarning, this, [this](const QString& message) {
        log::warning("viewport", message.toStdString());
        statusBar()->showMessage(message, 20000);
    });
    connect(m_document, &SdfDocument::sdfApplied, this, [this] { m_logFrameTime = true; });
    // The viewport fell back to the previous SDF: say that jobs run it too (after the warning).
    connect(m_document, &SdfDocument::sdfReverted, this, [this](const QString& file) {
        const QString note = tr("Plane readouts, probes, exports and sampling run it too (%1); the editor keeps the new text.")
                                 .arg(file.isEmpty() ? tr("the unsaved text") : QFileInfo(file).fileName());
        log::warning("viewport", note.toStdString());
        statusBar()->showMessage(statusBar()->currentMessage() + " " + note, 20000);
    });
    connect(m_viewport, &widgets::ViewportWidget::frameRendered, this, [this](double milliseconds, float scale) {
        if (m_logFrameTime && scale >= 1.0f) {
            m_logFrameTime = false;
            log::info("viewport", QString("first full frame of %1: %2 ms at %3x%4")
                                      .arg(m_document->path().isEmpty() ? QString("the editor's text") : m_document->path())
                                      .arg(milliseconds, 0, 'f', 1)
                                      .arg(int(m_viewport->width() * m_viewport->devicePixelRatioF()))
                                      .arg(int(m_viewport->height() * m_viewport->devicePixelRatioF()))
                                      .toStdString());
        }
        m_frameTime->setText(
            scale < 1.0f ? tr("frame %1 ms at %2 % resolution (moving)").arg(milliseconds, 0, 'f', 1).arg(int(scale * 100.0f))
                         : tr("frame %1 ms").arg(milliseconds, 0, 'f', 1));
        updatePrecision();
    });
}

MainWindow::~MainWindow() {
    if (m_logSink) log::removeSink(m_logSink);
}

void MainWindow::setUpLog() {
    // One log file per session (the previous one kept as .1), the lines also in the Log dock.
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation);
    QDir().mkpath(folder);
    m_logFilePath = QDir(folder).filePath("sdfwb.log");
    QFile::remove(m_logFilePath + ".1");
    QFile::rename(m_logFilePath, m_logFilePath + ".1");
    m_logPanel->setFilePath(m_logFilePath);
    auto file = std::make_shared<std::ofstream>(m_logFilePath.toStdString(), std::ios::app);
    QPointer<widgets::LogPanel> panel = m_logPanel;
    m_logSink = log::addSink([file, panel](log::Level level, std::string_view category, std::string_view message) {
        const std::string line = QDateTime::currentDateTime().toString("hh:mm:ss.zzz").toStdString() + " [" +
                                 log::levelName(level) + "] " + std::string(category) + ": " + std::string(message);
        if (*file) *file << line << std::endl;
        // Any thread may log; the dock is updated on the UI thread.
        QMetaObject::invokeMethod(
            panel.data(),
            [panel, text = QString::fromStdString(line)] {
                if (panel) panel->appendLine(text);
            },
            Qt::QueuedConnection);
    });
    log::info("app", "sdfwb " SDFWB_VERSION " log: " + m_logFilePath.toStdString());
}

void MainWindow::loadDatasetItems(const QString& reportPath) {
    // The list job's entries, with the measured type and render time from the dataset report
    // (scripts/dataset_report.py), as `sdfwb --batch list` gives them.
    values::ListRequest request;
    request.report = reportPath.toStdString();
    auto listed = jobs::run(request, {});
    if (!listed) {
        m_browser->setItems({});
        m_browser->setReportNote(QString::fromStdString(listed.error.message));
        return;
    }
    m_browser->setItems(listed->items);
    m_browser->setReportNote(listed->report.empty() ? tr("No dataset report (dataset/report.json): types are the declared ones")
                                                    : tr("Measured type and render time (1280x720, Gooch): %1, %2")
                                                          .arg(QString::fromStdString(listed->measuredOn),
                                                               QString::fromStdString(listed->measuredDate)));
}

void MainWindow::updatePrecision() {
    const auto floor =
        values::precisionFloor(m_viewport->camera(), m_viewport->trace().epsilonScale, std::max(m_viewport->height(), 1));
    if (floor.exceeded) {
        m_precision->setText(tr("<span style='color:#e04040'>below float32 precision: positions known to %1, hit tolerance %2 "
                                "(surface noise; bring the camera nearer the origin)</span>")
                                 .arg(double(floor.positionFloor), 0, 'g', 2)
                                 .arg(double(floor.hitTolerance), 0, 'g', 2));
    } else {
        m_precision->setText(tr("float32 floor %1 / hit tolerance %2")
                                 .arg(double(floor.positionFloor), 0, 'g', 2)
                                 .arg(double(floor.hitTolerance), 0, 'g', 2));
    }
    m_precision->setToolTip(
        tr("Float32 spacing of positions at this camera distance, against the sphere tracer's hit tolerance "
           "(half a pixel's footprint at the target). When the first reaches half the second, the surface "
           "shows rounding noise. The audit (sdfwb --batch audit) measures the noise in the SDF's own values."));
}

QDockWidget* MainWindow::addDock(const QString& title, const QString& name, QWidget* widget, Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name);
    dock->setWidget(widget);
    addDockWidget(area, dock);
    return dock;
}

bool MainWindow::openFile(const QString& path) { return m_files->load(path); }

void MainWindow::saveAsWithDialog() {
    if (m_document->isMesh()) { // refused without asking for a name: the message says why
        m_files->saveAs(m_document->path());
        return;
    }
    const QString suggested = m_files->suggestedSavePath();
    const QString path = m_chooseSavePath ? m_chooseSavePath(suggested)
                                          : QFileDialog::getSaveFileName(this, tr("Save SDF"), suggested, tr("GLSL (*.glsl)"));
    if (!path.isEmpty()) m_files->saveAs(path);
}

void MainWindow::setBackgroundColour(const glm::vec3& colour) {
    values::ShadingSettings shading = m_viewport->shading();
    shading.background = colour;
    shading.backgroundImage.clear();
    m_viewport->setShading(shading);
}

void MainWindow::setBackgroundImage(const QString& path) {
    values::ShadingSettings shading = m_viewport->shading();
    shading.backgroundImage = path.toStdString();
    m_viewport->setShading(shading);
}

void MainWindow::setShadingMode(shaders::ShadingMode mode) {
    values::ShadingSettings shading = m_viewport->shading();
    shading.mode = mode;
    m_viewport->setShading(shading);
    for (QAction* action : m_shadingGroup->actions()) action->setChecked(action->data().toInt() == int(mode));
}

void MainWindow::setAmbientOcclusion(bool enabled) {
    values::ShadingSettings shading = m_viewport->shading();
    shading.ambientOcclusion = enabled;
    m_viewport->setShading(shading);
    m_aoAction->setChecked(enabled);
}

void MainWindow::updateOverlay() {
    if (!m_overlayAction->isChecked()) {
        m_viewport->setOverlayText({});
        return;
    }
    auto metadata = dataset::parseMetadata(m_editor->text().toStdString(), m_document->path().toStdString());
    if (!metadata) {
        m_viewport->setOverlayText(tr("(no metadata block)"));
        return;
    }
    m_viewport->setOverlayText(QString::fromStdString(dataset::overlayText(*metadata)));
}

void MainWindow::restoreSession() {
    QSettings settings;
    restoreGeometry(settings.value("window/geometry").toByteArray());
    restoreState(settings.value("window/state").toByteArray());
    values::Camera camera;
    auto readVector = [&](const char* key, glm::vec3& value) {
        QList<QVariant> list = settings.value(key).toList();
        if (list.size() == 3)
            for (int i = 0; i < 3; ++i) value[i] = list[i].toFloat();
    };
    readVector("camera/position", camera.position);
    readVector("camera/target", camera.target);
    camera.fovYDegrees = settings.value("camera/fov", camera.fovYDegrees).toFloat();
    camera.nearPlane = settings.value("camera/near", camera.nearPlane).toFloat();
    camera.farPlane = settings.value("camera/far", camera.farPlane).toFloat();
    m_viewport->setCamera(camera);
    m_cameraPanel->setCamera(camera);
    values::ShadingSettings shading = m_viewport->shading();
    shading.mode = shaders::parseShadingMode(settings.value("shading/mode", "gooch").toString().toStdString())
                       .value_or(shaders::ShadingMode::Gooch);
    shading.ambientOcclusion = settings.value("shading/ao", false).toBool();
    shading.matcap = settings.value("shading/matcap", "clay").toString().toStdString();
    m_viewport->setShading(shading);
    setShadingMode(shading.mode);
    m_aoAction->setChecked(shading.ambientOcclusion);
    m_overlayAction->setChecked(settings.value("view/overlay", false).toBool());
    m_sessionParameterFile = settings.value("parameters/file").toString();
    m_sessionParameterValues = settings.value("parameters/values").toStringList();
}

void MainWindow::saveSession() {
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    const values::Camera& camera = m_viewport->camera();
    auto vector = [](const glm::vec3& v) { return QList<QVariant>{v.x, v.y, v.z}; };
    settings.setValue("camera/position", vector(camera.position));
    settings.setValue("camera/target", vector(camera.target));
    settings.setValue("camera/fov", camera.fovYDegrees);
    settings.setValue("camera/near", camera.nearPlane);
    settings.setValue("camera/far", camera.farPlane);
    settings.setValue("shading/mode", shaders::shadingModeName(m_viewport->shading().mode));
    settings.setValue("shading/ao", m_viewport->shading().ambientOcclusion);
    settings.setValue("shading/matcap", QString::fromStdString(m_viewport->shading().matcap));
    settings.setValue("view/overlay", m_overlayAction->isChecked());
    QStringList values;
    for (const shaders::ParameterValue& value : m_document->input().params)
        values << QString::fromStdString(shaders::formatParameterValue(value));
    settings.setValue("parameters/file", m_document->path());
    settings.setValue("parameters/values", values);
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!m_files->confirmClose()) {
        event->ignore();
        return;
    }
    saveSession();
    event->accept();
}

void MainWindow::updateTitle() {
    QString name = m_document->path().isEmpty() ? tr("untitled") : m_document->path();
    const QString shipped =
        m_document->isMesh()
            ? tr(" [mesh: sign %1, normalize %2; not saved]").arg(m_document->meshSign(), m_document->meshNormalize())
        : FileController::isShipped(m_document->path()) ? tr(" [shipped, read-only: Save asks for a new name]")
        : !m_document->frame().isEmpty()
            ? tr(" [[-1, 1]^3 does not hold its scene whole: framed by the box %1]").arg(m_document->frame())
        : m_document->level() != 0.0f
            ? tr(" [an unsigned field: its surface taken at f = %1, where its march stops]").arg(double(m_document->level()))
            : QString();
    setWindowTitle(QString("%1%2%3 - sdfwb").arg(name, m_document->isModified() ? "*" : "", shipped));
}

bool MainWindow::showMeshDeviation(const QString& path) {
    auto mesh = meshing::readMesh(path.toStdString());
    if (!mesh || mesh->indices.empty()) {
        const QString why = mesh ? tr("it has no triangles") : QString::fromStdString(mesh.error().message);
        statusBar()->showMessage(tr("Cannot show %1: %2").arg(path, why), 10000);
        return false;
    }
    std::vector<float> positions;
    positions.reserve(3 * mesh->vertices.size());
    for (const glm::vec3& v : mesh->vertices) positions.insert(positions.end(), {v.x, v.y, v.z});
    // Full colour at a tenth of the mean edge: a scale that suits a mesh of any resolution.
    double edgeSum = 0.0;
    for (std::size_t t = 0; t + 2 < mesh->indices.size(); t += 3)
        for (int e = 0; e < 3; ++e)
            edgeSum += double(glm::distance(mesh->vertices[mesh->indices[t + std::size_t(e)]],
                                            mesh->vertices[mesh->indices[t + std::size_t((e + 1) % 3)]]));
    const float scale = float(0.1 * edgeSum / double(mesh->indices.size()));
    m_viewport->setMeshOverlay(positions, mesh->indices, scale);
    m_hideMeshAction->setEnabled(true);
    statusBar()->showMessage(tr("Mesh deviation: %1, %2 triangles. Grey on the surface, red outside, blue inside; full colour at "
                                "|f| = %3 (a tenth of its mean edge).")
                                 .arg(QFileInfo(path).fileName())
                                 .arg(mesh->triangleCount())
                                 .arg(double(scale), 0, 'g', 3));
    return true;
}

void MainWindow::hideMeshDeviation() {
    m_viewport->setMeshOverlay({}, {}, 0.0f);
    m_hideMeshAction->setEnabled(false);
    statusBar()->clearMessage();
}

} // namespace sdfwb::app
