#pragma once
// The SDF being edited, the one place that holds it: its file, its text and whether it has unsaved
// edits, the last text that compiled (what the viewport shows), the entry point, the parameter
// values, the scene time, the cutting plane, and the checking pipeline. It knows no view: it
// emits a signal for each change, and the window passes them to the viewport (MainWindow). Edits
// are debounced and checked off the UI thread (include resolution + glslang on the tracer variant
// setTracerFeatures names); text that passes is offered with sdfReady, and whoever compiles it
// for the driver answers with driverCompiled (its errors become diagnostics). Jobs (sampling,
// exports, plane readouts) take `input()`: the shown text, not the file on disk. Owns its worker
// threads; never blocks the UI thread.

#include <shaders/Diagnostic.h>
#include <shaders/SdfSource.h>
#include <shaders/TracerComposer.h>
#include <values/RenderSettings.h>
#include <values/Requests.h>

#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>

#include <array>
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace sdfwb::app {

class SdfDocument : public QObject {
    Q_OBJECT
public:
    explicit SdfDocument(QObject* parent = nullptr);

    // The tracer variant a check runs glslang on, for the cutting plane (the viewport's shading
    // and trace settings); default: the variant of the default settings.
    void setTracerFeatures(std::function<shaders::TracerFeatures(const values::CuttingPlane&)> features) {
        m_features = std::move(features);
    }

    // Unsaved edits. The editor's undo history sets it (through the window), saving and loading clear it.
    bool isModified() const { return m_modified; }
    void setModified(bool modified);

    const QString& path() const { return m_path; }
    // A new file: until it compiles, jobs run its text (the last good text was another file's).
    void setPath(const QString& path) { m_path = path; }
    // A triangle mesh as the document's file (File > Open mesh): the text is GLSL over the mesh's
    // field sdfwb_meshSdf(p) (meshfield/), checked and traced with the mesh and passed to jobs with
    // the same sign and normalisation ("winding", "unit-cube", ...; empty: the defaults).
    bool isMesh() const;
    void setMeshOptions(const QString& sign, const QString& normalize) {
        m_meshSign = sign;
        m_meshNormalize = normalize;
    }
    const QString& meshSign() const { return m_meshSign; }
    const QString& meshNormalize() const { return m_meshNormalize; }
    // A pasted whole shader whose scene [-1, 1]^3 does not hold whole (one built around its own camera):
    // the box X0,Y0,Z0,X1,Y1,Z1 it is framed by (shaders::PreparedSdf::frame), decided by the first
    // check of each file and entry function (jobs::decidePastedView) and passed to jobs as
    // --normalize; empty when the field is shown as it is.
    const QString& frame() const { return m_frame; }
    // A pasted whole shader whose field is never negative (an unsigned distance) and whose own march
    // stops at a constant (`d < 0.001`): that constant, its surface here and passed to jobs as
    // --level (jobs::decidePastedView); 0 otherwise.
    float level() const { return m_level; }

    // The editor's latest text, and the text the viewport shows (the last that compiled and
    // passed its timing frame, or the one before when the viewport fell back from a stalling one).
    const QString& text() const { return m_text; }
    const QString& lastGoodText() const { return m_good.text; }
    const shaders::PreparedSdf& lastGoodSource() const { return m_good.source; }
    // Whether the viewport fell back to the previous SDF (a frame of the new one would stall);
    // jobs then run that previous SDF too, until new text is applied.
    bool reverted() const { return m_reverted; }
    // What a job runs on: the path (for includes and labels), the entry, and the viewport's text
    // (the editor's text until something has compiled, and for a newly opened file until it does).
    values::SdfInput input() const;

    // The parameter values the viewport draws with (and jobs run with); uniforms, no recompile.
    void setParameterValues(const std::vector<shaders::ParameterSetting>& values);
    const std::vector<shaders::ParameterSetting>& parameterValues() const { return m_parameterValues; }

    // The scene time in seconds (animated SDFs, Shadertoy's iTime) and the cutting plane: the
    // viewport draws with them, and plane readouts, the probe, screenshots and videos run with them.
    void setTime(float seconds);
    float time() const { return m_time; }
    void setPlane(const values::CuttingPlane& plane);
    const values::CuttingPlane& plane() const { return m_plane; }
    // The frame the viewport shows, as a job takes it (the probe, videos): the shown SDF, the
    // time and the plane from here; the camera, shading, trace settings and overlay from `view`
    // (the viewport's frameSettings()).
    values::FrameRequest frame(const values::FrameSettings& view, int width, int height) const;

    // What the compiler of sdfReady's SDF found (empty: it compiled): with none, that SDF becomes
    // the shown one (sdfApplied); errors join the diagnostics.
    void driverCompiled(const std::vector<shaders::Diagnostic>& driver);
    // The view drew the shown SDF's first frame in time: it is what a later stalling one falls back to.
    void shownSdfTimed();
    // The view fell back from the shown SDF to the last timed one (a frame of it would stall).
    void shownSdfStalled();

    // Schedules a check of `text` after the debounce delay; newer text supersedes older.
    void textEdited(const QString& text);
    // Checks `text` now (still off the UI thread).
    void checkNow(const QString& text);

    // The entry point asked for (empty: metadata `entry:`, sdf, or a conventional name); takes
    // effect at the next check. `signature()` is what the last good check found.
    void setEntry(const QString& entry) { m_entry = entry; }
    const QString& entry() const { return m_entry; }
    const shaders::SdfSignature& signature() const { return m_good.signature; }

    // The image bound to a Shadertoy's iChannelN (empty: the noise texture); takes effect at the
    // next check, and jobs started from the document use it too.
    void setChannel(int channel, const QString& path);
    const std::array<std::string, shaders::kShadertoyChannels>& channels() const { return m_channels; }

    const std::vector<shaders::Diagnostic>& diagnostics() const { return m_diagnostics; }
    int debounceMilliseconds() const { return m_debounce.interval(); }
    // "name(type a, ...)" of the functions the last checked text defines (autocompletion).
    const QStringList& fileSignatures() const { return m_fileSignatures; }

signals:
    // After each check: diagnostics from the resolver, glslang and the driver.
    void diagnosticsChanged(const std::vector<shaders::Diagnostic>& diagnostics);
    // Checked text that passed, to compile for the driver; answer with driverCompiled.
    void sdfReady(const sdfwb::shaders::PreparedSdf& prepared);
    void modifiedChanged(bool modified);
    void parameterValuesChanged(const std::vector<sdfwb::shaders::ParameterSetting>& values);
    // The viewport now shows the new text.
    void sdfApplied();
    // The viewport fell back to the previous SDF, which jobs now run too; `file` is its path.
    void sdfReverted(const QString& file);
    // After each check: the functions a whole shader's march steps by equally often, when it
    // cannot tell which is the field (empty otherwise); the entry box offers them.
    void entryCandidatesChanged(const QStringList& names);
    // The functions the checked text defines changed (for autocompletion).
    void signaturesChanged(const QStringList& signatures);
    // The time or the plane changed (through the setters, or a Ctrl + drag in the viewport).
    void timeChanged(float seconds);
    void planeChanged(const sdfwb::values::CuttingPlane& plane);

private:
    void startCheck(const QString& text);
    void finishCheck(std::uint64_t generation, shaders::PreparedSdf prepared, std::vector<shaders::Diagnostic> diagnostics);

    std::function<shaders::TracerFeatures(const values::CuttingPlane&)> m_features;
    bool m_modified = false;
    struct Offered { // the SDF offered with sdfReady, until driverCompiled
        std::uint64_t generation;
        shaders::PreparedSdf prepared;
    };
    std::optional<Offered> m_offered;
    QString m_path;
    QString m_pendingText;
    QString m_text;
    QString m_checkedText; // the text of the newest check
    // What the viewport shows, and the last SDF that passed its timing frame (what the viewport
    // falls back to when a new one would stall).
    struct Shown {
        QString path, text;
        shaders::PreparedSdf source;
        shaders::SdfSignature signature;
    };
    Shown m_good, m_timed;
    bool m_reverted = false;
    QString m_entry;
    QString m_meshSign, m_meshNormalize;
    QString m_frame, m_frameDecidedFor; // the frame, and the file and entry it was decided for
    float m_level = 0.0f;               // decided with the frame
    std::array<std::string, shaders::kShadertoyChannels> m_channels;
    QTimer m_debounce;
    std::uint64_t m_generation = 0;
    std::vector<shaders::Diagnostic> m_diagnostics;
    QStringList m_fileSignatures;
    std::vector<shaders::ParameterSetting> m_parameterValues;
    float m_time = 0.0f;
    values::CuttingPlane m_plane;
};

} // namespace sdfwb::app
