#pragma once
// The dataset by category: a thumbnail, the name, the measured type (the declared one when the
// dataset report has no measurement) and the render time from the dataset report; the metadata
// (author, license, notes) as a tooltip and below the tree. Activating an entry asks to open its
// file; "New from template" asks for a new SDF. UI thread only.

#include <values/Requests.h>

#include <QHash>
#include <QWidget>

#include <optional>
#include <vector>

class QLabel;
class QTreeWidget;
class QTreeWidgetItem;

namespace sdfwb::widgets {

class DatasetBrowser : public QWidget {
    Q_OBJECT
public:
    explicit DatasetBrowser(QWidget* parent = nullptr);
    void setItems(const std::vector<values::ListItem>& items); // the list job's entries, measured values included
    // The report's machine line, shown under the tree ("render times on ...").
    void setReportNote(const QString& note);
    int count() const;
    QStringList paths() const;
    // Shows `imagePath` as the thumbnail of the entry whose file is `sdfPath`; false when unknown.
    bool setThumbnail(const QString& sdfPath, const QString& imagePath);
    int thumbnailCount() const { return m_thumbnails.size(); }
    QString thumbnailOf(const QString& sdfPath) const { return m_thumbnails.value(sdfPath); }
    // Activates the entry named `name` as a double-click would (tests); false when absent.
    bool activate(const QString& name);
    QTreeWidget* tree() const { return m_tree; }

signals:
    void openRequested(const QString& path);
    void newRequested();
    void shown(); // the browser became visible (thumbnails are made on demand)

protected:
    void showEvent(QShowEvent* event) override;

private:
    QTreeWidget* m_tree = nullptr;
    QLabel* m_details = nullptr;
    QLabel* m_note = nullptr;
    std::vector<values::ListItem> m_items;
    QHash<QString, QTreeWidgetItem*> m_byPath;
    QHash<QString, QString> m_thumbnails; // SDF path -> image shown
};

} // namespace sdfwb::widgets
