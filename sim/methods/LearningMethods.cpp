// The learners the paper compares with: policy search by the signed derivative (PGSD), offline
// policy search on fixed scenarios (PEGASUS), iterative learning control (ILC).
#include "sim/methods/Declarations.h"

#include <QCoreApplication>
#include "core/IlcController.h"
#include "core/PgsdController.h"
#include "core/PriscaController.h"
#include "sim/tuning/MethodTuning.h"

namespace prisca::sim::methods {

namespace {

const MethodParameter& pgsdHorizon() {
    static const MethodParameter p = [] {
        MethodParameter p = integer(
            "pgsd.H", QT_TRANSLATE_NOOP("MethodParameter", "PGSD horizon H"), "steps", 1, 1000,
            QT_TRANSLATE_NOOP("MethodParameter", "PGSD's smoothing horizon H (eq. 9)."));
        p.get = [](const MethodTuning& f) { return one(f.pgsd.horizon); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.pgsd.horizon = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& pgsdStep() {
    static const MethodParameter p = [] {
        MethodParameter p =
            real("pgsd.alpha", QT_TRANSLATE_NOOP("MethodParameter", "PGSD step α"), "", 0, 1e6, 5,
                 QT_TRANSLATE_NOOP("MethodParameter", "The fixed step size of PGSD (no decay)."));
        p.get = [](const MethodTuning& f) { return one(f.pgsd.stepSize); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.pgsd.stepSize = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& pgsdThetaBound() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "pgsd.theta-bound", QT_TRANSLATE_NOOP("MethodParameter", "PGSD θ bound"), "", 0, 1e4, 2,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "If above 0, PGSD's θ is kept in |θ_i| ≤ bound after each update."));
        p.zeroMeans = QT_TRANSLATE_NOOP("MethodParameter", "none");
        p.get = [](const MethodTuning& f) { return one(f.pgsd.thetaBound); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.pgsd.thetaBound = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& pegasusIterations() {
    static const MethodParameter p = [] {
        MethodParameter p = integer(
            "pegasus.iterations", QT_TRANSLATE_NOOP("MethodParameter", "PEGASUS iterations"), "", 0,
            100000,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Gradient steps PEGASUS takes on its fixed scenarios before a run."));
        p.get = [](const MethodTuning& f) { return one(f.pegasusIterations); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.pegasusIterations = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& pegasusScenarios() {
    static const MethodParameter p = [] {
        MethodParameter p =
            integer("pegasus.scenarios", QT_TRANSLATE_NOOP("MethodParameter", "PEGASUS scenarios"),
                    "", 1, 1000,
                    QT_TRANSLATE_NOOP("MethodParameter",
                                      "Fixed scenarios (start, perturbation, noise) "
                                      "each evaluation averages."));
        p.get = [](const MethodTuning& f) { return one(f.pegasus.scenarios); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.pegasus.scenarios = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& pegasusStep() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "pegasus.alpha", QT_TRANSLATE_NOOP("MethodParameter", "PEGASUS step α"), "", 0, 1e9, 4,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Gradient-descent step on the mean episode cost."));
        p.get = [](const MethodTuning& f) { return one(f.pegasus.stepSize); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.pegasus.stepSize = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& ilcLearning() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "ilc.learning", QT_TRANSLATE_NOOP("MethodParameter", "ILC learning Γ/Kp"), "", 0, 100,
            3,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "ILC's learning gain per control, as a share of the PD's Kp: how "
                              "much of a trial's error goes into the next trial's feedforward."));
        p.get = [](const MethodTuning& f) { return one(f.ilcLearningScale); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.ilcLearningScale = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& ilcLead() {
    static const MethodParameter p = [] {
        MethodParameter p =
            integer("ilc.lead", QT_TRANSLATE_NOOP("MethodParameter", "ILC lead"), "steps", 0, 200,
                    QT_TRANSLATE_NOOP("MethodParameter",
                                      "The error this many steps later corrects the "
                                      "action now (covers the plant's delay)."));
        p.get = [](const MethodTuning& f) { return one(f.ilcLead); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.ilcLead = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& ilcCutoff() {
    static const MethodParameter p = [] {
        MethodParameter p =
            real("ilc.cutoff", QT_TRANSLATE_NOOP("MethodParameter", "ILC Q cutoff"), "Hz", 0, 20, 2,
                 QT_TRANSLATE_NOOP("MethodParameter",
                                   "Zero-phase low-pass on the learned feedforward "
                                   "after each trial; 0 leaves it unfiltered."));
        p.get = [](const MethodTuning& f) { return one(f.ilcCutoff); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.ilcCutoff = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& ilcFeedback() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "ilc.feedback", QT_TRANSLATE_NOOP("MethodParameter", "ILC feedback scale"), "", 0, 100,
            3, QT_TRANSLATE_NOOP("MethodParameter", "The PD gains in ILC's loop, scaled by this."));
        p.get = [](const MethodTuning& f) { return one(f.ilcFeedbackScale); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.ilcFeedbackScale = v[0]; };
        return p;
    }();
    return p;
}

Made makePgsd(const MethodSpec&, const MethodInput& in) {
    const MethodTuning& profile = in.profile;
    const auto& demonstration = in.demonstration;
    return std::make_unique<core::PgsdController>(
        profile.trackingProblem(demonstration, Mode::TimeDriven), profile.features, profile.mapping,
        profile.pgsd);
}

Made makePegasus(const MethodSpec&, const MethodInput& in) {
    const MethodTuning& profile = in.profile;
    const auto& demonstration = in.demonstration;
    const Eigen::MatrixXd* theta = in.theta;
    // PEGASUS learns offline, episode by episode; online it is the same linear policy
    // around the demonstration, with theta frozen.
    core::PriscaParameters frozen = profile.prisca;
    frozen.learning = false;
    auto policy = std::make_unique<core::PriscaController>(
        profile.trackingProblem(demonstration, Mode::TimeDriven), profile.features,
        profile.mapping.asDouble(), frozen, QStringLiteral("pegasus"));
    if (theta) {
        policy->setInitialTheta(*theta);
    }
    return policy;
}

Made makeIlc(const MethodSpec&, const MethodInput& in) {
    const MethodTuning& profile = in.profile;
    const auto& demonstration = in.demonstration;
    return std::make_unique<core::IlcController>(
        profile.trackingProblem(demonstration, Mode::TimeDriven), profile.ilcParameters());
}

}  // namespace

/// PGSD.
MethodSpec pgsdMethod() {
    MethodSpec s = entry("pgsd", "PGSD", &makePgsd);
    s.learnsOnline = true;
    s.usesFeatures = true;
    s.summary = "policy search by the signed derivative";
    s.parameters = {pgsdHorizon(), pgsdStep(), pgsdThetaBound()};
    return s;
}

/// PEGASUS.
MethodSpec pegasusMethod() {
    MethodSpec s = entry("pegasus", "PEGASUS", &makePegasus);
    s.training = MethodSpec::Training::Pegasus;
    s.inTable1 = false;  // its offline search is the learning curves' subject
    s.usesFeatures = true;
    s.summary = "offline policy search on fixed scenarios";
    s.parameters = {pegasusIterations(), pegasusScenarios(), pegasusStep()};
    return s;
}

/// ILC around the PD.
MethodSpec ilcMethod() {
    MethodSpec s = entry("ilc", "ILC", &makeIlc);
    s.learnsOnline = true;
    s.summary = "iterative learning control around the PD";
    s.parameters = {ilcLearning(), ilcLead(), ilcCutoff(), ilcFeedback(), pdKp(), pdKd()};
    return s;
}

}  // namespace prisca::sim::methods
