#include "FileController.h"

#include "SdfDocument.h"

#include <core/Log.h>
#include <core/Paths.h>
#include <core/TextFile.h>
#include <meshfield/MeshField.h>
#include <widgets/GlslEditor.h>
#include <widgets/ViewportWidget.h>

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>

namespace sdfwb::app {
namespace {

const char* const kRecoveryHeader = "// sdfwb recovery of: ";

const char* const kTemplate = R"(/* sdfwb
name: New Shape
category: Misc
type: conservative
animated: no
author: your name
license: CC0-1.0
notes: What it is and how it is built.
*/
#include "primitives.glsl"

float sdf(vec3 p) {
    // Fits [-1,1]^3; fronts face +X, tops face +Y.
    return opSmoothUnion(sdSphere(p - vec3(0.0, 0.25, 0.0), 0.45), sdBox(p + vec3(0.0, 0.35, 0.0), vec3(0.7, 0.15, 0.5)), 0.1);
}
)";

QString recoveryFolder() { return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/recovery"; }

} // namespace

FileController::FileController(QWidget* window, widgets::GlslEditor* editor, SdfDocument* document,
                               widgets::ViewportWidget* viewport, QObject* parent)
    : QObject(parent), m_window(window), m_editor(editor), m_document(document), m_viewport(viewport) {
    m_prompt = [this](const QString& question) {
        auto answer =
            QMessageBox::question(m_window, tr("sdfwb"), question, QMessageBox::Yes | QMessageBox::No | QMessageBox::Cancel);
        return answer == QMessageBox::Yes ? Answer::Yes : answer == QMessageBox::No ? Answer::No : Answer::Cancel;
    };
    m_autosave.setInterval(5000);
    connect(&m_autosave, &QTimer::timeout, this, &FileController::autosaveNow);
    m_autosave.start();
    connect(&m_watcher, &QFileSystemWatcher::fileChanged, this, &FileController::fileChangedOnDisk);
}

bool FileController::load(const QString& path) {
    if (meshfield::isMeshPath(path.toStdString())) return loadMesh(path);
    auto text = readTextFile(path.toStdString());
    if (!text) {
        emit message(QString::fromStdString(text.error().message));
        log::error("app", text.error().message);
        return false;
    }
    QString canonical = QFileInfo(path).absoluteFilePath();
    // Another file: its own entry point (automatic until chosen); a reload keeps the choice.
    if (canonical != m_document->path()) m_document->setEntry(QString());
    m_document->setPath(canonical);
    {
        const QSignalBlocker blocker(m_editor);
        m_editor->setText(QString::fromStdString(*text));
        markUnmodified();
    }
    m_document->checkNow(m_editor->text());
    watch(canonical);
    addRecent(canonical);
    emit pathChanged(canonical);
    return true;
}

bool FileController::loadMesh(const QString& path) {
    // A mesh that leaves the tracer's box [-1, 1]^3 opens scaled into it (unit-cube); the jobs
    // started from the document get the same options, so they run on the field the viewport shows.
    auto plain = meshfield::loadMeshField(path.toStdString(), {});
    if (!plain) {
        emit message(QString::fromStdString(plain.error().message));
        log::error("app", plain.error().message);
        return false;
    }
    const bool inside = (*plain)->bounds.insideUnitBox();
    meshfield::MeshFieldOptions options;
    options.normalize = inside ? meshfield::Normalization::None : meshfield::Normalization::UnitCube;
    auto field = inside ? plain : meshfield::loadMeshField(path.toStdString(), options);
    if (!field) {
        emit message(QString::fromStdString(field.error().message));
        return false;
    }
    const QString canonical = QFileInfo(path).absoluteFilePath();
    if (canonical != m_document->path()) m_document->setEntry(QString());
    m_document->setPath(canonical);
    m_document->setMeshOptions(meshfield::signName(options.sign), meshfield::normalizationName(options.normalize));
    {
        const QSignalBlocker blocker(m_editor);
        m_editor->setText(QString::fromStdString((*field)->glslSource()));
        markUnmodified();
    }
    m_document->checkNow(m_editor->text());
    watch(canonical);
    addRecent(canonical);
    emit pathChanged(canonical);
    log::info("app", (*field)->summary());
    emit message(QString::fromStdString((*field)->summary()));
    return true;
}

// The text matches its file: the document's flag and the editor's save point (which its undo
// history returns to) both clear.
void FileController::markUnmodified() {
    m_editor->setModified(false);
    m_document->setModified(false);
}

void FileController::newFromTemplate() {
    m_document->setPath(QString());
    m_editor->setText(kTemplate);
    m_document->setModified(true);
    m_document->checkNow(m_editor->text());
    emit pathChanged(QString());
}

bool FileController::isShipped(const QString& path) {
    if (path.isEmpty()) return false;
    const QString root = QFileInfo(QString::fromStdString(paths::datasetRoot().string())).canonicalFilePath();
    const QFileInfo info(path);
    // The folder's canonical path: the file itself may not exist yet (save as).
    const QString folder = QFileInfo(info.absolutePath()).canonicalFilePath();
    return !root.isEmpty() && !folder.isEmpty() && (folder == root || folder.startsWith(root + "/"));
}

QString FileController::documentPath() const { return m_document->path(); }

QString FileController::suggestedSavePath() const {
    const QString current = m_document->path();
    if (!current.isEmpty() && !isShipped(current)) return current;
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation) + "/sdfwb";
    QDir().mkpath(folder);
    const QString name = current.isEmpty() ? QString("untitled.glsl") : QFileInfo(current).fileName();
    return QDir(folder).filePath(name);
}

