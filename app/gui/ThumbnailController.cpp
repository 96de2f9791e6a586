#include "ThumbnailController.h"

#include "BatchProcess.h"

#include <core/Log.h>
#include <jobs/JobJson.h>

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QStandardPaths>

namespace sdfwb::app {

ThumbnailController::ThumbnailController(QObject* parent)
    : QObject(parent), m_executable(BatchProcess::defaultExecutable()),
      m_folder(QStandardPaths::writableLocation(QStandardPaths::CacheLocation) + "/thumbnails") {}

ThumbnailController::~ThumbnailController() {
    if (isRendering()) {
        m_process->kill();
        m_process->waitForFinished(3000);
    }
}

bool ThumbnailController::isRendering() const { return m_process && m_process->state() != QProcess::NotRunning; }

QString ThumbnailController::thumbnailPath(const QString& sdfPath) const {
    QFile file(sdfPath);
    if (!file.open(QIODevice::ReadOnly)) return {};
    QCryptographicHash hash(QCryptographicHash::Sha1);
    hash.addData(QFileInfo(sdfPath).absoluteFilePath().toUtf8());
    hash.addData(file.readAll());
    hash.addData(QByteArray::number(kSize));
    return QDir(m_folder).filePath(QString::fromLatin1(hash.result().toHex().left(20)) + ".png");
}

QString ThumbnailController::cachedThumbnail(const QString& sdfPath) const {
    const QString path = thumbnailPath(sdfPath);
    return !path.isEmpty() && QFileInfo::exists(path) ? path : QString();
}

void ThumbnailController::request(const QStringList& sdfPaths) {
    QStringList missing;
    for (const QString& sdf : sdfPaths) {
        if (m_destination.contains(sdf)) continue; // being rendered
        const QString path = thumbnailPath(sdf);
        if (path.isEmpty()) continue;
        if (QFileInfo::exists(path))
            emit thumbnailReady(sdf, path);
        else
            missing << sdf;
    }
    if (missing.isEmpty()) return;
    if (!QDir().mkpath(m_folder)) {
        log::warning("thumbnails", "cannot create " + m_folder.toStdString());
        return;
    }
    if (!isRendering()) {
        m_process = new QProcess(this);
        m_pending.clear();
        connect(m_process, &QProcess::readyReadStandardOutput, this, &ThumbnailController::readOutput);
        connect(m_process, &QProcess::finished, this, [this, process = m_process] {
            readOutput();
            // Whatever the child did not answer is forgotten: a later request tries again.
            for (const QString& sdf : m_queue) m_destination.remove(sdf);
            m_queue.clear();
            process->deleteLater();
            if (m_process == process) m_process = nullptr;
        });
        m_process->setStandardErrorFile(QProcess::nullDevice()); // log lines only
        m_process->start(m_executable, {"--batch", "request", "-", "--protocol", "--each-line", "--quiet"});
    }
    for (const QString& sdf : missing) {
        values::RenderRequest request;
        request.frame.sdf.sdf = sdf.toStdString();
        request.frame.width = request.frame.height = kSize;
        request.frame.shading.mode = shaders::ShadingMode::Gooch;
        const QString destination = thumbnailPath(sdf);
        request.output = destination.toStdString();
        m_destination.insert(sdf, destination);
        m_queue << sdf;
        m_process->write(QByteArray::fromStdString(jobs::toJson(request)) + "\n");
    }
}

void ThumbnailController::readOutput() {
    if (!m_process) return;
    forEachMessage(*m_process, m_pending, [this](const jobs::WorkerMessage& message) {
        if (message.kind != jobs::WorkerMessage::Kind::End || m_queue.isEmpty()) return; // one {"end"} per request
        const QString sdf = m_queue.takeFirst();
        const QString image = m_destination.take(sdf);
        if (message.exitCode == 0 && QFileInfo::exists(image)) {
            ++m_rendered;
            emit thumbnailReady(sdf, image);
        } else {
            log::warning("thumbnails", "no thumbnail for " + sdf.toStdString());
        }
    });
}

} // namespace sdfwb::app
