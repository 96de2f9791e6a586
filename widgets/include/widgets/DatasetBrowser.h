#pragma once
// The dataset by category: name, declared type, animated; the metadata (author, license, notes)
// as a tooltip and below the tree. Activating an entry asks to open its file. UI thread only.

#include <QWidget>

class QLabel;
class QTreeWidget;

namespace sdfwb::widgets {

struct DatasetItem {
    QString name, category, type, author, license, notes, path;
    bool animated = false;
};

class DatasetBrowser : public QWidget {
    Q_OBJECT
public:
    explicit DatasetBrowser(QWidget* parent = nullptr);
    void setItems(const QList<DatasetItem>& items);
    int count() const;
    // Activates the entry named `name` as a double-click would (tests); false when absent.
    bool activate(const QString& name);

signals:
    void openRequested(const QString& path);

private:
    QTreeWidget* m_tree = nullptr;
    QLabel* m_details = nullptr;
    QList<DatasetItem> m_items;
};

} // namespace sdfwb::widgets