bool FileController::save() {
    if (m_document->path().isEmpty()) return false;              // the caller asks for a name (save as)
    if (m_document->isMesh()) return saveAs(m_document->path()); // refused there, with the reason
    if (isShipped(m_document->path())) {
        emit message(tr("%1 ships with sdfwb and is read-only: save your version under a new name")
                         .arg(QFileInfo(m_document->path()).fileName()));
        return false; // the caller asks for a name (save as)
    }
    return saveAs(m_document->path());
}

bool FileController::saveAs(const QString& path) {
    if (m_document->isMesh() || meshfield::isMeshPath(path.toStdString())) {
        // Text over a mesh calls sdfwb_meshSdf, which only exists with that mesh loaded; and text
        // must never replace a mesh file.
        emit message(tr("Not saved: the text over a mesh runs only with its mesh. Use it as it is, or on the command line "
                        "(sdfwb --batch ... --sdf %1)")
                         .arg(QFileInfo(m_document->path()).fileName()));
        log::warning("app", "refused to save the text over a mesh: " + path.toStdString());
        return false;
    }
    if (isShipped(path)) {
        emit message(tr("Not saved: %1 is in the shipped dataset, which is read-only; choose a folder of your own").arg(path));
        log::warning("app", "refused to write into the shipped dataset: " + path.toStdString());
        return false;
    }
    m_saving = true;
    auto written = writeFileAtomically(path.toStdString(), m_editor->text().toStdString());
    m_saving = false;
    if (!written) {
        emit message(QString::fromStdString(written.error().message));
        log::error("app", written.error().message);
        return false;
    }
    QFile::remove(recoveryPath());
    QString canonical = QFileInfo(path).absoluteFilePath();
    m_document->setPath(canonical);
    markUnmodified();
    watch(canonical);
    addRecent(canonical);
    m_document->checkNow(m_editor->text()); // includes resolve relative to the new folder
    emit pathChanged(canonical);
    emit message(tr("Saved %1").arg(canonical));
    return true;
}

QStringList FileController::recentFiles() const { return QSettings().value("files/recent").toStringList(); }

void FileController::addRecent(const QString& path) {
    QStringList recent = recentFiles();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > 10) recent.removeLast();
    QSettings().setValue("files/recent", recent);
}

QString FileController::recoveryPath() const {
    QString key = m_document->path().isEmpty() ? QString("untitled") : m_document->path();
    QString hash = QCryptographicHash::hash(key.toUtf8(), QCryptographicHash::Sha1).toHex().left(16);
    return recoveryFolder() + "/" + hash + ".glsl";
}

