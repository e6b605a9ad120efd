#pragma once

#include "Demonstration.h"

#include <Eigen/Core>

#include <QByteArray>
#include <QElapsedTimer>
#include <QFile>
#include <QString>

namespace prisca::core {

/// A demonstration streamed to disk as it is recorded (the window's driving, the rig's camera):
/// the header is written and flushed when it opens, rows are flushed at least every
/// `flushIntervalMs` of wall time, so a crash or a kill loses at most that much of the take and
/// never the header. The file is the demonstration CSV format; rows carry the times given.
class DemonstrationStream {
  public:
    explicit DemonstrationStream(int flushIntervalMs = 250) : flushIntervalMs_(flushIntervalMs) {}
    ~DemonstrationStream();
    DemonstrationStream(const DemonstrationStream&) = delete;
    DemonstrationStream& operator=(const DemonstrationStream&) = delete;

    /// Creates (truncates) `path` and writes the header of `header` (names, units, dt, plant,
    /// metadata; its rows are ignored). False with *error (the file and the reason) on failure.
    bool open(const QString& path, const Demonstration& header, QString* error);
    bool isOpen() const { return file_.isOpen(); }
    QString fileName() const { return file_.fileName(); }
    /// Appends one row; flushes when the interval has passed. False with *error once writing
    /// failed (the rows stay pending for the next attempt).
    bool append(double t, const Eigen::VectorXd& state, const Eigen::VectorXd& action,
                QString* error);
    /// Writes what is pending now. False with *error on failure.
    bool flush(QString* error);
    /// Flushes and closes. False with *error if the last write failed.
    bool close(QString* error);

  private:
    int flushIntervalMs_;
    QFile file_;
    QByteArray pending_;
    QElapsedTimer sinceFlush_;
};

}  // namespace prisca::core
