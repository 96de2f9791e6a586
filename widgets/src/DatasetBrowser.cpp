#include <widgets/DatasetBrowser.h>

#include <QHeaderView>
#include <QIcon>
#include <QLabel>
#include <QMap>
#include <QPixmap>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace sdfwb::widgets {

DatasetBrowser::DatasetBrowser(QWidget* parent) : QWidget(parent) {
    setObjectName("DatasetBrowser");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* create = new QPushButton(tr("New SDF from template"));
    create->setObjectName("newFromTemplate");
    m_tree = new QTreeWidget;
    m_tree->setObjectName("datasetTree");
    m_tree->setHeaderLabels({tr("SDF"), tr("measured type"), tr("render ms"), tr("animated")});
    m_tree->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_tree->setIconSize(QSize(48, 48));
    m_details = new QLabel;
    m_details->setWordWrap(true);
    m_details->setObjectName("details");
    m_note = new QLabel;
    m_note->setWordWrap(true);
    m_note->setObjectName("reportNote");
    layout->addWidget(create);
    layout->addWidget(m_tree, 1);
    layout->addWidget(m_details);
    layout->addWidget(m_note);
    connect(create, &QPushButton::clicked, this, &DatasetBrowser::newRequested);
    connect(m_tree, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        int index = item ? item->data(0, Qt::UserRole).toInt() : -1;
        if (index < 0 || index >= m_items.size()) return m_details->clear();
        const DatasetItem& d = m_items[index];
        const QString measured = d.measuredType.isEmpty() ? tr("not measured") : tr("measured %1").arg(d.measuredType);
        m_details->setText(tr("<b>%1</b> (%2; declared %3, %4)<br>%5 - %6<br><small>%7</small>")
                               .arg(d.name, d.category, d.type, measured, d.author, d.license, d.notes));
    });
    connect(m_tree, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
        int index = item->data(0, Qt::UserRole).toInt();
        if (index >= 0 && index < m_items.size()) emit openRequested(m_items[index].path);
    });
}

void DatasetBrowser::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    emit shown();
}

void DatasetBrowser::setItems(const QList<DatasetItem>& items) {
    m_items = items;
    m_tree->clear();
    m_byPath.clear();
    m_thumbnails.clear();
    QMap<QString, QTreeWidgetItem*> categories;
    for (int i = 0; i < items.size(); ++i) {
        const DatasetItem& d = items[i];
        QTreeWidgetItem*& category = categories[d.category];
        if (!category) {
            category = new QTreeWidgetItem(m_tree, {d.category});
            category->setData(0, Qt::UserRole, -1);
            category->setFirstColumnSpanned(true);
        }
        // The measured type, marked when it differs from the declared one.
        QString type = d.measuredType.isEmpty()   ? d.type + tr(" (declared)")
                       : d.measuredType == d.type ? d.measuredType
                                                  : tr("%1 (declared %2)").arg(d.measuredType, d.type);
        auto* item = new QTreeWidgetItem(
            category, {d.name, type, d.renderMilliseconds ? QString::number(*d.renderMilliseconds, 'f', 1) : QString(),
                       d.animated ? tr("yes") : QString()});
        item->setData(0, Qt::UserRole, i);
        item->setToolTip(0, d.notes);
        item->setTextAlignment(2, Qt::AlignRight | Qt::AlignVCenter);
        m_byPath.insert(d.path, item);
    }
    m_tree->expandAll();
}

void DatasetBrowser::setReportNote(const QString& note) { m_note->setText(note); }

int DatasetBrowser::count() const { return m_items.size(); }

QStringList DatasetBrowser::paths() const {
    QStringList out;
    for (const DatasetItem& d : m_items) out << d.path;
    return out;
}

bool DatasetBrowser::setThumbnail(const QString& sdfPath, const QString& imagePath) {
    QTreeWidgetItem* item = m_byPath.value(sdfPath);
    if (!item) return false;
    QPixmap pixmap(imagePath);
    if (pixmap.isNull()) return false;
    item->setIcon(0, QIcon(pixmap));
    m_thumbnails.insert(sdfPath, imagePath);
    return true;
}

bool DatasetBrowser::activate(const QString& name) {
    for (const DatasetItem& d : m_items)
        if (d.name.compare(name, Qt::CaseInsensitive) == 0) {
            emit openRequested(d.path);
            return true;
        }
    return false;
}

} // namespace sdfwb::widgets
