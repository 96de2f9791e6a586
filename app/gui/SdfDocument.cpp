#include "SdfDocument.h"

#include <core/Log.h>
#include <core/Paths.h>
#include <jobs/Jobs.h>
#include <meshfield/MeshField.h>
#include <renderer/HeadlessContext.h>
#include <renderer/SdfRenderer.h>
#include <shaders/GlslChecker.h>
#include <shaders/LoopLimits.h>
#include <shaders/TracerComposer.h>

#include <QCoreApplication>
#include <QMetaObject>
#include <QPointer>
#include <QThreadPool>

#include <cstdio>

namespace sdfwb::app {

SdfDocument::SdfDocument(QObject* parent) : QObject(parent) {
    m_debounce.setSingleShot(true);
    m_debounce.setTimerType(Qt::PreciseTimer); // a coarse timer may fire 6 ms late
    m_debounce.setInterval(120);
    connect(&m_debounce, &QTimer::timeout, this, [this] { startCheck(m_pendingText); });
}

void SdfDocument::setModified(bool modified) {
    if (modified == m_modified) return;
    m_modified = modified;
    emit modifiedChanged(modified);
}

// The view times each new SDF on its first frame: one that passes is the fallback for the next;
// one that would stall is replaced by that fallback, in the view and in jobs.
void SdfDocument::shownSdfTimed() { m_timed = m_good; }

void SdfDocument::shownSdfStalled() {
    if (m_timed.text.isEmpty()) return;
    m_good = m_timed;
    m_reverted = true;
    emit sdfReverted(m_good.path);
}

values::FrameRequest SdfDocument::frame(const values::FrameSettings& view, int width, int height) const {
    values::FrameRequest frame;
    static_cast<values::FrameSettings&>(frame) = view; // the view's, whole
    frame.sdf = input();
    frame.width = width;
    frame.height = height;
    frame.time = m_time;
    frame.plane = m_plane;
    return frame;
}

void SdfDocument::setTime(float seconds) {
    m_time = seconds;
    emit timeChanged(seconds);
}

void SdfDocument::setPlane(const values::CuttingPlane& plane) {
    m_plane = plane;
    emit planeChanged(m_plane);
}

values::SdfInput SdfDocument::input() const {
    // The viewport's SDF, except before anything compiled and for a new file that has not yet.
    const bool shown = !m_good.text.isEmpty() && (m_good.path == m_path || m_reverted);
    values::SdfInput input{(shown ? m_good.path : m_path).toStdString(), m_entry.toStdString(),
                           (shown ? m_good.text : m_text).toStdString(), shaders::valuesOf(m_parameterValues)};
    input.channels.assign(m_channels.begin(), m_channels.end());
    while (!input.channels.empty() && input.channels.back().empty()) input.channels.pop_back();
    if (isMesh()) {
        input.sign = m_meshSign.toStdString();
        input.normalize = m_meshNormalize.toStdString();
    } else {
        input.normalize = m_frame.toStdString();
        input.level = m_level;
    }
    return input;
}

bool SdfDocument::isMesh() const { return !m_path.isEmpty() && meshfield::isMeshPath(m_path.toStdString()); }

namespace {

// The view of a pasted whole shader (SdfDocument::frame and level): `kept` when it was decided for
// this file and entry, else decided now by a search of the field's values in an EGL context of this
// worker thread. The field is framed by the box (jobs::frameField, as --normalize frames it for the
// jobs), or an unsigned field's surface taken at the level its march stops at (as --level).
jobs::PastedView decideView(shaders::PreparedSdf& prepared, const jobs::PastedView* kept, const std::string& label) {
    jobs::PastedView view;
    if (kept) {
        view = *kept;
    } else if (auto context = renderer::HeadlessContext::create()) {
        view = jobs::decidePastedView(prepared, {});
        (*context)->doneCurrent();
        if (!view.box.empty())
            log::info("app", std::string(!view.floor.empty() ? "[-1, 1]^3 holds only the plane " + view.floor + " of the scene"
                                         : view.cut          ? "[-1, 1]^3 cuts the scene"
                                                             : "the surface lies outside [-1, 1]^3") +
                                 ": framed by the box " + view.box);
    }
    prepared.frame.level = view.level;
    if (!view.box.empty()) jobs::frameField(prepared, view.box, {}, label, "app"); // a box: no GL, no failure
    return view;
}

// What the Problems panel says of a level taken as an unsigned field's surface (decideView).
shaders::Diagnostic levelNote(const shaders::PreparedSdf& prepared, const std::string& file) {
    char level[32];
    std::snprintf(level, sizeof level, "%.7g", double(prepared.frame.level));
    return {file, prepared.marchThresholdLine, 1, shaders::Severity::Warning,
            std::string("the field is never negative (an unsigned distance, with no inside): its surface is taken at f = ") +
                level + ", where this march stops; samples and meshes made here use it (--level " + level +
                " on the command line)"};
}

// The document's text over its mesh: what the jobs' openSdf builds from the same input.
shaders::PreparedSdf prepareOverMesh(const std::string& source, const std::string& path, const std::string& entry,
                                     const std::string& sign, const std::string& normalize) {
    auto options = meshfield::parseMeshFieldOptions(sign, normalize);
    if (!options) {
        shaders::PreparedSdf failed;
        failed.source.map.files.push_back({path, ""});
        failed.diagnostics.push_back({path, 0, 0, shaders::Severity::Error, options.error().message});
        return failed;
    }
    return shaders::prepareMeshFile(path, *options, source, entry); // the field is cached: a re-check does not rebuild it
}

} // namespace

void SdfDocument::setChannel(int channel, const QString& path) {
    if (channel >= 0 && channel < shaders::kShadertoyChannels) m_channels[std::size_t(channel)] = path.toStdString();
}

void SdfDocument::setParameterValues(const std::vector<shaders::ParameterSetting>& values) {
    m_parameterValues = values;
    emit parameterValuesChanged(m_parameterValues);
}

void SdfDocument::textEdited(const QString& text) {
    m_text = text;
    m_pendingText = text;
    m_debounce.start();
}

void SdfDocument::checkNow(const QString& text) {
    m_text = text;
    m_debounce.stop();
    startCheck(text);
}

void SdfDocument::startCheck(const QString& text) {
    std::uint64_t generation = ++m_generation;
    m_checkedText = text;
    std::string source = text.toStdString();
    std::string path = m_path.toStdString();
    std::string entry = m_entry.toStdString();
    const auto channels = m_channels;
    const bool mesh = isMesh();
    std::string sign = m_meshSign.toStdString(), normalize = m_meshNormalize.toStdString();
    jobs::PastedView view{m_frame.toStdString(), {}, m_level};
    std::string decidedFor = m_frameDecidedFor.toStdString();
    // glslang checks the variant the viewport will compile (shading, AO, plane, markers, ...).
    const shaders::TracerFeatures features =
        m_features ? m_features(m_plane) : renderer::tracerFeatures(values::ShadingSettings{}, values::TraceSettings{}, m_plane);
    QPointer<SdfDocument> self(this);
    QThreadPool::globalInstance()->start([self, generation, source = std::move(source), path = std::move(path),
                                          entry = std::move(entry), features, channels, mesh, sign = std::move(sign),
                                          normalize = std::move(normalize), view = std::move(view),
                                          decidedFor = std::move(decidedFor)]() mutable {
        shaders::IncludeOptions options;
        options.libraryRoots = {paths::shaderLibraryRoot(), paths::datasetRoot()};
        shaders::PreparedSdf prepared = mesh
                                            ? prepareOverMesh(source, path, entry, sign, normalize)
                                            : shaders::prepareSdf(source, path.empty() ? "<editor>" : path, path, options, entry);
        prepared.channels = channels;
        const std::string frameFor = path + "\n" + prepared.signature.entry;
        // Framed only when a pasted whole shader's surface lies outside the unit box.
        const bool decided = !mesh && prepared.ok();
        if (decided)
            view = prepared.shadertoyMainImage
                       ? decideView(prepared, frameFor == decidedFor ? &view : nullptr, path.empty() ? "<editor>" : path)
                       : jobs::PastedView{};
        std::vector<shaders::Diagnostic> diagnostics = prepared.diagnostics;
        if (decided && view.level != 0.0f) diagnostics.push_back(levelNote(prepared, path.empty() ? "<editor>" : path));
        if (prepared.ok()) {
            auto composed = shaders::composeTracer(prepared, features);
            if (composed) {
                auto found = shaders::checkWithGlslang(*composed);
                diagnostics.insert(diagnostics.end(), found.begin(), found.end());
                // Loops the viewport's driver would cut short (llvmpipe: 65535 iterations).
                if (!shaders::hasErrors(found)) {
                    auto loops = shaders::findLongLoops(prepared, *composed, shaders::driverLoopLimit(), "Mesa's llvmpipe");
                    diagnostics.insert(diagnostics.end(), loops.begin(), loops.end());
                }
            }
        }
        QMetaObject::invokeMethod(
            QCoreApplication::instance(),
            [self, generation, prepared = std::move(prepared), diagnostics = std::move(diagnostics), view, frameFor,
             decided]() mutable {
                if (!self) return;
                if (decided && generation == self->m_generation) {
                    self->m_frame = QString::fromStdString(view.box);
                    self->m_level = view.level;
                    self->m_frameDecidedFor = QString::fromStdString(frameFor);
                }
                self->finishCheck(generation, std::move(prepared), std::move(diagnostics));
            },
            Qt::QueuedConnection);
        // Autocompletion entries come second: they are not on the path to the diagnostics.
        QStringList signatures;
        for (const std::string& signature : shaders::functionSignatures(source)) signatures << QString::fromStdString(signature);
        QMetaObject::invokeMethod(
            QCoreApplication::instance(),
            [self, generation, signatures = std::move(signatures)]() mutable {
                if (!self || generation != self->m_generation) return;
                self->m_fileSignatures = std::move(signatures);
                emit self->signaturesChanged(self->m_fileSignatures);
            },
            Qt::QueuedConnection);
    });
}

void SdfDocument::finishCheck(std::uint64_t generation, shaders::PreparedSdf prepared,
                              std::vector<shaders::Diagnostic> diagnostics) {
    if (generation != m_generation) return; // superseded by newer text
    // glslang's verdict goes on screen at once; the driver compile (on this thread, where the GL
    // context lives) follows in the next event-loop turn and adds its own errors if it finds any.
    m_diagnostics = std::move(diagnostics);
    QStringList candidates;
    for (const std::string& name : prepared.entryCandidates) candidates << QString::fromStdString(name);
    emit entryCandidatesChanged(candidates);
    emit diagnosticsChanged(m_diagnostics);
    if (shaders::hasErrors(m_diagnostics)) return;
    QTimer::singleShot(0, this, [this, generation, prepared = std::move(prepared)]() mutable {
        if (generation != m_generation) return;
        m_offered = Offered{generation, std::move(prepared)};
        emit sdfReady(m_offered->prepared);
    });
}

void SdfDocument::driverCompiled(const std::vector<shaders::Diagnostic>& driver) {
    if (!m_offered) return;
    Offered offered = std::move(*m_offered);
    m_offered.reset();
    if (offered.generation != m_generation) return; // newer text was checked meanwhile
    if (shaders::hasErrors(driver)) {
        for (const auto& d : driver)
            if (d.severity == shaders::Severity::Error) m_diagnostics.push_back(d);
        emit diagnosticsChanged(m_diagnostics);
        return;
    }
    m_good = {m_path, m_checkedText, offered.prepared, offered.prepared.signature};
    m_reverted = false;
    emit sdfApplied();
}

} // namespace sdfwb::app
