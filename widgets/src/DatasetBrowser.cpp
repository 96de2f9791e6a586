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
        if (index < 0 || index >= count()) return m_details->clear();
        const values::ListItem& d = m_items[std::size_t(index)];
        auto q = [](const std::string& text) { return QString::fromStdString(text); };
        const QString measured = d.measuredType.empty() ? tr("not measured") : tr("measured %1").arg(q(d.measuredType));
        m_details->setText(
            tr("<b>%1</b> (%2; declared %3, %4)<br>%5 - %6<br><small>%7</small>")
                .arg(q(d.name), q(d.category), q(d.declaredType), measured, q(d.author), q(d.license), q(d.notes)));
    });
    connect(m_tree, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
        int index = item->data(0, Qt::UserRole).toInt();
        if (index >= 0 && index < count()) emit openRequested(QString::fromStdString(m_items[std::size_t(index)].path));
    });
}

void DatasetBrowser::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    emit shown();
}

void DatasetBrowser::setItems(const std::vector<values::ListItem>& items) {
    m_items = items;
    m_tree->clear();
    m_byPath.clear();
    m_thumbnails.clear();
    QMap<QString, QTreeWidgetItem*> categories;
    for (int i = 0; i < int(items.size()); ++i) {
        const values::ListItem& d = items[std::size_t(i)];
        const QString name = QString::fromStdString(d.name), declared = QString::fromStdString(d.declaredType),
                      measured = QString::fromStdString(d.measuredType);
        QTreeWidgetItem*& category = categories[QString::fromStdString(d.category)];
        if (!category) {
            category = new QTreeWidgetItem(m_tree, {QString::fromStdString(d.category)});
            category->setData(0, Qt::UserRole, -1);
            category->setFirstColumnSpanned(true);
        }
        // The measured type, marked when it differs from the declared one.
        QString type = measured.isEmpty()     ? declared + tr(" (declared)")
                       : measured == declared ? measured
                                              : tr("%1 (declared %2)").arg(measured, declared);
        auto* item = new QTreeWidgetItem(
            category, {name, type, d.renderMilliseconds ? QString::number(*d.renderMilliseconds, 'f', 1) : QString(),
                       d.animated ? tr("yes") : QString()});
        item->setData(0, Qt::UserRole, i);
        item->setToolTip(0, QString::fromStdString(d.notes));
        item->setTextAlignment(2, Qt::AlignRight | Qt::AlignVCenter);
        m_byPath.insert(QString::fromStdString(d.path), item);
    }
    m_tree->expandAll();
}

void DatasetBrowser::setReportNote(const QString& note) { m_note->setText(note); }

int DatasetBrowser::count() const { return int(m_items.size()); }

QStringList DatasetBrowser::paths() const {
    QStringList out;
    for (const values::ListItem& d : m_items) out << QString::fromStdString(d.path);
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
    for (const values::ListItem& d : m_items)
        if (QString::fromStdString(d.name).compare(name, Qt::CaseInsensitive) == 0) {
            emit openRequested(QString::fromStdString(d.path));
            return true;
        }
    return false;
}

} // namespace sdfwb::widgets
