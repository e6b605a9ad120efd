#pragma once

#include "core/Demonstration.h"
#include "devices/FloorCalibration.h"
#include "devices/Geofence.h"
#include "devices/TransmitterLink.h"
#include "sim/plants/Plant.h"

#include <QCoreApplication>
#include <QString>

#include <opencv2/core.hpp>

#include <optional>
#include <vector>

namespace prisca::rig {

/// Where the loop latency the trials compensate comes from.
enum class LoopLatencySource {
    Assumed,   ///< the profile's assumption for the camera (known only for the virtual camera)
    Measured,  ///< RigSession::measureLatency
    Declared,  ///< given by the operator (a value measured elsewhere)
};

/// What the pre-trial check looks at: the rig's state at one moment, plain data.
struct PreTrialInputs {
    bool cameraRunning = false;
    bool virtualCamera = true;  ///< the virtual rig's synthetic camera (else a device or a video)
    bool carSeen = false;       ///< the newest frame has the car in it (the virtual car: it exists)
    cv::Size frameSize;         ///< the newest frame's [px]; empty before the first
    devices::FloorCalibration calibration;
    bool calibrationIsVirtualRigs = true;  ///< still the synthetic camera's calibration
    devices::LinkStatus link;
    std::optional<double> loopLatency;  ///< [s]
    LoopLatencySource loopLatencySource = LoopLatencySource::Assumed;
    double injectedCameraDelay = 0.0;  ///< the virtual camera's added delay [s]
    bool emergencyLatched = false;     ///< E-STOP (the window's, through the link's latch)
    /// Of the latch: the process was stopped and continued, and holds failsafe until E-STOP is
    /// reset (devices::processfailsafe::held()).
    bool failsafeHeld = false;
    devices::Geofence fence;
    /// The run: its demonstration (the path and the lot) and its target; null: none.
    std::shared_ptr<const core::Demonstration> demonstration;
    std::optional<sim::PlantInfo> plant;
    QString methodLabel;
    bool methodSimulationOnly = false;  ///< plans on a simulated plant (the oracle)
    bool methodTrainsOffline = false;
    bool methodPlansThroughModel = false;  ///< mpc: it needs the car's model
    bool modelIdentified = false;          ///< the session has the car's model (mpcModel)
};

/// One line of the check.
struct PreTrialItem {
    QString key;    ///< "camera", "car", "calibration", "lens", "link", "latency", "estop",
                    ///< "task", "fence", "view": for tests and the CLI's JSON
    QString label;  ///< what it is, in a word or two ("Camera")
    bool ok = false;
    bool blocking = true;  ///< a failed blocking item keeps a trial from starting
    QString detail;        ///< when ok: what was found; else what is missing and what to do
};

/// The rig's readiness for a trial: every item, and whether a trial may start.
struct PreTrialCheck {
    std::vector<PreTrialItem> items;
    /// Every blocking item holds.
    bool ready() const;
    /// The failed blocking items' labels ("Camera, Link"); empty when ready.
    QString missingLabels() const;
    /// The failed blocking items' details, one sentence each; empty when ready.
    QString missingDetails() const;
    const PreTrialItem* find(const QString& key) const;
};

/// Evaluates the check (a pure function of its inputs; RigSession::preTrialCheck gathers them).
/// The demonstration's path and its lot must lie inside the fence and inside the camera's view
/// (mapped through the calibration, with `kViewMarginPx` to spare); a real camera needs its own
/// calibration and a lens; the latency must be measured or declared unless the virtual camera's
/// is known by construction (no injected delay). With no fence the trial may start, but the
/// line says the car is stopped only by E-STOP and the lost-track guard then.
PreTrialCheck evaluatePreTrialCheck(const PreTrialInputs& inputs);

/// Whether a method may drive a real car, and why not (empty: it may): the rig's one rule, for
/// the pre-trial check and for `prisca-cli rig`'s refusal before any device is opened. The
/// oracle plans on the simulator itself; a method that trains offline runs in simulation.
QString methodRigProblem(bool simulationOnly, bool trainsOffline, const QString& label);

/// Why no trial may start while the link's E-STOP latch is on, naming its cause: the
/// operator's E-STOP, or failsafe held after the process was stopped and continued.
QString emergencyProblem(bool failsafeHeld);

/// The demonstration's points (and lot) kept this far inside the image edges [px]: the car's
/// LEDs must stay in view around its centre.
inline constexpr double kViewMarginPx = 20.0;

}  // namespace prisca::rig
