#include "CloudController.h"

#include <core/Log.h>
#include <sampling/SampleFile.h>
#include <widgets/ViewportWidget.h>

#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <vector>

namespace sdfwb::app {

CloudController::CloudController(widgets::ViewportWidget* viewport, QObject* parent) : QObject(parent), m_viewport(viewport) {}

Expected<CloudController::Loaded> CloudController::show(const QString& path) {
    auto reader = sampling::SampleReader::open(path.toStdString());
    if (!reader) {
        emit message(tr("Cannot show %1: %2").arg(path, QString::fromStdString(reader.error().message)));
        return reader.error();
    }
    Loaded loaded;
    loaded.rows = (*reader)->rows();
    loaded.stride = std::max<std::uint64_t>(1, (loaded.rows + kMaxPoints - 1) / kMaxPoints);
    std::vector<float> positions, gradients;
    positions.reserve(3 * std::min(loaded.rows, kMaxPoints));
    gradients.reserve(positions.capacity());
    // Chunks of whole rows; every stride-th row of each is kept (strides start at row 0).
    constexpr std::uint64_t kChunk = 1 << 16;
    std::vector<float> p(3 * kChunk), d(kChunk), g(3 * kChunk);
    for (std::uint64_t first = 0; first < loaded.rows; first += kChunk) {
        const std::size_t n = std::size_t(std::min(kChunk, loaded.rows - first));
        if (auto ok = (*reader)->read(first, n, p.data(), d.data(), g.data()); !ok) {
            emit message(tr("Cannot show %1: %2").arg(path, QString::fromStdString(ok.error().message)));
            return ok.error();
        }
        for (std::size_t i = 0; i < n; ++i) {
            const bool finite =
                std::isfinite(p[3 * i]) && std::isfinite(p[3 * i + 1]) && std::isfinite(p[3 * i + 2]) && std::isfinite(d[i]);
            if (!finite) ++loaded.badRows;
            if ((first + i) % loaded.stride != 0 || !finite) continue;
            positions.insert(positions.end(), {p[3 * i], p[3 * i + 1], p[3 * i + 2]});
            gradients.insert(gradients.end(), {g[3 * i], g[3 * i + 1], g[3 * i + 2]});
        }
    }
    m_viewport->setPointCloud(positions, gradients);
    loaded.drawn = m_viewport->pointCloudSize();
    QString text = tr("Sample cloud: %1, %2 rows, %3 drawn, %4 NaN/Inf rows not drawn; coloured by gradient direction")
                       .arg(QFileInfo(path).fileName())
                       .arg(loaded.rows)
                       .arg(loaded.drawn)
                       .arg(loaded.badRows);
    if (loaded.stride > 1) text += tr(" (every %1th row)").arg(loaded.stride);
    log::info("cloud", text.toStdString());
    emit message(text);
    return loaded;
}

void CloudController::hide() {
    m_viewport->setPointCloud({}, {});
    emit message(tr("Sample cloud hidden"));
}

bool CloudController::isShown() const { return m_viewport->pointCloudSize() > 0; }

} // namespace sdfwb::app
