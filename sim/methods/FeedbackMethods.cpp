// The feedback law's parameters, shared by every method that starts from it (the PD family,
// PRISCA's prior, ILC, MPC's fallback), and the PD family and the open-loop playback.
#include "sim/methods/Declarations.h"

#include <QCoreApplication>
#include "core/ActionPlayback.h"
#include "core/PdController.h"
#include "sim/tuning/MethodTuning.h"

namespace prisca::sim::methods {

// Per demonstration sample: 1 where the robust fit explains it, else 0 (the feedback gate of
// MethodTuning::feedbackWhereExplained).
std::vector<double> explainedGate(const MethodTuning& profile,
                                  const core::Demonstration& demonstration) {
    const std::vector<bool> explained =
        core::fitActionMapping(demonstration, profile.mapping, profile.info.deviationModel())
            .explained;
    return std::vector<double>(explained.begin(), explained.end());
}

// Per demonstration sample, -1 on a car-like vehicle's heading and yaw-rate errors where the
// demonstration drives backwards, else 1 (n x T); empty for other plants (a differential drive
// turns on its own command, in either direction) or when switched off.
// The heading error turns into lateral error at the signed speed, and the steering turns the
// heading at the signed speed: in reverse both change sign, so a law derived for forward travel
// keeps its lateral term and must turn its heading terms round (docs/research-log.md).
Eigen::MatrixXd reverseSchedule(const MethodTuning& profile,
                                const core::Demonstration& demonstration) {
    const auto& pose = profile.info.pose;
    const auto& body = profile.info.bodyVelocity;
    if (!profile.feedbackReverseAware || !pose || !body || !profile.info.steersThroughTravel) {
        return {};
    }
    Eigen::MatrixXd schedule =
        Eigen::MatrixXd::Ones(demonstration.stateDimension(), demonstration.length());
    for (int j = 0; j < demonstration.length(); ++j) {
        if (demonstration.states(j, body->forward) < 0.0) {
            schedule(pose->heading, j) = -1.0;
            schedule(body->yawRate, j) = -1.0;
        }
    }
    return schedule;
}

const MethodParameter& feedbackReverseAware() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "feedback.reverse", QT_TRANSLATE_NOOP("MethodParameter", "Heading feedback reversed"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "For a vehicle, the feedback law (the PD family's, PRISCA's prior) "
                              "turns the sign of its heading and yaw-rate terms where the "
                              "demonstration drives backwards, where steering turns the car the "
                              "other way; off: the same law in both directions."));
        p.get = [](const MethodTuning& f) { return one(f.feedbackReverseAware ? 1.0 : 0.0); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.feedbackReverseAware = v[0] != 0.0;
        };
        return p;
    }();
    return p;
}

const MethodParameter& feedbackExplainedOnly() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "feedback.explained-only",
            QT_TRANSLATE_NOOP("MethodParameter", "Feedback where explained"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "The feedback law (the PD family's, PRISCA's prior) acts only while "
                              "the reference is a sample the robust fit explains: not in a slide, "
                              "where the linear model the gains stand on does not hold. auto: with "
                              "the demonstration start, not with the tuned one."));
        p.kind = Kind::Choice;
        p.choices = {"auto", "on", "off"};
        p.get = [](const MethodTuning& f) {
            return one(f.feedbackGate == MethodTuning::FeedbackGate::On    ? 1
                       : f.feedbackGate == MethodTuning::FeedbackGate::Off ? 2
                                                                           : 0);
        };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.feedbackGate = v[0] == 1.0   ? MethodTuning::FeedbackGate::On
                             : v[0] == 2.0 ? MethodTuning::FeedbackGate::Off
                                           : MethodTuning::FeedbackGate::Auto;
        };
        return p;
    }();
    return p;
}

const MethodParameter& start() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "start", QT_TRANSLATE_NOOP("MethodParameter", "Start"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "The feedback law the PD family and PRISCA (its prior) start from. "
                              "tuned: the plant profile's PD gains; demo: derived from the "
                              "demonstration, the fit and the actuator limits alone (a "
                              "stationary LQR gain on the fitted model with weights from the "
                              "demonstration's own scales, no faster than the fitted dead time "
                              "allows, on the errors B~ names per control but those the action "
                              "sets); PRISCA then also takes its automatic step and scales."));
        p.kind = Kind::Choice;
        p.choices = {"tuned", "demo"};
        p.get = [](const MethodTuning& f) {
            return one(f.start == MethodTuning::Start::Demonstration ? 1 : 0);
        };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.start = v[0] != 0.0 ? MethodTuning::Start::Demonstration : MethodTuning::Start::Tuned;
        };
        return p;
    }();
    return p;
}

const MethodParameter& matchingWindow() {
    static const MethodParameter p = [] {
        MethodParameter p = integer(
            "matching.window", QT_TRANSLATE_NOOP("MethodParameter", "Matching window"), "samples",
            0, 1000000,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "How far ahead the least-state-deviation reference may search "
                              "(eq. 12); 0 searches the whole demonstration."));
        p.get = [](const MethodTuning& f) { return one(f.matchingWindow); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.matchingWindow = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& pdKp() {
    static const MethodParameter p = [] {
        MethodParameter p =
            real("pd.kp", QT_TRANSLATE_NOOP("MethodParameter", "PD gain Kp"), "", 0, 1e4, 3,
                 QT_TRANSLATE_NOOP("MethodParameter",
                                   "Proportional gain per control on its error "
                                   "combination c_l · e (u = u* − Kp ε − Kd dε/dt)."));
        p.perChannel = true;
        p.get = [](const MethodTuning& f) -> Eigen::VectorXd { return f.pd.kp; };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.pd.kp = v; };
        return p;
    }();
    return p;
}

const MethodParameter& pdKd() {
    static const MethodParameter p = [] {
        MethodParameter p =
            real("pd.kd", QT_TRANSLATE_NOOP("MethodParameter", "PD gain Kd"), "s", 0, 1e4, 3,
                 QT_TRANSLATE_NOOP("MethodParameter",
                                   "Derivative gain per control on the rate of "
                                   "its error combination."));
        p.perChannel = true;
        p.get = [](const MethodTuning& f) -> Eigen::VectorXd { return f.pd.kd; };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.pd.kd = v; };
        return p;
    }();
    return p;
}

