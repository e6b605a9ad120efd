// A time-varying LQR on the model fitted from the demonstration (eq. 5), with its per-plant
// defaults.
#include "sim/methods/Declarations.h"

#include <QCoreApplication>
#include <cmath>
#include "core/ActionMapping.h"
#include "core/LqrController.h"
#include "sim/tuning/MethodTuning.h"

namespace prisca::sim::methods {

namespace {

// ---- lqr: a time-varying LQR on the model fitted from the demonstration ----------------------
// Its per-plant defaults, from grids on each plant's tuning cells only (docs/results.md, "LQR").
struct LqrDefaults {
    const char* plant;
    double throttleEffort, otherEffort;  // R of the first control, and of the others
    double terminal;
    bool drift;
};

constexpr LqrDefaults kLqrDefaults[] = {
    {"slidecar", 30.0, 100.0, 100.0, false},
    {"acrobot", 1e-6, 1e-6, 100.0, true},
    {"aircraft", 3.0, 3.0, 100.0, false},
    {"diffdrive", 1e-3, 1e-3, 100.0, false},
};

// Null for a plant with no entry: its parameters then have no value, which the catalog's tests
// catch for every catalog plant.
const LqrDefaults* lqrDefaults(const MethodTuning& f) {
    for (const LqrDefaults& d : kLqrDefaults) {
        if (f.info.name == QLatin1String(d.plant)) {
            return &d;
        }
    }
    return nullptr;
}

const MethodParameter& lqrEffort() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "lqr.effort", QT_TRANSLATE_NOOP("MethodParameter", "LQR effort weight R"), "1/action²",
            1e-6, 1e6, 6,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "R per control in the LQR's cost e^T W e + (u − u*)^T R (u − u*): "
                              "larger is gentler."));
        p.perChannel = true;
        p.defaultFor = [](const MethodTuning& f) -> Eigen::VectorXd {
            const LqrDefaults* d = lqrDefaults(f);
            if (!d) {
                return Eigen::VectorXd();
            }
            Eigen::VectorXd r = Eigen::VectorXd::Constant(f.info.actionDimension(), d->otherEffort);
            r[0] = d->throttleEffort;
            return r;
        };
        return p;
    }();
    return p;
}

const MethodParameter& lqrTerminal() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "lqr.terminal", QT_TRANSLATE_NOOP("MethodParameter", "LQR terminal weight"), "", 0.01,
            1e6, 2,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "The deviation at the demonstration's end costs this many times a "
                              "step's (where a parking manoeuvre is judged)."));
        p.defaultFor = [](const MethodTuning& f) {
            const LqrDefaults* d = lqrDefaults(f);
            return d ? one(d->terminal) : Eigen::VectorXd();
        };
        return p;
    }();
    return p;
}

const MethodParameter& lqrDrift() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "lqr.drift", QT_TRANSLATE_NOOP("MethodParameter", "LQR models the drift"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Fit eq. 5 in full (the state's own drift A with B); off: B alone, "
                              "each state driven only by the controls."));
        p.defaultFor = [](const MethodTuning& f) {
            const LqrDefaults* d = lqrDefaults(f);
            return d ? one(d->drift ? 1 : 0) : Eigen::VectorXd();
        };
        return p;
    }();
    return p;
}

Made makeLqr(const MethodSpec&, const MethodInput& in) {
    const MethodTuning& profile = in.profile;
    // eq. 5 (A with B, or B alone) fitted on the demonstration: the model a control engineer
    // would identify from the one recording there is.
    const core::Demonstration& demonstration = *in.demonstration;
    const int n = demonstration.stateDimension();
    core::LqrParameters parameters;
    if (lqrDrift().value(profile)[0] != 0.0) {
        core::ActionMappingFitOptions options;
        options.drift = true;
        const core::ActionMappingFit fit = core::fitActionMapping(
            demonstration, profile.mapping, profile.info.deviationModel(), options);
        parameters.a = fit.a;
        parameters.b = fit.b;
    } else {
        parameters.a = Eigen::MatrixXd::Zero(n, n);
        parameters.b = in.fittedB;  // the task's own fit, as the Mapping panel shows it
    }
    parameters.effort = lqrEffort().value(profile);
    parameters.terminalWeight = lqrTerminal().value(profile)[0];
    // The trial goes on for the settle time past the demonstration: plan over it too.
    parameters.holdSteps = static_cast<int>(std::lround(profile.settleTime / demonstration.dt));
    return std::make_unique<core::LqrController>(
        profile.trackingProblem(in.demonstration, Mode::TimeDriven), parameters);
}

}  // namespace

/// LQR.
MethodSpec lqrMethod() {
    MethodSpec s = entry("lqr", "LQR", &makeLqr);
    s.summary = "time-varying LQR on the model fitted from the demonstration (eq. 5)";
    s.parameters = {lqrEffort(), lqrTerminal(), lqrDrift()};
    return s;
}

}  // namespace prisca::sim::methods
