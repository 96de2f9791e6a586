#pragma once
// Sample clouds in the viewport: any .bin/.npz/.ply sample file (or a sampling preview) drawn over
// the traced surface, each point coloured by its gradient. Rows with NaN or Inf are counted, not
// drawn; files over kMaxPoints rows are thinned evenly (every k-th row) and the message says so.

#include <core/Expected.h>

#include <QObject>
#include <QString>

#include <cstdint>

namespace sdfwb::widgets {
class ViewportWidget;
}

namespace sdfwb::app {

class CloudController : public QObject {
    Q_OBJECT
public:
    static constexpr std::uint64_t kMaxPoints = 2000000;

    struct Loaded {
        std::uint64_t rows = 0;    // in the file
        std::uint64_t drawn = 0;   // points in the viewport
        std::uint64_t badRows = 0; // NaN or Inf in position or distance (not drawn)
        std::uint64_t stride = 1;  // every stride-th row was read
    };

    explicit CloudController(widgets::ViewportWidget* viewport, QObject* parent = nullptr);
    // Reads `path` and shows its cloud; an unreadable file leaves the current cloud as it was.
    Expected<Loaded> show(const QString& path);
    void hide();
    bool isShown() const;

signals:
    // A line for the status bar: what was shown, or why not.
    void message(const QString& text);

private:
    widgets::ViewportWidget* m_viewport;
};

} // namespace sdfwb::app
