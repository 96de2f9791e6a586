#include "SdfDocument.h"

#include <core/Paths.h>
#include <shaders/GlslChecker.h>
#include <shaders/TracerComposer.h>
#include <widgets/ViewportWidget.h>

#include <QCoreApplication>
#include <QMetaObject>
#include <QPointer>
#include <QThreadPool>

namespace sdfwb::app {

SdfDocument::SdfDocument(widgets::ViewportWidget* viewport, QObject* parent) : QObject(parent), m_viewport(viewport) {
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(150);
    connect(&m_debounce, &QTimer::timeout, this, [this] { startCheck(m_pendingText); });
}

void SdfDocument::textEdited(const QString& text) {
    m_pendingText = text;
    m_debounce.start();
}

void SdfDocument::checkNow(const QString& text) {
    m_debounce.stop();
    startCheck(text);
}

void SdfDocument::startCheck(const QString& text) {
    std::uint64_t generation = ++m_generation;
    std::string source = text.toStdString();
    std::string path = m_path.toStdString();
    QPointer<SdfDocument> self(this);
    QThreadPool::globalInstance()->start([self, generation, source = std::move(source), path = std::move(path)] {
        shaders::IncludeOptions options;
        options.libraryRoots = {paths::shaderLibraryRoot(), paths::datasetRoot()};
        shaders::PreparedSdf prepared = shaders::prepareSdf(source, path.empty() ? "<editor>" : path, path, options);
        std::vector<shaders::Diagnostic> diagnostics = prepared.diagnostics;
        if (prepared.ok()) {
            auto composed = shaders::composeTracer(prepared, shaders::TracerFeatures{});
            if (composed) {
                auto found = shaders::checkWithGlslang(*composed);
                diagnostics.insert(diagnostics.end(), found.begin(), found.end());
            }
        }
        QMetaObject::invokeMethod(QCoreApplication::instance(), [self, generation, prepared = std::move(prepared), diagnostics = std::move(diagnostics)]() mutable {
            if (self) self->finishCheck(generation, std::move(prepared), std::move(diagnostics));
        }, Qt::QueuedConnection);
    });
}

void SdfDocument::finishCheck(std::uint64_t generation, shaders::PreparedSdf prepared, std::vector<shaders::Diagnostic> diagnostics) {
    if (generation != m_generation) return;  // superseded by newer text
    if (!shaders::hasErrors(diagnostics)) {
        // The driver may still reject what glslang accepts; its messages join the list.
        auto driver = m_viewport->setSdf(prepared);
        for (const auto& d : driver)
            if (d.severity == shaders::Severity::Error) diagnostics.push_back(d);
        if (!shaders::hasErrors(driver)) emit sdfApplied();
    }
    m_diagnostics = std::move(diagnostics);
    emit diagnosticsChanged(m_diagnostics);
}

} // namespace sdfwb::app
