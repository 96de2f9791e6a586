#pragma once
// The SDF being edited: its file, its text, and the checking pipeline. Edits are debounced and
// checked off the UI thread (include resolution + glslang); good text goes to the viewport, whose
// driver compile may add diagnostics. Owns its worker threads; never blocks the UI thread.

#include <shaders/Diagnostic.h>
#include <shaders/SdfSource.h>

#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>

#include <atomic>
#include <vector>

namespace sdfwb::widgets {
class ViewportWidget;
}

namespace sdfwb::app {

class SdfDocument : public QObject {
    Q_OBJECT
public:
    SdfDocument(widgets::ViewportWidget* viewport, QObject* parent = nullptr);

    const QString& path() const { return m_path; }
    void setPath(const QString& path) { m_path = path; }

    // Schedules a check of `text` after the debounce delay; newer text supersedes older.
    void textEdited(const QString& text);
    // Checks `text` now (still off the UI thread).
    void checkNow(const QString& text);

    // The entry point asked for (empty: metadata `entry:`, sdf, or a conventional name); takes
    // effect at the next check. `signature()` is what the last good check found.
    void setEntry(const QString& entry) { m_entry = entry; }
    const QString& entry() const { return m_entry; }
    const shaders::SdfSignature& signature() const { return m_signature; }

    const std::vector<shaders::Diagnostic>& diagnostics() const { return m_diagnostics; }
    int debounceMilliseconds() const { return m_debounce.interval(); }
    // "name(type a, ...)" of the functions the last checked text defines (autocompletion).
    const QStringList& fileSignatures() const { return m_fileSignatures; }

signals:
    // After each check: diagnostics from the resolver, glslang and the driver.
    void diagnosticsChanged(const std::vector<shaders::Diagnostic>& diagnostics);
    // The viewport now shows the new text.
    void sdfApplied();
    // The functions the checked text defines changed (for autocompletion).
    void signaturesChanged(const QStringList& signatures);

private:
    void startCheck(const QString& text);
    void finishCheck(std::uint64_t generation, shaders::PreparedSdf prepared, std::vector<shaders::Diagnostic> diagnostics);

    widgets::ViewportWidget* m_viewport;
    QString m_path;
    QString m_pendingText;
    QString m_entry;
    shaders::SdfSignature m_signature;
    QTimer m_debounce;
    std::uint64_t m_generation = 0;
    std::vector<shaders::Diagnostic> m_diagnostics;
    QStringList m_fileSignatures;
};

} // namespace sdfwb::app
