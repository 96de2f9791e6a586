#include <widgets/DatasetBrowser.h>

#include <QHeaderView>
#include <QLabel>
#include <QMap>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace sdfwb::widgets {

DatasetBrowser::DatasetBrowser(QWidget* parent) : QWidget(parent) {
    setObjectName("DatasetBrowser");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_tree = new QTreeWidget;
    m_tree->setHeaderLabels({tr("SDF"), tr("type"), tr("animated")});
    m_tree->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_details = new QLabel;
    m_details->setWordWrap(true);
    m_details->setObjectName("details");
    layout->addWidget(m_tree, 1);
    layout->addWidget(m_details);
    connect(m_tree, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        int index = item ? item->data(0, Qt::UserRole).toInt() : -1;
        if (index < 0 || index >= m_items.size()) return m_details->clear();
        const DatasetItem& d = m_items[index];
        m_details->setText(tr("<b>%1</b> (%2, %3)<br>%4 - %5<br><small>%6</small>")
                               .arg(d.name, d.category, d.type, d.author, d.license, d.notes));
    });
    connect(m_tree, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
        int index = item->data(0, Qt::UserRole).toInt();
        if (index >= 0 && index < m_items.size()) emit openRequested(m_items[index].path);
    });
}

void DatasetBrowser::setItems(const QList<DatasetItem>& items) {
    m_items = items;
    m_tree->clear();
    QMap<QString, QTreeWidgetItem*> categories;
    for (int i = 0; i < items.size(); ++i) {
        const DatasetItem& d = items[i];
        QTreeWidgetItem*& category = categories[d.category];
        if (!category) {
            category = new QTreeWidgetItem(m_tree, {d.category});
            category->setData(0, Qt::UserRole, -1);
            category->setFirstColumnSpanned(true);
        }
        auto* item = new QTreeWidgetItem(category, {d.name, d.type, d.animated ? tr("yes") : QString()});
        item->setData(0, Qt::UserRole, i);
        item->setToolTip(0, d.notes);
    }
    m_tree->expandAll();
}

int DatasetBrowser::count() const { return m_items.size(); }

bool DatasetBrowser::activate(const QString& name) {
    for (const DatasetItem& d : m_items)
        if (d.name.compare(name, Qt::CaseInsensitive) == 0) {
            emit openRequested(d.path);
            return true;
        }
    return false;
}

} // namespace sdfwb::widgets
