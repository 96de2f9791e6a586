#include <widgets/LogPanel.h>

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QVBoxLayout>

namespace sdfwb::widgets {
namespace {

constexpr int kMaxLines = 5000;

int severity(const QString& line) {
    if (line.contains("[error]")) return 2;
    if (line.contains("[warning]")) return 1;
    return 0;
}

} // namespace

LogPanel::LogPanel(QWidget* parent) : QWidget(parent) {
    setObjectName("LogPanel");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    auto* row = new QHBoxLayout;
    m_level = new QComboBox;
    m_level->setObjectName("logLevel");
    m_level->addItems({tr("All"), tr("Warnings and errors"), tr("Errors")});
    m_path = new QLabel;
    m_path->setTextInteractionFlags(Qt::TextSelectableByMouse);
    row->addWidget(new QLabel(tr("Show:")));
    row->addWidget(m_level);
    row->addWidget(m_path, 1);
    m_view = new QPlainTextEdit;
    m_view->setObjectName("logView");
    m_view->setReadOnly(true);
    m_view->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_view->setMaximumBlockCount(kMaxLines);
    QFont font("monospace");
    font.setStyleHint(QFont::Monospace);
    font.setPointSizeF(8.5);
    m_view->setFont(font);
    layout->addLayout(row);
    layout->addWidget(m_view, 1);
    connect(m_level, &QComboBox::currentIndexChanged, this, &LogPanel::refilter);
}

void LogPanel::setFilePath(const QString& path) { m_path->setText(tr("file: %1").arg(path)); }

bool LogPanel::shown(const QString& line) const { return severity(line) >= m_level->currentIndex(); }

void LogPanel::appendLine(const QString& line) {
    m_lines.append(line);
    if (m_lines.size() > kMaxLines) m_lines.removeFirst();
    if (!shown(line)) return;
    const int level = severity(line);
    const QString colour = level == 2 ? "#d03030" : level == 1 ? "#c87810" : QString();
    QScrollBar* bar = m_view->verticalScrollBar();
    const bool atEnd = bar->value() == bar->maximum();
    if (colour.isEmpty())
        m_view->appendPlainText(line);
    else
        m_view->appendHtml(QString("<span style='color:%1'>%2</span>").arg(colour, line.toHtmlEscaped()));
    if (atEnd) bar->setValue(bar->maximum());
}

QString LogPanel::text() const { return m_view->toPlainText(); }

void LogPanel::refilter() {
    const QStringList lines = m_lines;
    m_lines.clear();
    m_view->clear();
    for (const QString& line : lines) appendLine(line);
}

} // namespace sdfwb::widgets
