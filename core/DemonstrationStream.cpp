#include "DemonstrationStream.h"

#include "DemonstrationCsv.h"

#include <QDir>
#include <QFileInfo>

namespace prisca::core {

DemonstrationStream::~DemonstrationStream() {
    QString ignored;
    close(&ignored);
}

bool DemonstrationStream::open(const QString& path, const Demonstration& header, QString* error) {
    close(error);
    QDir().mkpath(QFileInfo(path).absolutePath());
    file_.setFileName(path);
    if (!file_.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        *error = QStringLiteral("%1: %2").arg(path, file_.errorString());
        return false;
    }
    Demonstration empty = header;
    empty.time.resize(0);
    empty.states.resize(0, header.stateDimension());
    empty.actions.resize(0, header.actionDimension());
    pending_ = formatDemonstrationCsvHeader(empty);
    return flush(error);  // the header on disk at once: a take killed early is still a file
}

bool DemonstrationStream::append(double t, const Eigen::VectorXd& state,
                                 const Eigen::VectorXd& action, QString* error) {
    appendDemonstrationCsvRow(pending_, t, state, action);
    if (sinceFlush_.isValid() && sinceFlush_.elapsed() < flushIntervalMs_) {
        return true;
    }
    return flush(error);
}

bool DemonstrationStream::flush(QString* error) {
    sinceFlush_.start();
    if (!file_.isOpen() || pending_.isEmpty()) {
        return true;
    }
    if (file_.write(pending_) != pending_.size() || !file_.flush()) {
        *error = QStringLiteral("%1: %2").arg(file_.fileName(), file_.errorString());
        return false;
    }
    pending_.clear();
    return true;
}

bool DemonstrationStream::close(QString* error) {
    if (!file_.isOpen()) {
        return true;
    }
    const bool ok = flush(error);
    file_.close();
    return ok;
}

}  // namespace prisca::core
