#include "DemonstrationStream.h"

#include "DemonstrationCsv.h"
#include "DeviationModel.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <unistd.h>

namespace prisca::core {

DemonstrationStream::~DemonstrationStream() {
    if (file_.isOpen()) {
        QString ignored;
        flush(&ignored);
        file_.close();
    }
}

bool DemonstrationStream::open(const QString& path, const Demonstration& header,
                               const std::vector<int>& angleIndices, QString* error) {
    abandon();
    if (!(header.dt >= Demonstration::kMinDt && header.dt <= Demonstration::kMaxDt)) {
        *error = QStringLiteral("%1: a recording needs a sampling period from %2 to %3 s")
                     .arg(path)
                     .arg(Demonstration::kMinDt)
                     .arg(Demonstration::kMaxDt);
        return false;
    }
    for (int a : angleIndices) {
        if (a < 0 || a >= header.stateNames.size()) {
            *error = QStringLiteral("%1: angle column %2 is not a state").arg(path).arg(a);
            return false;
        }
    }
    QDir().mkpath(QFileInfo(path).absolutePath());
    path_ = path;
    file_.setFileName(partPath(path));
    if (!file_.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        *error = QStringLiteral("%1: %2").arg(file_.fileName(), file_.errorString());
        return false;
    }
    header_ = header;
    header_.time.resize(0);
    header_.states.resize(0, header.stateNames.size());
    header_.actions.resize(0, header.actionNames.size());
    angles_ = angleIndices;
    started_ = false;
    rowStates_.clear();
    rowActions_.clear();
    pending_ = formatDemonstrationCsvHeader(header_);
    return flush(error);  // the header on disk at once: a take killed early is still a file
}

void DemonstrationStream::addRow(double t, const Eigen::VectorXd& state,
                                 const Eigen::VectorXd& action) {
    appendDemonstrationCsvRow(pending_, t, state, action);
    rowStates_.push_back(state);
    rowActions_.push_back(action);
}

bool DemonstrationStream::append(double time, const Eigen::VectorXd& state,
                                 const Eigen::VectorXd& action, QString* error) {
    if (!file_.isOpen() || !std::isfinite(time) || state.size() != header_.stateDimension() ||
        action.size() != header_.actionDimension() || !state.allFinite() || !action.allFinite() ||
        (started_ && !(time > lastTime_))) {
        return true;
    }
    const double dt = header_.dt;
    if (!started_) {
        started_ = true;
        firstTime_ = time;
        addRow(0.0, state, action);
    } else {
        // Every row time t_k in (lastTime_, time], from the two samples around it.
        for (;;) {
            const int k = rows();
            const double tk = k * dt;
            const double since = time - firstTime_;
            if (tk > since + 1e-9 * dt) {
                break;
            }
            const double span = time - lastTime_;
            const double w = std::clamp((tk - (lastTime_ - firstTime_)) / span, 0.0, 1.0);
            Eigen::VectorXd s = lastState_ + w * (state - lastState_);
            for (int a : angles_) {
                s[a] = wrapAngle(lastState_[a] + w * wrapAngle(state[a] - lastState_[a]));
            }
            addRow(tk, s, w >= 1.0 - 1e-9 ? action : lastAction_);
        }
    }
    lastTime_ = time;
    lastState_ = state;
    lastAction_ = action;
    // The first row at once, so the file is a demonstration from the first sample on; then
    // every interval of wall time, and every interval of the take's own time: a burst of
    // samples (a backlog of camera frames handled at once) leaves no more of the take unwritten.
    const double takeTime = time - firstTime_;
    if (rows() > 1 && sinceFlush_.isValid() && sinceFlush_.elapsed() < flushIntervalMs_ &&
        takeTime - flushedTime_ < flushIntervalMs_ * 1e-3) {
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
    flushedTime_ = started_ ? lastTime_ - firstTime_ : 0.0;
    return true;
}

Demonstration DemonstrationStream::demonstration() const {
    Demonstration demo = header_;
    const int T = rows();
    demo.time.resize(T);
    demo.states.resize(T, header_.stateDimension());
    demo.actions.resize(T, header_.actionDimension());
    for (int k = 0; k < T; ++k) {
        demo.time[k] = k * header_.dt;
        demo.states.row(k) = rowStates_[size_t(k)].transpose();
        demo.actions.row(k) = rowActions_[size_t(k)].transpose();
    }
    return demo;
}

bool DemonstrationStream::finish(QString* error) {
    if (!file_.isOpen()) {
        *error = QStringLiteral("%1: the recording is not open").arg(path_);
        return false;
    }
    if (!flush(error)) {
        return false;
    }
    // On disk before it takes the final name, so a power cut cannot leave an empty file there.
    if (::fdatasync(file_.handle()) != 0) {
        *error = QStringLiteral("%1: cannot sync to disk").arg(file_.fileName());
        return false;
    }
    file_.close();
    const QString part = partPath(path_);
    // rename(2) replaces the target in one step; QFile::rename refuses an existing target.
    if (std::rename(QFile::encodeName(part).constData(), QFile::encodeName(path_).constData()) !=
        0) {
        *error = QStringLiteral("%1: cannot rename to %2").arg(part, path_);
        return false;
    }
    return true;
}

void DemonstrationStream::abandon() {
    if (file_.isOpen()) {
        file_.close();
        QFile::remove(file_.fileName());
    }
    pending_.clear();
}

}  // namespace prisca::core
