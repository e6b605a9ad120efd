#pragma once

#include "core/Demonstration.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/episodes/TrialMetrics.h"
#include "sim/plants/Plant.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <opencv2/core.hpp>

#include <cstdio>
#include <memory>
#include <optional>
#include <vector>

namespace prisca::rig {

/// One sample of a trial: what was seen and what was commanded, at time t [s from the trial's
/// first frame or step].
struct BundleSample {
    double t = 0.0;
    long long frame = -1;  ///< camera frame (rig trials), -1 in simulation
    bool found = false;    ///< a pose was tracked (always in simulation: the true state)
    double x = 0.0, y = 0.0, psi = 0.0;  ///< tracked (rig) or true (simulation) pose
    std::vector<double> state;           ///< the observation the controller got
    std::vector<double> action;          ///< its command (empty: none, failsafe)
    bool failsafe = false;               ///< the link (or the loop) was in failsafe
};

/// A trial bundle: one folder with everything needed to look at a trial again.
///   bundle.json         what ran (kind, method, plant, seed, the calibration and fence on the
///                       rig, the loop latency) and, once the trial ended, its result
///   demonstration.csv   the demonstration it followed
///   samples.csv         one line per frame or step, appended and flushed every second, so a
///                       bundle whose writer was killed reads up to its last second
///   frames/NNNNNN.jpg   the camera's frames at the chosen rate (rig trials), each a whole file
class TrialBundleWriter {
  public:
    /// Creates the folder (it must not exist yet, or be empty) and writes bundle.json and the
    /// demonstration. False and *error on failure.
    bool open(const QString& folder, const QJsonObject& header,
              const core::Demonstration& demonstration, QString* error);
    void append(const BundleSample& sample);
    /// A camera frame (8-bit grey or BGR), stored as JPEG under its frame index.
    bool addFrame(long long frame, const cv::Mat& image);
    /// Appends what is buffered to samples.csv and flushes it to the disk.
    bool flush();
    /// Flushes, then rewrites bundle.json with `result` added (atomically).
    bool finish(const QJsonObject& result, QString* error);
    const QString& folder() const { return folder_; }
    ~TrialBundleWriter();

  private:
    QString folder_;
    QJsonObject header_;
    std::FILE* samples_ = nullptr;
    QByteArray pending_;
    double lastFlushT_ = 0.0;
};

/// A bundle read back (replay). Rows end at the last complete line.
struct TrialBundle {
    QString folder;
    QJsonObject header;  ///< bundle.json (with "result" once the trial ended)
    std::shared_ptr<const core::Demonstration> demonstration;
    std::vector<BundleSample> samples;
    std::vector<std::pair<long long, QString>> frames;  ///< frame index, JPEG path, in order
    bool complete() const { return header.contains("result"); }
    /// The frame shown at sample i: the stored frame nearest its frame index, before or after
    /// (frames are kept at a fraction of the camera's rate; the nearest is the nearest in time)
    /// (empty: none).
    QString frameAt(size_t sample) const;

    static std::optional<TrialBundle> load(const QString& folder, QString* error);
};

/// A simulated trial as a bundle in `folder` (new): one sample per control step (the true pose,
/// the observation, the command) and the final state; `header` gains kind "simulation" and the
/// result (the trial's own parking error). False and *error on failure.
bool writeSimulationBundle(const QString& folder, QJsonObject header, const sim::PlantInfo& info,
                           const core::Demonstration& demonstration,
                           const sim::EpisodeResult& result, const sim::TrialSummary& summary,
                           QString* error);

/// The bundle's samples as recorded runs for identification: the observation each sample
/// carried and its command, at the samples' own period (their median spacing), split where a
/// pose or a command is missing (a lost track, a failsafe) or the samples skip a period. Runs
/// shorter than 10 samples are dropped. Each run's metadata "source" names the bundle and the
/// part.
std::vector<core::Demonstration> recordedRuns(const TrialBundle& bundle);

/// The bundle's scores from its samples: duration, frames, frames with a pose, commands in
/// failsafe, and where the last pose stopped relative to the demonstration's end (position
/// [m], heading [rad]); what `prisca-cli replay` prints.
QJsonObject summarizeBundle(const TrialBundle& bundle);

}  // namespace prisca::rig
