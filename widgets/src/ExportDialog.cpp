#include <widgets/ExportDialog.h>

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace sdfwb::widgets {

ExportDialog::ExportDialog(Kind kind, QWidget* parent) : QDialog(parent), m_kind(kind) {
    bool video = kind == Kind::Video;
    setWindowTitle(video ? tr("Export animation") : tr("Save screenshot"));
    setObjectName(video ? "VideoExportDialog" : "ScreenshotDialog");
    auto* form = new QFormLayout;
    auto* outputRow = new QHBoxLayout;
    m_output = new QLineEdit;
    m_output->setObjectName("output");
    auto* browse = new QPushButton(tr("Browse..."));
    outputRow->addWidget(m_output, 1);
    outputRow->addWidget(browse);
    form->addRow(tr("File:"), outputRow);
    auto* sizeRow = new QHBoxLayout;
    m_width = new QSpinBox;
    m_width->setRange(2, 16384);
    m_height = new QSpinBox;
    m_height->setRange(2, 16384);
    sizeRow->addWidget(m_width);
    sizeRow->addWidget(new QLabel(QString::fromUtf8("×")));
    sizeRow->addWidget(m_height);
    form->addRow(tr("Size:"), sizeRow);
    if (video) {
        m_seconds = new QDoubleSpinBox;
        m_seconds->setRange(0.1, 3600.0);
        m_seconds->setSuffix(" s");
        form->addRow(tr("Length:"), m_seconds);
        m_fps = new QSpinBox;
        m_fps->setRange(1, 240);
        form->addRow(tr("Frame rate:"), m_fps);
        m_turntable = new QCheckBox(tr("Turntable (orbit once around Y)"));
        form->addRow(m_turntable);
    }
    m_progress = new QProgressBar;
    m_progress->setRange(0, 1000);
    m_progress->setVisible(video);
    m_message = new QLabel;
    m_message->setWordWrap(true);
    m_message->setObjectName("message");
    auto* buttons = new QDialogButtonBox;
    m_start = buttons->addButton(video ? tr("Export") : tr("Save"), QDialogButtonBox::AcceptRole);
    m_start->setObjectName("start");
    m_cancel = buttons->addButton(tr("Cancel export"), QDialogButtonBox::ActionRole);
    m_cancel->setObjectName("cancel");
    m_cancel->setEnabled(false);
    m_cancel->setVisible(video);
    QPushButton* close = buttons->addButton(QDialogButtonBox::Close);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_progress);
    layout->addWidget(m_message);
    layout->addWidget(buttons);
    setRequest(values::AnimateRequest{});

    connect(browse, &QPushButton::clicked, this, [this, video] {
        QString filter = video ? tr("MP4 video (*.mp4)") : tr("Images (*.png *.jpg *.exr)");
        QString path = QFileDialog::getSaveFileName(this, windowTitle(), m_output->text(), filter);
        if (!path.isEmpty()) m_output->setText(path);
    });
    connect(m_start, &QPushButton::clicked, this, [this] {
        if (m_output->text().trimmed().isEmpty()) {
            setMessage(tr("Choose a file to write."), true);
            return;
        }
        emit startRequested(request());
    });
    connect(m_cancel, &QPushButton::clicked, this, &ExportDialog::cancelRequested);
    connect(close, &QPushButton::clicked, this, [this] {
        if (m_cancel->isEnabled()) emit cancelRequested();
        reject();
    });
}

void ExportDialog::setRequest(const values::AnimateRequest& r) {
    m_output->setText(QString::fromStdString(r.output));
    m_width->setValue(r.frame.width);
    m_height->setValue(r.frame.height);
    if (m_seconds) m_seconds->setValue(double(r.seconds));
    if (m_fps) m_fps->setValue(r.framesPerSecond);
    if (m_turntable) m_turntable->setChecked(r.turntable);
}

values::AnimateRequest ExportDialog::request() const {
    values::AnimateRequest r;
    r.output = m_output->text().trimmed().toStdString();
    r.frame.width = m_width->value();
    r.frame.height = m_height->value();
    if (m_seconds) r.seconds = float(m_seconds->value());
    if (m_fps) r.framesPerSecond = m_fps->value();
    if (m_turntable) r.turntable = m_turntable->isChecked();
    return r;
}

void ExportDialog::setRunning(bool running) {
    m_start->setEnabled(!running);
    m_cancel->setEnabled(running);
    if (running) m_progress->setValue(0);
}

void ExportDialog::setProgress(quint64 done, quint64 total) {
    m_progress->setValue(total ? int(1000.0 * double(done) / double(total)) : 0);
}

void ExportDialog::setMessage(const QString& message, bool error) {
    m_message->setText(message);
    m_message->setStyleSheet(error ? "color: #b00020;" : "");
}

} // namespace sdfwb::widgets
