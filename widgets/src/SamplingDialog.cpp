#include <widgets/SamplingDialog.h>

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpressionValidator>
#include <QSpinBox>
#include <QVBoxLayout>

namespace sdfwb::widgets {

SamplingDialog::SamplingDialog(const QStringList& patterns, QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("Sample SDF"));
    setObjectName("SamplingDialog");
    auto* form = new QFormLayout;
    m_sdf = new QLabel;
    form->addRow(tr("SDF:"), m_sdf);
    m_pattern = new QComboBox;
    m_pattern->setEditable(true); // a sampler file path may be typed too
    m_pattern->addItems(patterns);
    m_pattern->setObjectName("pattern");
    form->addRow(tr("Pattern:"), m_pattern);
    auto* digits = new QRegularExpressionValidator(QRegularExpression("[0-9]{1,19}"), this);
    m_count = new QLineEdit("1000000");
    m_count->setValidator(digits);
    m_count->setObjectName("count");
    form->addRow(tr("Samples (N):"), m_count);
    m_seed = new QLineEdit("0");
    m_seed->setValidator(digits);
    m_seed->setObjectName("seed");
    form->addRow(tr("Seed:"), m_seed);
    m_time = new QDoubleSpinBox;
    m_time->setRange(-1e6, 1e6);
    m_time->setDecimals(3);
    m_time->setSuffix(" s");
    form->addRow(tr("Time:"), m_time);
    auto* outputRow = new QHBoxLayout;
    m_output = new QLineEdit;
    m_output->setObjectName("output");
    auto* browse = new QPushButton(tr("Browse..."));
    outputRow->addWidget(m_output, 1);
    outputRow->addWidget(browse);
    form->addRow(tr("Output file:"), outputRow);
    m_format = new QComboBox;
    m_format->addItems({tr("from extension"), "bin", "npz", "ply"});
    form->addRow(tr("Format:"), m_format);
    m_pointSize = new QSpinBox;
    m_pointSize->setObjectName("pointSize");
    m_pointSize->setRange(1, 32);
    m_pointSize->setValue(3);
    m_pointSize->setSuffix(tr(" px"));
    m_pointSize->setToolTip(tr("Size of the previewed points in the viewport"));
    form->addRow(tr("Preview point size:"), m_pointSize);

    m_progress = new QProgressBar;
    m_progress->setRange(0, 1000);
    m_progress->setValue(0);
    m_message = new QLabel;
    m_message->setWordWrap(true);
    m_message->setObjectName("message");

    auto* buttons = new QDialogButtonBox;
    m_start = buttons->addButton(tr("Sample"), QDialogButtonBox::AcceptRole);
    m_start->setObjectName("start");
    m_preview = buttons->addButton(tr("Preview"), QDialogButtonBox::ActionRole);
    m_preview->setObjectName("preview");
    m_preview->setToolTip(tr("Draws up to %1 points of this pattern, seed and time in the viewport, coloured by gradient, "
                             "without writing a file")
                              .arg(kPreviewPoints));
    m_cancel = buttons->addButton(tr("Cancel run"), QDialogButtonBox::ActionRole);
    m_cancel->setObjectName("cancel");
    m_cancel->setEnabled(false);
    QPushButton* close = buttons->addButton(QDialogButtonBox::Close);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_progress);
    layout->addWidget(m_message);
    layout->addWidget(buttons);

    connect(browse, &QPushButton::clicked, this, [this] {
        QString path =
            QFileDialog::getSaveFileName(this, tr("Samples file"), m_output->text(), tr("Samples (*.npz *.bin *.ply)"));
        if (!path.isEmpty()) m_output->setText(path);
    });
    connect(m_start, &QPushButton::clicked, this, [this] {
        if (m_output->text().trimmed().isEmpty()) {
            setMessage(tr("Choose an output file (.npz, .bin or .ply)."), true);
            return;
        }
        emit startRequested(request());
    });
    connect(m_preview, &QPushButton::clicked, this, [this] { emit previewRequested(request()); });
    connect(m_pointSize, &QSpinBox::valueChanged, this, &SamplingDialog::pointSizeChanged);
    connect(m_cancel, &QPushButton::clicked, this, &SamplingDialog::cancelRequested);
    connect(close, &QPushButton::clicked, this, [this] {
        if (m_cancel->isEnabled()) emit cancelRequested();
        reject();
    });
}

int SamplingDialog::pointSize() const { return m_pointSize->value(); }

void SamplingDialog::setSdfName(const QString& name) { m_sdf->setText(name); }

values::SampleRequest SamplingDialog::request() const {
    values::SampleRequest r;
    r.pattern = m_pattern->currentText().trimmed().toStdString();
    r.count = m_count->text().toULongLong();
    r.seed = m_seed->text().toULongLong();
    r.time = float(m_time->value());
    r.output = m_output->text().trimmed().toStdString();
    r.format = m_format->currentIndex() == 0 ? std::string() : m_format->currentText().toStdString();
    return r;
}

void SamplingDialog::setRequest(const values::SampleRequest& r) {
    m_pattern->setCurrentText(QString::fromStdString(r.pattern));
    m_count->setText(QString::number(r.count));
    m_seed->setText(QString::number(r.seed));
    m_time->setValue(double(r.time));
    m_output->setText(QString::fromStdString(r.output));
    const int format = m_format->findText(QString::fromStdString(r.format));
    m_format->setCurrentIndex(format < 0 ? 0 : format);
}

void SamplingDialog::setRunning(bool running) {
    m_start->setEnabled(!running);
    m_preview->setEnabled(!running);
    m_cancel->setEnabled(running);
    if (running) m_progress->setValue(0);
}

void SamplingDialog::setProgress(std::uint64_t done, std::uint64_t total) {
    m_progress->setValue(total ? int(1000.0 * double(done) / double(total)) : 0);
}

void SamplingDialog::setMessage(const QString& message, bool error) {
    for (QWidget* marked : m_marked) {
        marked->setStyleSheet({});
        marked->setProperty("fault", false);
    }
    m_marked.clear();
    m_message->setText(message);
    m_message->setStyleSheet(error ? "color: #b00020;" : "");
}

std::pair<QWidget*, QString> SamplingDialog::field(const std::string& path) const {
    if (path == "pattern") return {m_pattern, tr("Pattern")};
    if (path == "n") return {m_count, tr("Samples (N)")};
    if (path == "seed") return {m_seed, tr("Seed")};
    if (path == "time") return {m_time, tr("Time")};
    if (path == "output") return {m_output, tr("Output file")};
    if (path == "format") return {m_format, tr("Format")};
    return {nullptr, {}};
}

void SamplingDialog::setFailure(const std::string& message, const std::vector<KeyMention>& keys) {
    const std::string text = worded(message, keys, [this](const std::string& path) {
        const QString label = field(path).second;
        return label.isEmpty() ? "'" + std::string(keyName(path)) + "'" : label.toStdString();
    });
    setMessage(QString::fromStdString(text), true);
    for (const KeyMention& key : keys) {
        QWidget* widget = field(key.path).first;
        if (!widget || widget->property("fault").toBool()) continue;
        widget->setProperty("fault", true);
        widget->setStyleSheet("border: 2px solid #b00020;");
        m_marked.push_back(widget);
    }
    if (!m_marked.empty()) m_marked.front()->setFocus();
}

} // namespace sdfwb::widgets