const MethodParameter& pdHorizon() {
    static const MethodParameter p = [] {
        MethodParameter p = integer(
            "pd.H", QT_TRANSLATE_NOOP("MethodParameter", "PD smoothing H"), "steps", 0, 1000,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "PD+H and PD+H+LSD smooth the error over this "
                              "many steps (the weights of eq. 9)."));
        p.get = [](const MethodTuning& f) { return one(f.pdHorizon); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.pdHorizon = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

namespace {

// The PD family: a plain PD, with the H-step smoothing, with the least-state-deviation
// reference, or both; PD (selected) is the PD with gains its training chose.
Made makePdFamily(const MethodSpec& spec, const MethodInput& in) {
    const bool smoothed = spec.id == QLatin1String("pd-h") || spec.id == QLatin1String("pd-h-lsd");
    const bool lsd = spec.id == QLatin1String("pd-lsd") || spec.id == QLatin1String("pd-h-lsd");
    const bool demoStart = in.profile.start == MethodTuning::Start::Demonstration;
    // The law derived from the demonstration smooths over PRISCA's horizon H (no tuned pd.H),
    // its lag counted in the loop's delay.
    const int horizon = !smoothed   ? 0
                        : demoStart ? in.profile.prisca.horizon
                                    : in.profile.pdHorizon;
    core::PdParameters gains = in.profile.startLaw(*in.demonstration, in.fittedB, horizon);
    auto pd = std::make_unique<core::PdController>(
        in.profile.trackingProblem(in.demonstration,
                                   lsd ? Mode::LeastStateDeviation : Mode::TimeDriven),
        gains, spec.id);
    if (in.profile.feedbackWhereExplained()) {
        pd->setFeedbackGate(explainedGate(in.profile, *in.demonstration));
    }
    pd->setErrorSchedule(reverseSchedule(in.profile, *in.demonstration));
    return pd;
}

Made makePlayback(const MethodSpec&, const MethodInput& in) {
    const MethodTuning& profile = in.profile;
    const auto& demonstration = in.demonstration;
    return std::make_unique<core::ActionPlayback>(
        profile.trackingProblem(demonstration, Mode::TimeDriven));
}

}  // namespace

/// The PD family, in Table I's order: PD, PD (selected), PD+H, PD+LSD, PD+H+LSD.
std::vector<MethodSpec> pdFamilyMethods() {
    std::vector<MethodSpec> family;
    family.push_back([] {
        MethodSpec s = entry("pd", "PD", &makePdFamily);
        s.summary = "proportional-derivative feedback around the demonstration, time-driven";
        s.parameters = {start(), feedbackExplainedOnly(), feedbackReverseAware(), pdKp(), pdKd()};
        return s;
    }());
    family.push_back([] {
        MethodSpec s = entry("pd-selected", "PD (SELECTED)", &makePdFamily);
        s.training = MethodSpec::Training::SelectPdGains;
        s.inCurves = false;  // selects its gains offline, before any curve starts
        s.summary = "PD with gains grid-searched on the training trials";
        s.parameters = {pdKp(), pdKd()};
        return s;
    }());
    family.push_back([] {
        MethodSpec s = entry("pd-h", "PD+H", &makePdFamily);
        s.summary = "PD on the error smoothed over H steps";
        s.parameters = {start(),    feedbackExplainedOnly(), feedbackReverseAware(), pdKp(), pdKd(),
                        pdHorizon()};
        return s;
    }());
    family.push_back([] {
        MethodSpec s = entry("pd-lsd", "PD+LSD", &makePdFamily);
        s.summary = "PD with the least-state-deviation reference";
        s.parameters = {start(), feedbackExplainedOnly(), feedbackReverseAware(), pdKp(),
                        pdKd(),  matchingWindow()};
        return s;
    }());
    family.push_back([] {
        MethodSpec s = entry("pd-h-lsd", "PD+H+LSD", &makePdFamily);
        s.summary = "PD with both";
        s.parameters = {
            start(),     feedbackExplainedOnly(), feedbackReverseAware(), pdKp(), pdKd(),
            pdHorizon(), matchingWindow()};
        return s;
    }());
    return family;
}

Made makePdLsd(const MethodInput& in) {
    static const MethodSpec pdLsd = [] {
        for (MethodSpec& s : pdFamilyMethods()) {
            if (s.id == QLatin1String("pd-lsd")) {
                return s;
            }
        }
        throw std::logic_error("the PD family declares no pd-lsd");
    }();
    return makePdFamily(pdLsd, in);
}

/// The demonstration's actions, open loop.
MethodSpec playbackMethod() {
    MethodSpec s = entry("playback", "ACTION PLAYBACK", &makePlayback);
    s.summary = "the demonstration's actions, open loop";
    s.parameters = {};
    return s;
}

}  // namespace prisca::sim::methods
