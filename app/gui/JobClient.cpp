#include "JobClient.h"

namespace sdfwb::app {

void JobClient::conclude(bool ok, bool cancelled, const std::string& report, const QString& message,
                         const jobs::JobError& error) {
    m_error = ok ? jobs::JobError{} : error;
    emit diagnosticsReported(m_error.diagnostics);
    emit finished(ok, cancelled, report, message);
}

} // namespace sdfwb::app
