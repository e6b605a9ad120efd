#pragma once

#include "core/Demonstration.h"
#include "sim/planning/Identification.h"
#include "sim/plants/PlantParameters.h"

#include <QMetaType>
#include <QObject>

#include <atomic>
#include <memory>

namespace prisca::app {

/// What an identification runs on, copied into the worker's thread. Plain data.
struct IdentificationRequest {
    int id = 0;  ///< the caller's number for it; finished() and progress() carry it back
    /// The run to fit (the session's demonstration; the session keeps a model only when it
    /// still holds this very one).
    std::shared_ptr<const core::Demonstration> demonstration;
    sim::PlantParameters prior;  ///< where the search starts (LabSession::identificationPrior)
    sim::IdentificationSettings settings;  ///< the budget: `prisca-cli identify`'s defaults
};

/// Fits a plant's parameters to a demonstration (sim::identifyPlant) in the background: tens of
/// seconds to minutes of model runs, which the GUI thread must never wait for. Lives on its own
/// thread; run() is posted to it, cancel() may be called from any thread and stops the search
/// within a few model runs.
class IdentificationWorker : public QObject {
    Q_OBJECT
  public:
    explicit IdentificationWorker(QObject* parent = nullptr) : QObject(parent) {}
    /// Any thread, before run() is posted: a cancel() from then on stops that run, even one
    /// that comes before the run has begun on the worker's thread.
    void prepare() { cancelled_.store(false); }
    /// Any thread.
    void cancel() { cancelled_.store(true); }
    bool isCancelled() const { return cancelled_.load(); }

  public slots:
    void run(const prisca::app::IdentificationRequest& request);

  signals:
    /// Model runs done of about `total` (the search's budget), a few times a second at most.
    void progress(int id, long long done, long long total);
    /// The identification ended: a model (result->ok()), a refusal with its reason, or
    /// cancelled.
    void finished(int id, std::shared_ptr<const prisca::sim::IdentificationResult> result);
    /// It failed outright (an exception from below): what went wrong.
    void failed(int id, const QString& message);

  private:
    std::atomic<bool> cancelled_{false};
};

}  // namespace prisca::app

Q_DECLARE_METATYPE(prisca::app::IdentificationRequest)
Q_DECLARE_METATYPE(std::shared_ptr<const prisca::sim::IdentificationResult>)
