#pragma once
// The workbench window: docks for the editor and the viewport, menus, the status bar.
// It lays out widgets and wires them to the SdfDocument controller; the work happens elsewhere.

#include <QMainWindow>

class QDockWidget;
class QLabel;

namespace sdfwb::widgets {
class GlslEditor;
class ViewportWidget;
}

namespace sdfwb::app {

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
    SdfDocument* document() const { return m_document; }
    SamplingController* sampling() const { return m_sampling; }

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void createMenus();
    void restoreLayout();
    void updateTitle();

    widgets::GlslEditor* m_editor = nullptr;
    widgets::ViewportWidget* m_viewport = nullptr;
    QDockWidget* m_editorDock = nullptr;
    QDockWidget* m_viewportDock = nullptr;
    QLabel* m_frameTime = nullptr;
    QLabel* m_diagnosticSummary = nullptr;
    SdfDocument* m_document = nullptr;
    SamplingController* m_sampling = nullptr;
};

} // namespace sdfwb::app
