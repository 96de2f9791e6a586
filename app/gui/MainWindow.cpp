#include "MainWindow.h"

#include "SamplingController.h"
#include "SdfDocument.h"

#include <core/Log.h>
#include <core/TextFile.h>
#include <widgets/GlslEditor.h>
#include <widgets/ViewportWidget.h>

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QLabel>
#include <QMenuBar>
#include <QSettings>
#include <QStatusBar>

namespace sdfwb::app {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setObjectName("MainWindow");
    setDockNestingEnabled(true);
    resize(1400, 820);

    m_viewport = new widgets::ViewportWidget;
    m_viewport->setObjectName("Viewport");
    m_viewportDock = new QDockWidget(tr("Viewport"), this);
    m_viewportDock->setObjectName("ViewportDock");
    m_viewportDock->setWidget(m_viewport);
    addDockWidget(Qt::RightDockWidgetArea, m_viewportDock);

    m_editor = new widgets::GlslEditor;
    m_editor->setObjectName("Editor");
    m_editorDock = new QDockWidget(tr("Editor"), this);
    m_editorDock->setObjectName("EditorDock");
    m_editorDock->setWidget(m_editor);
    addDockWidget(Qt::LeftDockWidgetArea, m_editorDock);
    resizeDocks({m_editorDock, m_viewportDock}, {560, 840}, Qt::Horizontal);

    m_document = new SdfDocument(m_viewport, this);
    connect(m_editor, &QsciScintilla::textChanged, this, [this] {
        m_document->textEdited(m_editor->text());
        updateTitle();
    });
    connect(m_document, &SdfDocument::diagnosticsChanged, this, [this](const std::vector<shaders::Diagnostic>& diagnostics) {
        QString path = m_document->path().isEmpty() ? QString("<editor>") : m_document->path();
        m_editor->setDiagnostics(diagnostics, path);
        int errors = 0, warnings = 0;
        for (const auto& d : diagnostics) (d.severity == shaders::Severity::Error ? errors : warnings)++;
        m_diagnosticSummary->setText(errors ? tr("%1 error(s), %2 warning(s): showing the last good shader").arg(errors).arg(warnings)
                                            : tr("%1 warning(s)").arg(warnings));
    });

    m_frameTime = new QLabel(this);
    m_diagnosticSummary = new QLabel(this);
    statusBar()->addWidget(m_diagnosticSummary, 1);
    statusBar()->addPermanentWidget(m_frameTime);
    connect(m_viewport, &widgets::ViewportWidget::frameRendered, this,
            [this](double milliseconds) { m_frameTime->setText(tr("frame %1 ms").arg(milliseconds, 0, 'f', 1)); });

    m_sampling = new SamplingController(this, [this] { return m_document->path(); }, this);

    createMenus();
    restoreLayout();
    updateTitle();
}

MainWindow::~MainWindow() = default;

bool MainWindow::openFile(const QString& path) {
    auto text = readTextFile(path.toStdString());
    if (!text) {
        log::error("app", text.error().message);
        statusBar()->showMessage(QString::fromStdString(text.error().message));
        return false;
    }
    m_document->setPath(path);
    const QSignalBlocker blocker(m_editor);
    m_editor->setText(QString::fromStdString(*text));
    m_editor->setModified(false);
    m_document->checkNow(m_editor->text());
    updateTitle();
    return true;
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open..."), this, [this] {
        QString path = QFileDialog::getOpenFileName(this, tr("Open SDF"), QString(), tr("GLSL (*.glsl *.frag *.glslf);;All files (*)"));
        if (!path.isEmpty()) openFile(path);
    });
    open->setShortcut(QKeySequence::Open);
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    QMenu* tools = menuBar()->addMenu(tr("&Tools"));
    QAction* sample = tools->addAction(tr("&Sample SDF..."), m_sampling, &SamplingController::showDialog);
    sample->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_M));

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addAction(m_editorDock->toggleViewAction());
    view->addAction(m_viewportDock->toggleViewAction());
    view->addSeparator();
    view->addAction(tr("&Reset camera"), m_viewport, &widgets::ViewportWidget::resetCamera);
}

void MainWindow::restoreLayout() {
    QSettings settings;
    restoreGeometry(settings.value("window/geometry").toByteArray());
    restoreState(settings.value("window/state").toByteArray());
}

void MainWindow::closeEvent(QCloseEvent* event) {
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    event->accept();
}

void MainWindow::updateTitle() {
    QString name = m_document->path().isEmpty() ? tr("untitled") : m_document->path();
    setWindowTitle(QString("%1%2 - sdfwb").arg(name, m_editor->isModified() ? "*" : ""));
}

} // namespace sdfwb::app
