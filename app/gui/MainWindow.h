#pragma once
// The workbench window: docks (editor, viewport, camera, time), menus, status bar, and the
// session (layout, camera, shading) saved on close and restored on start. It lays widgets out and
// wires them to controllers; the work happens in the controllers and below.

#include <values/RenderSettings.h>

#include <glm/vec3.hpp>

#include <QMainWindow>
#include <QStringList>

#include <functional>

class QActionGroup;
class QDockWidget;
class QLabel;
class QLineEdit;

namespace sdfwb::widgets {
class CameraPanel;
class DatasetBrowser;
class GlslEditor;
class LogPanel;
class ProbePanel;
class ParametersPanel;
class PlanePanel;
class ProblemsPanel;
class TimeBar;
class ViewportWidget;
} // namespace sdfwb::widgets

namespace sdfwb::app {

class CloudController;
class ExportController;
class ProbeController;
class ThumbnailController;
class MeshExportController;
class FileController;
class JobWorker;
class PlaneController;
class PlaybackController;
class SamplingController;
class SdfDocument;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens `path` in the editor and the viewport; false (with a message in the log) on failure.
    bool openFile(const QString& path);

    widgets::ViewportWidget* viewport() const { return m_viewport; }
    widgets::GlslEditor* editor() const { return m_editor; }
    widgets::CameraPanel* cameraPanel() const { return m_cameraPanel; }
    widgets::TimeBar* timeBar() const { return m_timeBar; }
    SdfDocument* document() const { return m_document; }
    SamplingController* sampling() const { return m_sampling; }
    ExportController* exports() const { return m_exports; }
    MeshExportController* meshExport() const { return m_meshExport; }
    PlaybackController* playback() const { return m_playback; }
    widgets::PlanePanel* planePanel() const { return m_planePanel; }
    widgets::ParametersPanel* parametersPanel() const { return m_parametersPanel; }
    PlaneController* plane() const { return m_plane; }
    FileController* files() const { return m_files; }
    widgets::ProblemsPanel* problems() const { return m_problems; }
    widgets::DatasetBrowser* datasetBrowser() const { return m_browser; }
    widgets::ProbePanel* probePanel() const { return m_probePanel; }
    widgets::LogPanel* logPanel() const { return m_logPanel; }
    ProbeController* probe() const { return m_probe; }
    JobWorker* worker() const { return m_worker; }
    CloudController* clouds() const { return m_clouds; }
    ThumbnailController* thumbnails() const { return m_thumbnails; }
    QAction* probeAction() const { return m_probeAction; }
    QLabel* planeReadout() const { return m_planeReadout; }
    // The log file this window's session writes (and the Log dock shows).
    QString logFilePath() const { return m_logFilePath; }

    // Picks the path "Save as" writes to, given the suggested one; empty: cancelled. Default: a
    // file dialog. Tests answer it (no modal dialog blocks a test).
    using PathChooser = std::function<QString(const QString& suggested)>;
    void setSavePathChooser(PathChooser chooser) { m_chooseSavePath = std::move(chooser); }
    // Fills the dataset browser from the catalogue, with measured types and render times from the
    // dataset report `reportPath` (scripts/dataset_report.py writes dataset/report.json).
    void loadDatasetItems(const QString& reportPath);
    // The same for choosing a background image and colour (View menu).
    void setBackgroundColour(const glm::vec3& colour);
    void setBackgroundImage(const QString& path);

    void setShadingMode(shaders::ShadingMode mode);
    void setAmbientOcclusion(bool enabled);
    // Shows the mesh in `path` over the surface, coloured by its deviation from the field (View >
    // Show mesh deviation; an export shows its mesh by itself). False, with the reason in the
    // status bar, for a file that does not read as a mesh.
    bool showMeshDeviation(const QString& path);
    void hideMeshDeviation();

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    QDockWidget* addDock(const QString& title, const QString& name, QWidget* widget, Qt::DockWidgetArea area);
    void createMenus();
    void createFileMenu();
    void createEditMenu();
    void createViewMenu();
    void addShadertoyItems(QMenu* view);
    void addOverlayItems(QMenu* view);
    void createToolsMenu();
    void restoreSession();
    void saveSession();
    void updateTitle();
    void updatePrecision();
    void updateOverlay();
    void updateRecentMenu();
    void saveAsWithDialog();
    void setUpLog();
    void createDocks();
    void createControllers();
    void createEntryToolBar();
    void connectFilesAndEditor();
    void loadCompletions();
    void connectDocument();
    void connectParameters();
    void createStatusBar();

    widgets::GlslEditor* m_editor = nullptr;
    widgets::ViewportWidget* m_viewport = nullptr;
    widgets::CameraPanel* m_cameraPanel = nullptr;
    widgets::TimeBar* m_timeBar = nullptr;
    widgets::PlanePanel* m_planePanel = nullptr;
    widgets::ParametersPanel* m_parametersPanel = nullptr;
    QDockWidget* m_parametersDock = nullptr;
    // Parameter values of the last session, applied when its file's SDF first compiles.
    QString m_sessionParameterFile;
    QStringList m_sessionParameterValues;
    QDockWidget* m_planeDock = nullptr;
    PlaneController* m_plane = nullptr;
    JobWorker* m_worker = nullptr; // the persistent child for plane readouts and probes
    FileController* m_files = nullptr;
    widgets::ProblemsPanel* m_problems = nullptr;
    widgets::DatasetBrowser* m_browser = nullptr;
    QDockWidget* m_browserDock = nullptr;
    QDockWidget* m_problemsDock = nullptr;
    QMenu* m_recentMenu = nullptr;
    QStringList m_librarySignatures;
    QString m_lastSearch;
    QDockWidget* m_editorDock = nullptr;
    QDockWidget* m_viewportDock = nullptr;
    QDockWidget* m_cameraDock = nullptr;
    QDockWidget* m_timeDock = nullptr;
    QLabel* m_frameTime = nullptr;
    QLabel* m_precision = nullptr; // float32 floor against the hit tolerance of the current view
    QLabel* m_diagnosticSummary = nullptr;
    QLineEdit* m_entry = nullptr; // the SDF's function (--entry); empty: automatic
    QActionGroup* m_shadingGroup = nullptr;
    QAction* m_aoAction = nullptr;
    QAction* m_overlayAction = nullptr;
    QAction* m_shadertoyAction = nullptr;
    QAction* m_hideMeshAction = nullptr;
    widgets::ProbePanel* m_probePanel = nullptr;
    widgets::LogPanel* m_logPanel = nullptr;
    QDockWidget* m_probeDock = nullptr;
    QDockWidget* m_logDock = nullptr;
    QAction* m_probeAction = nullptr;
    QLabel* m_planeReadout = nullptr;
    QString m_logFilePath;
    int m_logSink = 0;
    bool m_logFrameTime = false; // the next full-resolution frame's time goes to the log
    PathChooser m_chooseSavePath;
    ProbeController* m_probe = nullptr;
    CloudController* m_clouds = nullptr;
    ThumbnailController* m_thumbnails = nullptr;
    SdfDocument* m_document = nullptr;
    SamplingController* m_sampling = nullptr;
    ExportController* m_exports = nullptr;
    MeshExportController* m_meshExport = nullptr;
    PlaybackController* m_playback = nullptr;
};

} // namespace sdfwb::app
