#pragma once
// Files of the SDF being edited: new from a template, save and save-as (atomic), recent files,
// reload when the file changes on disk, F5 to reload every shader, and no lost work: an autosave
// to a recovery file every few seconds while modified, recovery after a crash, a prompt on close.
// Questions go through a prompt function so tests can answer them (no modal dialog blocks a test).

#include <QFileSystemWatcher>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>

#include <functional>

namespace sdfwb::widgets {
class GlslEditor;
class ViewportWidget;
} // namespace sdfwb::widgets

namespace sdfwb::app {

class SdfDocument;

class FileController : public QObject {
    Q_OBJECT
public:
    enum class Answer { Yes, No, Cancel };
    using Prompt = std::function<Answer(const QString& question)>;

    FileController(QWidget* window, widgets::GlslEditor* editor, SdfDocument* document, widgets::ViewportWidget* viewport,
                   QObject* parent = nullptr);

    void setPrompt(Prompt prompt) { m_prompt = std::move(prompt); }
    void setAutosaveInterval(int milliseconds) { m_autosave.setInterval(milliseconds); }

    // Loads `path` into the editor (no prompt); false with a message in the status when unreadable.
    // A .glsl file into the editor, or a triangle mesh (.obj .ply .stl .off .glb ...) as the
    // document's field, with its generated text (loadMesh).
    bool load(const QString& path);
    void newFromTemplate();
    bool save();
    bool saveAs(const QString& path);
    QStringList recentFiles() const;

    // Shipped dataset files are read-only: they may be edited in the editor, but save() refuses
    // them (the caller asks for a new name) and saveAs() never writes into the dataset.
    static bool isShipped(const QString& path);
    bool isReadOnly() const { return isShipped(documentPath()); }
    // Where "Save as" suggests to save the current document: the user's SDF folder for a shipped
    // file or an untitled one (Documents/sdfwb/NAME.glsl), else the file itself.
    QString suggestedSavePath() const;

    // The recovery file of the current document, and every recovery file left by earlier runs.
    QString recoveryPath() const;
    static QStringList recoveryFiles();
    void autosaveNow();
    // Loads a recovery file's text into the editor (modified, with its original path).
    bool restoreRecovery(const QString& recoveryFile);
    // Asks about unsaved edits; false when the user cancels. Cleans up the recovery file.
    bool confirmClose();
    // F5: reload the file if unmodified, rebuild every shader from disk (SDF, includes, built-ins).
    void reloadAll();

signals:
    void pathChanged(const QString& path);
    void message(const QString& text);

private:
    bool loadMesh(const QString& path);
    void markUnmodified();
    QString documentPath() const;
    void watch(const QString& path);
    void fileChangedOnDisk(const QString& path);
    void addRecent(const QString& path);

    QWidget* m_window;
    widgets::GlslEditor* m_editor;
    SdfDocument* m_document;
    widgets::ViewportWidget* m_viewport;
    Prompt m_prompt;
    QTimer m_autosave;
    QFileSystemWatcher m_watcher;
    bool m_saving = false;
};

} // namespace sdfwb::app
