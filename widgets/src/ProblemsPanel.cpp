#include <widgets/ProblemsPanel.h>

#include <QListWidget>
#include <QStyle>
#include <QVBoxLayout>

#include <algorithm>

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
    m_document = diagnostics;
    rebuild();
}

void ProblemsPanel::setJobDiagnostics(const QString& job, const std::vector<shaders::Diagnostic>& diagnostics) {
    auto it = std::find_if(m_jobs.begin(), m_jobs.end(), [&](const auto& entry) { return entry.first == job; });
    if (it == m_jobs.end()) {
        if (diagnostics.empty()) return;
        it = m_jobs.insert(m_jobs.end(), {job, {}});
    }
    it->second = diagnostics;
    rebuild();
}

void ProblemsPanel::rebuild() {
    m_list->clear();
    m_rows.clear();
    auto add = [this](const QString& prefix, const shaders::Diagnostic& d) {
        auto* item = new QListWidgetItem(prefix + QString::fromStdString(shaders::formatDiagnostic(d)));
        item->setIcon(style()->standardIcon(d.severity == shaders::Severity::Error ? QStyle::SP_MessageBoxCritical
                                                                                   : QStyle::SP_MessageBoxWarning));
        m_list->addItem(item);
        m_rows.push_back(d);
    };
    for (const shaders::Diagnostic& d : m_document) add({}, d);
    for (const auto& [job, diagnostics] : m_jobs)
        for (const shaders::Diagnostic& d : diagnostics) add(tr("%1 job: ").arg(job), d);
}

int ProblemsPanel::count() const { return int(m_rows.size()); }

QString ProblemsPanel::rowText(int row) const {
    return row >= 0 && row < m_list->count() ? m_list->item(row)->text() : QString();
}

void ProblemsPanel::activate(int row) {
    if (row < 0 || row >= int(m_rows.size())) return;
    const shaders::Diagnostic& d = m_rows[std::size_t(row)];
    emit locationActivated(QString::fromStdString(d.file), d.line, d.column);
}

} // namespace sdfwb::widgets
