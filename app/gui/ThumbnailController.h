#pragma once
// Thumbnails for the dataset browser: each SDF rendered small (Gooch shading, the default camera)
// by one child `sdfwb --batch request - --protocol --each-line` that takes every missing one in turn, cached
// as PNG files named by a hash of the SDF file's path and content, so an edited file gets a new
// one and an unchanged file is never rendered twice. Started on demand (the browser shown).

#include <QHash>
#include <QObject>
#include <QString>
#include <QStringList>

class QProcess;

namespace sdfwb::app {

class ThumbnailController : public QObject {
    Q_OBJECT
public:
    static constexpr int kSize = 96;

    explicit ThumbnailController(QObject* parent = nullptr);
    ~ThumbnailController() override;
    void setExecutable(const QString& path) { m_executable = path; }
    void setCacheFolder(const QString& folder) { m_folder = folder; }
    const QString& cacheFolder() const { return m_folder; }

    // The cached thumbnail of `sdfPath` for its current content (empty when there is none yet).
    QString cachedThumbnail(const QString& sdfPath) const;
    // Emits thumbnailReady for each SDF: at once for cached ones, the others as they render.
    void request(const QStringList& sdfPaths);
    bool isRendering() const;
    int rendered() const { return m_rendered; } // thumbnails rendered by this controller so far

signals:
    void thumbnailReady(const QString& sdfPath, const QString& imagePath);

private:
    QString thumbnailPath(const QString& sdfPath) const; // for the file's current content
    void readOutput();

    QString m_executable;
    QString m_folder;
    QProcess* m_process = nullptr;
    QStringList m_queue;                   // SDFs sent to the child, in order, awaiting their reports
    QHash<QString, QString> m_destination; // SDF path -> the PNG it is being rendered to
    QByteArray m_pending;
    int m_rendered = 0;
};

} // namespace sdfwb::app