QStringList FileController::recoveryFiles() {
    QDir folder(recoveryFolder());
    QStringList files;
    for (const QString& name : folder.entryList({"*.glsl"}, QDir::Files, QDir::Time)) files << folder.filePath(name);
    return files;
}

void FileController::autosaveNow() {
    if (!m_document->isModified()) return;
    QDir().mkpath(recoveryFolder());
    QString header = kRecoveryHeader + (m_document->path().isEmpty() ? QString("untitled") : m_document->path()) + "\n";
    auto written = writeFileAtomically(recoveryPath().toStdString(), (header + m_editor->text()).toStdString());
    if (!written) log::warning("app", "autosave: " + written.error().message);
}

bool FileController::restoreRecovery(const QString& recoveryFile) {
    auto text = readTextFile(recoveryFile.toStdString());
    if (!text) return false;
    QString content = QString::fromStdString(*text);
    if (!content.startsWith(kRecoveryHeader)) return false;
    int newline = content.indexOf('\n');
    QString original = content.mid(int(std::strlen(kRecoveryHeader)), newline - int(std::strlen(kRecoveryHeader)));
    m_document->setPath(original == "untitled" ? QString() : original);
    m_editor->setText(content.mid(newline + 1));
    m_document->setModified(true);
    m_document->checkNow(m_editor->text());
    if (original != "untitled") watch(original);
    emit pathChanged(m_document->path());
    // The text now lives in the editor (and the next autosave); drop the old file if it was another one.
    if (QFileInfo(recoveryFile).absoluteFilePath() != QFileInfo(recoveryPath()).absoluteFilePath()) QFile::remove(recoveryFile);
    return true;
}

bool FileController::confirmClose() {
    if (m_document->isModified()) {
        Answer answer = m_prompt(
            tr("%1 has unsaved edits. Save them?").arg(m_document->path().isEmpty() ? tr("The new SDF") : m_document->path()));
        if (answer == Answer::Cancel) return false;
        if (answer == Answer::Yes && !save()) return false;
    }
    QFile::remove(recoveryPath());
    return true;
}

void FileController::reloadAll() {
    if (m_document->isMesh() && !m_document->isModified()) {
        loadMesh(m_document->path());
    } else if (!m_document->path().isEmpty() && !m_document->isModified()) {
        auto text = readTextFile(m_document->path().toStdString());
        if (text) {
            const QSignalBlocker blocker(m_editor);
            m_editor->setText(QString::fromStdString(*text));
            markUnmodified();
        }
    }
    m_viewport->reloadShaders();
    m_document->checkNow(m_editor->text());
    emit message(tr("Reloaded every shader from disk"));
}

void FileController::watch(const QString& path) {
    if (!m_watcher.files().isEmpty()) m_watcher.removePaths(m_watcher.files());
    if (!path.isEmpty() && QFileInfo::exists(path)) m_watcher.addPath(path);
}

void FileController::fileChangedOnDisk(const QString& path) {
    if (m_saving || path != m_document->path()) return;
    // Editors that save by rename replace the file: watch the new one.
    QTimer::singleShot(50, this, [this, path] {
        watch(path);
        if (m_document->isMesh()) { // a mesh rewritten on disk: its field again, unless the text over it was edited
            if (!m_document->isModified() && loadMesh(path)) emit message(tr("Reloaded %1 (changed on disk)").arg(path));
            return;
        }
        auto text = readTextFile(path.toStdString());
        if (!text || QString::fromStdString(*text) == m_editor->text()) return;
        if (m_document->isModified() &&
            m_prompt(tr("%1 changed on disk. Reload it and lose your edits?").arg(path)) != Answer::Yes)
            return;
        const QSignalBlocker blocker(m_editor);
        m_editor->setText(QString::fromStdString(*text));
        markUnmodified();
        m_document->checkNow(m_editor->text());
        emit message(tr("Reloaded %1 (changed on disk)").arg(path));
    });
}

} // namespace sdfwb::app
