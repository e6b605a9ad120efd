#pragma once

#include "Demonstration.h"

#include <Eigen/Core>

#include <QByteArray>
#include <QElapsedTimer>
#include <QFile>
#include <QString>

#include <vector>

namespace prisca::core {

/// A demonstration streamed to disk as it is recorded, the one recorder of the window's driving
/// and the rig's camera. Samples come with their own times (a simulation's steps, a camera's
/// frame timestamps with jitter, dropped frames and pose-less gaps); the stream writes the
/// demonstration format's evenly spaced rows t_k = k dt from them as they pass: states
/// interpolated between the samples around t_k (angles the short way round), the action the
/// one applied at t_k (the last sample at or before it). So a gap keeps its length in time.
///
/// Crash safety: the rows go to partPath(path), whose header is written and flushed when it
/// opens, the first row with its sample; rows are flushed at least every `flushIntervalMs` of
/// wall time and of the take's own time (a burst of samples handed over at once included), so a
/// crash or a kill loses at most that much of the take and never the header, and what is left is a
/// readable demonstration. finish() renames the partial file onto `path` in one step, so an older
/// file there is either kept whole or replaced whole. Not thread-safe; one thread at a time.
class DemonstrationStream {
  public:
    explicit DemonstrationStream(int flushIntervalMs = 250) : flushIntervalMs_(flushIntervalMs) {}
    /// Flushes and closes, leaving the partial file as a crash would (finish() was not called).
    ~DemonstrationStream();
    DemonstrationStream(const DemonstrationStream&) = delete;
    DemonstrationStream& operator=(const DemonstrationStream&) = delete;

    /// Where the take lives until finish(): `path` + ".part".
    static QString partPath(const QString& path) { return path + QStringLiteral(".part"); }

    /// Creates (truncates) partPath(path), making its folder, and writes the header of `header`
    /// (names, units, dt, plant, metadata; its rows are ignored). `angleIndices` are the state
    /// columns that are angles in rad. False with *error (the file and the reason) on failure.
    bool open(const QString& path, const Demonstration& header,
              const std::vector<int>& angleIndices, QString* error);
    bool isOpen() const { return file_.isOpen(); }
    /// The final path given to open().
    const QString& fileName() const { return path_; }

    /// Adds the sample observed at `time` [s, any origin; the first sample's time is t = 0]:
    /// writes every row t_k up to it. A sample not after the previous one, or with a
    /// non-finite time, state or action, or of the wrong size, is ignored (true). Flushes when
    /// the interval has passed. False with *error once writing failed (the rows stay pending
    /// for the next attempt, and in memory).
    bool append(double time, const Eigen::VectorXd& state, const Eigen::VectorXd& action,
                QString* error);
    /// Rows written so far (to the file or pending).
    int rows() const { return static_cast<int>(rowStates_.size()); }
    /// Writes what is pending now. False with *error on failure.
    bool flush(QString* error);
    /// The take so far as a demonstration (the header's fields and every row).
    Demonstration demonstration() const;

    /// Ends the take: flushes, closes and renames the partial file onto the final path. False
    /// with *error on failure (the partial file is then kept).
    bool finish(QString* error);
    /// Ends the take without keeping it: closes and removes the partial file.
    void abandon();

  private:
    void addRow(double t, const Eigen::VectorXd& state, const Eigen::VectorXd& action);

    int flushIntervalMs_;
    QString path_;
    QFile file_;
    QByteArray pending_;
    QElapsedTimer sinceFlush_;
    Demonstration header_;
    std::vector<int> angles_;
    // The previous sample, for interpolating onto the rows' times.
    bool started_ = false;
    double firstTime_ = 0.0;
    double lastTime_ = 0.0;
    double flushedTime_ = 0.0;  ///< the take's time [s] of the last sample flushed
    Eigen::VectorXd lastState_, lastAction_;
    std::vector<Eigen::VectorXd> rowStates_, rowActions_;
};

}  // namespace prisca::core
