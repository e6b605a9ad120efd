#pragma once

// A method's declaration: what the catalog holds of each method (sim/methods/ declares them,
// MethodCatalog lists them and answers by id).

#include "core/Controller.h"
#include "sim/tuning/MethodParameter.h"
#include "sim/tuning/MethodTuning.h"

#include <QString>

#include <functional>
#include <memory>
#include <vector>

namespace prisca::sim {

/// What a method's controller is made from: the plant's profile (features, limits, matching,
/// gains), the demonstration, the fitted B = B_v (.) B~ (m x n) and, for a method trained
/// offline into a policy, that policy's theta (p x m; null for none).
struct MethodInput {
    const MethodTuning& profile;
    std::shared_ptr<const core::Demonstration> demonstration;
    const Eigen::MatrixXd& fittedB;
    const Eigen::MatrixXd* theta = nullptr;
    /// Asked now and then by a method that takes long to make (mpc identifies its model): true
    /// stops it (the run was stopped or E-STOP pressed); the controller made is then not used.
    std::function<bool()> cancelled = {};
};

/// One method: everything the window, the CLI, Table I and the learning curves need to know of
/// it. Adding a method is one entry in MethodCatalog.cpp plus the method's own files.
struct MethodSpec {
    using Create = std::unique_ptr<core::Controller> (*)(const MethodSpec&, const MethodInput&);
    /// How a method is trained before it is evaluated (MethodTraining).
    enum class Training {
        None,           ///< evaluated as it is (online learners learn trial after trial)
        SelectPdGains,  ///< grid-searches the PD gains on the training trials
        Pegasus         ///< searches a linear policy on fixed scenarios
    };
    QString id;                 ///< as the command line and session files spell it, e.g. "pd-h-lsd"
    QString label;              ///< in tables, lists and figures, e.g. "PD+H+LSD"
    const char* summary = "";   ///< one line for --help
    bool learnsOnline = false;  ///< learns trial after trial (warm-started in training)
    Training training = Training::None;
    bool inTable1 = true;  ///< has a row in Table I
    /// Runs in a Table I no one chose the methods of (false: only when named, as mpc, whose
    /// identification takes seconds per cell and which runs on the slide-car alone).
    bool inDefaultTable1 = true;
    bool inCurves = true;         ///< can be drawn as a learning curve
    bool ownFeatures = false;     ///< theta over the profile's PRISCA features (priscaFeatures)
    bool usesFeatures = false;    ///< a policy theta^T phi over features (the panel shows phi)
    bool limit = false;           ///< the ruler every accuracy figure is read against
    bool simulationOnly = false;  ///< needs the simulated plant itself (not on the rig)
    /// Plans through the car's identified model (MethodTuning::mpcModel); without one it
    /// identifies the car itself when it is built, which takes seconds: the rig wants it first.
    bool plansThroughModel = false;
    /// The plants it runs on (empty: every plant).
    QStringList plants;
    bool runsOn(const QString& plant) const { return plants.isEmpty() || plants.contains(plant); }
    /// What the method is tuned by, in the order the Controller panel shows them; a parameter
    /// several methods share (the PD gains, the matching window) is the same declaration in
    /// each of their lists.
    std::vector<MethodParameter> parameters;
    Create create = nullptr;  ///< builds the controller

    bool trainsOffline() const { return training != Training::None; }
};

}  // namespace prisca::sim
