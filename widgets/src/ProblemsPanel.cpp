#include <widgets/ProblemsPanel.h>

#include <QListWidget>
#include <QStyle>
#include <QVBoxLayout>

namespace sdfwb::widgets {

ProblemsPanel::ProblemsPanel(QWidget* parent) : QWidget(parent) {
    setObjectName("ProblemsPanel");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_list = new QListWidget;
    layout->addWidget(m_list);
    connect(m_list, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) { activate(m_list->row(item)); });
    connect(m_list, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) { activate(m_list->row(item)); });
}

void ProblemsPanel::setDiagnostics(const std::vector<shaders::Diagnostic>& diagnostics) {
    m_diagnostics = diagnostics;
    m_list->clear();
    for (const shaders::Diagnostic& d : diagnostics) {
        auto* item = new QListWidgetItem(QString::fromStdString(shaders::formatDiagnostic(d)));
        item->setIcon(style()->standardIcon(d.severity == shaders::Severity::Error ? QStyle::SP_MessageBoxCritical
                                                                                   : QStyle::SP_MessageBoxWarning));
        m_list->addItem(item);
    }
}

int ProblemsPanel::count() const { return int(m_diagnostics.size()); }

void ProblemsPanel::activate(int row) {
    if (row < 0 || row >= int(m_diagnostics.size())) return;
    const shaders::Diagnostic& d = m_diagnostics[std::size_t(row)];
    emit locationActivated(QString::fromStdString(d.file), d.line, d.column);
}

} // namespace sdfwb::widgets
