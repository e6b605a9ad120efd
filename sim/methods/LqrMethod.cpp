// A time-varying LQR on the model fitted from the demonstration (eq. 5).
#include "sim/methods/Declarations.h"

#include <QCoreApplication>
#include <cmath>
#include "core/ActionMapping.h"
#include "core/LqrController.h"
#include "sim/tuning/MethodTuning.h"

namespace prisca::sim::methods {

namespace {

// ---- lqr: a time-varying LQR on the model fitted from the demonstration ----------------------
// Its values per plant are the plant's tuning's (MethodTuning::lqrEffort, lqrTerminal, lqrDrift).

const MethodParameter& lqrEffort() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "lqr.effort", QT_TRANSLATE_NOOP("MethodParameter", "LQR effort weight R"), "1/action²",
            1e-6, 1e6, 6,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "R per control in the LQR's cost e^T W e + (u − u*)^T R (u − u*): "
                              "larger is gentler."));
        p.perChannel = true;
        p.get = [](const MethodTuning& f) { return f.lqrEffort; };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.lqrEffort = v; };
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
        p.get = [](const MethodTuning& f) { return one(f.lqrTerminal); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.lqrTerminal = v[0]; };
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
        p.get = [](const MethodTuning& f) { return one(f.lqrDrift ? 1.0 : 0.0); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.lqrDrift = v[0] != 0.0; };
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
