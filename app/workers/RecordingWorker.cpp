#include "app/workers/RecordingWorker.h"

#include "core/DemonstrationCsv.h"
#include "sim/PlantCatalog.h"
#include "sim/demonstrations/DemonstrationRecorder.h"

#include <QDir>
#include <QFileInfo>
#include <QTimer>

namespace prisca::app {

namespace {
constexpr int kRecordingTickMs = 5;
constexpr int kSampleFlushMs = 40;
}  // namespace

RecordingWorker::RecordingWorker(QObject* parent) : QObject(parent), timer_(new QTimer(this)) {
    timer_->setTimerType(Qt::PreciseTimer);
    timer_->setInterval(kRecordingTickMs);
    connect(timer_, &QTimer::timeout, this, &RecordingWorker::tick);
}

RecordingWorker::~RecordingWorker() = default;  // the stream flushes and closes itself

void RecordingWorker::start(const QString& plant, const QString& streamPath,
                            std::shared_ptr<const sim::PlantParameters> parameters) {
    if (active_) {
        stop();
    }
    try {
        plant_ =
            parameters ? sim::PlantCatalog::create(*parameters) : sim::PlantCatalog::create(plant);
    } catch (const std::exception& e) {
        emit failed(QString::fromStdString(e.what()));
        return;
    }
    // The demonstration format's own header, on disk at once; rows follow as they are driven.
    core::Demonstration header =
        sim::DemonstrationRecorder(plant_->info(), plant_->timing().controlPeriod).demonstration();
    header.metadata.insert(QStringLiteral("source"), QStringLiteral("recorded by driving"));
    QString error;
    if (!stream_.open(streamPath, header, plant_->info().angleIndices, &error)) {
        emit failed(tr("Cannot record to %1").arg(error));
        return;
    }
    state_ = plant_->reset(1, sim::Perturbation::none());
    input_ = Eigen::VectorXd::Zero(plant_->info().actionDimension());
    steps_ = 0;
    samples_.clear();
    stopRequested_.store(false);
    active_ = true;
    clock_.start();
    flushClock_.start();
    timer_->start();
}

void RecordingWorker::setInput(const Eigen::VectorXd& input) {
    if (!plant_ || input.size() != input_.size() || !input.allFinite()) {
        return;  // a malformed input never reaches the plant
    }
    const sim::PlantInfo& info = plant_->info();
    input_ = input.cwiseMax(info.actionLower).cwiseMin(info.actionUpper);
}

void RecordingWorker::tick() {
    if (!active_) {
        return;
    }
    if (stopRequested_.load()) {
        stop();
        return;
    }
    const double dt = plant_->timing().controlPeriod;
    const int due = static_cast<int>(clock_.nsecsElapsed() * 1e-9 / dt) + 1 - steps_;
    for (int i = 0; i < due && i < 40; ++i) {
        const int k = steps_++;
        const double t = k * dt;
        QString error;
        if (!stream_.append(t, state_, input_, &error)) {
            // A full disk: end the take (stop() tries once more to save it, and says where
            // what was written is if that fails too).
            stopRequested_.store(true);
        }
        LiveSample sample;
        sample.step = k;
        sample.time = t;
        sample.runTime = t;
        sample.state = state_;
        sample.action = input_;
        sample.referenceAction = input_;
        sample.wind = plant_->windVelocity();
        samples_.push_back(std::move(sample));
        state_ = plant_->step(input_);
    }
    if (flushClock_.elapsed() >= kSampleFlushMs && !samples_.isEmpty()) {
        emit samplesReady(samples_);
        samples_.clear();
        flushClock_.restart();
    }
}

void RecordingWorker::stop() {
    if (!active_) {
        return;
    }
    timer_->stop();
    active_ = false;
    if (!samples_.isEmpty()) {
        emit samplesReady(samples_);
        samples_.clear();
    }
    const QString streamPath = stream_.fileName();
    core::Demonstration demo = stream_.demonstration();  // "source" is in the header already
    QString error;
    if (!stream_.finish(&error)) {
        emit failed(tr("Writing the recording failed: %1 (the take so far is in %2)")
                        .arg(error, core::DemonstrationStream::partPath(streamPath)));
        return;
    }
    emit finished(demo, streamPath);
}

}  // namespace prisca::app
