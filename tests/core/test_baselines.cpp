// The comparison methods: PD and its H / LSD variants, action playback, PEGASUS.
#include "TestDemonstrations.h"
#include "core/ActionPlayback.h"
#include "core/IlcController.h"
#include "core/LqrController.h"
#include "core/PdController.h"
#include "core/Pegasus.h"
#include "core/PriscaController.h"

#include <QtTest>

#include <cmath>
#include <memory>
#include <random>
#include <set>

using namespace prisca::core;

namespace {

// Demonstration of an integrator s_{k+1} = s_k + dt G u_k driven by smooth actions.
std::shared_ptr<Demonstration> integratorDemonstration(const Eigen::MatrixXd& G, int T, double dt) {
    const int n = static_cast<int>(G.rows()), m = static_cast<int>(G.cols());
    auto d = std::make_shared<Demonstration>(prisca::test::namedDemonstration(T, n, m, dt, "m"));
    Eigen::VectorXd s = Eigen::VectorXd::Zero(n);
    for (int k = 0; k < T; ++k) {
        for (int l = 0; l < m; ++l)
            d->actions(k, l) = std::sin(1.1 * k * dt + l);
        d->states.row(k) = s.transpose();
        s += dt * G * d->actions.row(k).transpose();
    }
    return d;
}

TrackingProblem problemFor(std::shared_ptr<const Demonstration> demo,
                           MatchingParameters::Mode mode) {
    TrackingProblem problem;
    problem.demonstration = demo;
    problem.deviation = DeviationModel::euclidean(demo->stateDimension());
    problem.matching.mode = mode;
    problem.matching.window = 10;
    problem.limits = ActionLimits::symmetric(demo->actionDimension(), 5.0);
    return problem;
}

// Mean cost of one closed-loop trial on the integrator with gain scaled by `gainError`.
double closedLoopCost(Controller& controller, const Demonstration& demo, const Eigen::MatrixXd& G,
                      double gainError, ResetMode mode = ResetMode::Cold) {
    controller.reset(mode);
    Eigen::VectorXd s = Eigen::VectorXd::Constant(G.rows(), 0.05);
    double sum = 0.0;
    for (int k = 0; k < demo.length(); ++k) {
        const ControlStep& out = controller.step(s);
        sum += out.cost;
        s += demo.dt * gainError * G * out.action;
    }
    return sum / demo.length();
}

}  // namespace

class TestBaselines : public QObject {
    Q_OBJECT
  private slots:
    // The LQR's gains are the finite-horizon Riccati recursion's: checked against the scalar
    // recursion written out by hand, and the loop they close holds an offset start on the
    // integrator the model describes (far better than open loop).
    void lqr_gainsAreTheRiccatiRecursionsAndHoldTheIntegrator() {
        const double dt = 0.05, g = 2.0, q = 1.0, r = 0.1, terminal = 5.0;
        const int T = 60;
        const Eigen::MatrixXd G = Eigen::MatrixXd::Constant(1, 1, g);
        auto demo = integratorDemonstration(G, T, dt);
        TrackingProblem problem = problemFor(demo, MatchingParameters::Mode::TimeDriven);
        problem.costWeights = Eigen::VectorXd::Constant(1, q);
        LqrParameters parameters;
        parameters.a = Eigen::MatrixXd::Zero(1, 1);
        parameters.b = Eigen::MatrixXd::Constant(1, 1, g);  // m x n
        parameters.effort = Eigen::VectorXd::Constant(1, r);
        parameters.terminalWeight = terminal;
        LqrController lqr(problem, parameters);
        QCOMPARE(lqr.gainCount(), T);
        // By hand: P_T = terminal q; K = bd P / (r + bd^2 P); P <- q + P (1 - bd K).
        const double bd = dt * g;
        double P = terminal * q;
        std::vector<double> expected(T);
        for (int k = T - 1; k >= 0; --k) {
            const double K = bd * P / (r + bd * bd * P);
            P = q + P * (1.0 - bd * K);
            expected[k] = K;
        }
        for (int k : {0, T / 2, T - 1}) {
            QVERIFY2(std::abs(lqr.gain(k)(0, 0) - expected[k]) < 1e-12,
                     qPrintable(QStringLiteral("K_%1 %2 vs %3")
                                    .arg(k)
                                    .arg(lqr.gain(k)(0, 0))
                                    .arg(expected[k])));
        }
        QCOMPARE(lqr.gain(T + 10)(0, 0), lqr.gain(T - 1)(0, 0));  // past the end: the last
        // On the demonstration itself the action is the demonstration's.
        lqr.reset();
        const ControlStep& first = lqr.step(demo->states.row(0).transpose());
        QCOMPARE(first.action[0], demo->actions(0, 0));
        ActionPlayback playback(problemFor(demo, MatchingParameters::Mode::TimeDriven));
        const double closed = closedLoopCost(lqr, *demo, G, 1.0);
        const double open = closedLoopCost(playback, *demo, G, 1.0);
        QVERIFY2(closed < 0.2 * open, qPrintable(QStringLiteral("%1 vs %2").arg(closed).arg(open)));
        // A model that says nothing moves, or no effort cost, is refused.
        parameters.effort[0] = 0.0;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, LqrController(problem, parameters));
    }

    void pd_isNegativeFeedbackOnTheCombinedError() {
        auto demo = integratorDemonstration(Eigen::MatrixXd::Identity(2, 2), 50, 0.1);
        PdParameters gains;
        gains.errorCombination = (Eigen::MatrixXd(2, 2) << 1.0, 0.5, 0.0, 1.0).finished();
        gains.kp = Eigen::Vector2d(2.0, 3.0);
        gains.kd = Eigen::Vector2d(0.5, 0.0);
        PdController pd(problemFor(demo, MatchingParameters::Mode::TimeDriven), gains, "pd");
        double previous0 = 0.0;
        for (int k = 0; k < 10; ++k) {
            const Eigen::Vector2d e(0.1 * k, -0.05 * k * k);
            const ControlStep& out = pd.step(demo->states.row(k).transpose() + e);
            const double eps0 = e[0] + 0.5 * e[1], eps1 = e[1];
            const double rate0 = k == 0 ? 0.0 : (eps0 - previous0) / 0.1;
            previous0 = eps0;
            QVERIFY(std::abs(out.action[0] - (demo->actions(k, 0) - 2.0 * eps0 - 0.5 * rate0)) <=
                    1e-12);
            QVERIFY(std::abs(out.action[1] -
                             std::clamp(demo->actions(k, 1) - 3.0 * eps1, -5.0, 5.0)) <= 1e-12);
            QCOMPARE(out.referenceIndex, k);
        }
    }

    // A feedback gate per reference sample: the feedback acts in full where the gate is 1, not
    // at all where it is 0 (the demonstration's action alone), in proportion in between.
    void pd_feedbackGateScalesTheFeedbackByTheReferenceSample() {
        auto demo = integratorDemonstration(Eigen::MatrixXd::Identity(2, 2), 50, 0.1);
        PdParameters gains;
        gains.errorCombination = Eigen::MatrixXd::Identity(2, 2);
        gains.kp = Eigen::Vector2d(2.0, 3.0);
        gains.kd = Eigen::Vector2d::Zero();
        PdController pd(problemFor(demo, MatchingParameters::Mode::TimeDriven), gains, "pd");
        std::vector<double> gate(50, 1.0);
        for (int k = 10; k < 20; ++k) {
            gate[static_cast<size_t>(k)] = 0.0;
        }
        gate[20] = 0.5;
        pd.setFeedbackGate(gate);
        for (int k = 0; k < 25; ++k) {
            const Eigen::Vector2d e(0.1, -0.05);
            const ControlStep& out = pd.step(demo->states.row(k).transpose() + e);
            const double g = gate[static_cast<size_t>(k)];
            QVERIFY2(std::abs(out.action[0] - (demo->actions(k, 0) - g * 2.0 * 0.1)) <= 1e-12,
                     qPrintable(QString::number(k)));
            QVERIFY(std::abs(out.action[1] - (demo->actions(k, 1) + g * 3.0 * 0.05)) <= 1e-12);
        }
    }

    // A car's lateral error in its linearised kinematics, e_lat' = v e_psi, e_psi' = (v / L) d:
    // a law derived for forward travel, d = -(k1 e_lat + k2 e_psi), is stable for v > 0 and
    // unstable in reverse (both signs turn, the closed loop's trace becomes +k2 v / L); with the
    // heading's sign turned where the demonstration reverses (the error schedule) it holds.
    void pd_errorScheduleTurnsTheHeadingTermRoundInReverse() {
        const double dt = 0.02, wheelbase = 0.26, k1 = 2.0, k2 = 0.8;
        const int T = 300;
        auto demo = std::make_shared<Demonstration>(prisca::test::namedDemonstration(T, 2, 1, dt));
        demo->states.setZero();
        demo->actions.setZero();
        PdParameters law;
        law.errorCombination = (Eigen::MatrixXd(1, 2) << k1, k2).finished();
        law.kp = Eigen::VectorXd::Ones(1);
        law.kd = Eigen::VectorXd::Zero(1);
        auto finalError = [&](double speed, bool schedule) {
            TrackingProblem problem = problemFor(demo, MatchingParameters::Mode::TimeDriven);
            problem.limits = ActionLimits::symmetric(1, 1e9);
            PdController pd(problem, law, "pd");
            if (schedule) {
                Eigen::MatrixXd factors = Eigen::MatrixXd::Ones(2, T);
                factors.row(1).setConstant(speed < 0.0 ? -1.0 : 1.0);
                pd.setErrorSchedule(factors);
            }
            Eigen::Vector2d e(0.1, 0.0);
            for (int k = 0; k < T && e.allFinite(); ++k) {
                const double d = pd.step(e).action[0];
                e += dt * Eigen::Vector2d(speed * e[1], speed / wheelbase * d);
            }
            return e.norm();
        };
        QVERIFY2(finalError(1.0, false) < 0.01,
                 qPrintable(QString::number(finalError(1.0, false))));
        QVERIFY2(finalError(1.0, true) == finalError(1.0, false), "forward: nothing changes");
        QVERIFY2(!(finalError(-1.0, false) < 1.0),
                 qPrintable(QString::number(finalError(-1.0, false))));
        QVERIFY2(finalError(-1.0, true) < 0.01,
                 qPrintable(QString::number(finalError(-1.0, true))));
    }

    void pdH_smoothsTheErrorWithTheNestedWeights() {
        auto demo = integratorDemonstration(Eigen::MatrixXd::Identity(1, 1), 40, 0.1);
        PdParameters gains;
        gains.errorCombination = Eigen::MatrixXd::Ones(1, 1);
        gains.kp = Eigen::VectorXd::Constant(1, 1.0);
        gains.kd = Eigen::VectorXd::Zero(1);
        gains.horizon = 3;
        PdController pd(problemFor(demo, MatchingParameters::Mode::TimeDriven), gains, "pd-h");
        std::vector<double> errors;
        for (int k = 0; k < 12; ++k) {
            const double e = std::cos(0.9 * k);
            errors.push_back(e);
            const double u =
                pd.step(demo->states.row(k).transpose() + Eigen::VectorXd::Constant(1, e))
                    .action[0];
            const int a = std::max(0, k - 3);
            double smoothed = 0.0;  // E_{i=a:k} E_{j=i:k} e_j, literally
            for (int i = a; i <= k; ++i) {
                double inner = 0.0;
                for (int j = i; j <= k; ++j)
                    inner += errors[j];
                smoothed += inner / (k - i + 1);
            }
            smoothed /= (k - a + 1);
            QVERIFY2(std::abs(u - (demo->actions(k, 0) - smoothed)) <= 1e-12,
                     qPrintable(QString::number(k)));
        }
    }

    void pdLsd_followsTheNearestDemonstrationState() {
        auto demo = integratorDemonstration(Eigen::MatrixXd::Identity(1, 1), 60, 0.1);
        PdParameters gains;
        gains.errorCombination = Eigen::MatrixXd::Ones(1, 1);
        gains.kp = Eigen::VectorXd::Constant(1, 1.0);
        gains.kd = Eigen::VectorXd::Zero(1);
        PdController pd(problemFor(demo, MatchingParameters::Mode::LeastStateDeviation), gains,
                        QStringLiteral("pd-lsd"));
        QCOMPARE(pd.name(), QStringLiteral("pd-lsd"));
        // Holding still at the start: the reference waits instead of running away by time. The
        // demonstration's first two samples are equal (u*_0 = 0), so it waits at the second.
        QVERIFY(demo->states.row(0) == demo->states.row(1));
        QVERIFY(demo->states.row(2) != demo->states.row(1));
        for (int k = 0; k < 5; ++k)
            QCOMPARE(pd.step(demo->states.row(0).transpose()).referenceIndex, std::min(k, 1));
    }

    void pd_closesTheLoopBetterThanPlaybackWhenTheGainIsWrong() {
        const Eigen::MatrixXd G = Eigen::MatrixXd::Identity(2, 2);
        auto demo = integratorDemonstration(G, 300, 0.025);
        PdParameters gains;
        gains.errorCombination = Eigen::MatrixXd::Identity(2, 2);
        gains.kp = Eigen::Vector2d(8.0, 8.0);
        gains.kd = Eigen::Vector2d(0.0, 0.0);
        PdController pd(problemFor(demo, MatchingParameters::Mode::TimeDriven), gains, "pd");
        ActionPlayback playback(problemFor(demo, MatchingParameters::Mode::TimeDriven));
        const double pdCost = closedLoopCost(pd, *demo, G, 2.0);
        const double playbackCost = closedLoopCost(playback, *demo, G, 2.0);
        QVERIFY2(pdCost * 5.0 < playbackCost,
                 qPrintable(QString("%1 vs %2").arg(pdCost).arg(playbackCost)));
    }

    void playback_replaysActionsByTimeAndHoldsTheLast() {
        auto demo = integratorDemonstration(Eigen::MatrixXd::Identity(1, 1), 8, 0.1);
        TrackingProblem problem = problemFor(demo, MatchingParameters::Mode::LeastStateDeviation);
        problem.limits = ActionLimits::symmetric(1, 0.9);
        ActionPlayback playback(problem);
        for (int k = 0; k < 12; ++k) {
            const Eigen::VectorXd s =
                Eigen::VectorXd::Constant(1, 100.0);  // ignored for the action
            const ControlStep& out = playback.step(s);
            const int j = std::min(k, 7);
            QCOMPARE(out.referenceIndex, j);
            QCOMPARE(out.action[0], std::clamp(demo->actions(j, 0), -0.9, 0.9));
            QVERIFY(std::abs(out.cost - std::pow(100.0 - demo->states(j, 0), 2)) <= 1e-9);
        }
        playback.reset();
        QCOMPARE(playback.step(Eigen::VectorXd::Zero(1)).referenceIndex, 0);
    }

    void pegasus_finiteDifferenceGradientIsExactOnAQuadratic() {
        Eigen::MatrixXd target(2, 2);
        target << 1.0, -2.0, 0.5, 3.0;
        std::set<int> scenariosSeen;
        auto rollout = [&](const Eigen::MatrixXd& theta, int scenario) {
            scenariosSeen.insert(scenario);
            const Eigen::MatrixXd shifted = target.array() + 0.1 * scenario;
            return EpisodeOutcome{(theta - shifted).squaredNorm(), 100};
        };
        PegasusParameters parameters;
        parameters.scenarios = 3;
        parameters.stepSize = 0.25;
        parameters.perturbation = 0.01;
        Pegasus pegasus(rollout, Eigen::MatrixXd::Zero(2, 2), parameters);
        const auto first = pegasus.iterate();
        QVERIFY(first.has_value());
        const Eigen::MatrixXd meanTarget = target.array() + 0.1;  // mean of the three shifts
        QVERIFY((first->gradient - (-2.0 * meanTarget)).cwiseAbs().maxCoeff() <= 1e-9);
        QCOMPARE(first->stepsConsumed, (2LL * 4 + 1) * 3 * 100);
        QCOMPARE(pegasus.stepsConsumed(), first->stepsConsumed);
        QCOMPARE(scenariosSeen, (std::set<int>{0, 1, 2}));
        for (int i = 0; i < 40; ++i)
            pegasus.iterate();
        QVERIFY((pegasus.theta() - meanTarget).cwiseAbs().maxCoeff() <= 1e-9);
    }

    void pegasus_cancelLeavesThetaAndLimitsTheStep() {
        auto rollout = [](const Eigen::MatrixXd& theta, int) {
            return EpisodeOutcome{theta.squaredNorm(), 1};
        };
        PegasusParameters parameters;
        parameters.stepSize = 100.0;
        parameters.maxStepNorm = 0.5;
        Pegasus pegasus(rollout, Eigen::MatrixXd::Constant(1, 2, 3.0), parameters);
        int polls = 0;
        QVERIFY(!pegasus.iterate([&] { return ++polls > 3; }).has_value());
        QCOMPARE(pegasus.theta(), Eigen::MatrixXd::Constant(1, 2, 3.0));
        QVERIFY(pegasus.iterate().has_value());
        QVERIFY(std::abs((pegasus.theta() - Eigen::MatrixXd::Constant(1, 2, 3.0)).norm() - 0.5) <=
                1e-12);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 Pegasus({}, Eigen::MatrixXd::Zero(1, 1), {}));
    }

    void pegasus_improvesAFrozenLinearPolicyOnFixedScenarios() {
        const Eigen::MatrixXd G = Eigen::MatrixXd::Identity(1, 1);
        auto demo = integratorDemonstration(G, 200, 0.025);
        PriscaParameters frozen;
        frozen.learning = false;
        PriscaController policy(problemFor(demo, MatchingParameters::Mode::TimeDriven),
                                FeatureMap::deviationFeatures(1, {0}), Eigen::MatrixXd::Ones(1, 1),
                                frozen);
        auto rollout = [&](const Eigen::MatrixXd& theta, int scenario) {
            policy.setTheta(theta);
            policy.reset(ResetMode::WarmStart);
            Eigen::VectorXd s = Eigen::VectorXd::Constant(1, 0.1 * (scenario + 1));
            double sum = 0.0;
            for (int k = 0; k < demo->length(); ++k) {
                const ControlStep& out = policy.step(s);
                sum += out.cost;
                s += demo->dt * 2.5 * G * out.action;  // the real gain differs
            }
            return EpisodeOutcome{sum / demo->length(), demo->length()};
        };
        PegasusParameters parameters;
        parameters.scenarios = 2;
        parameters.stepSize = 20.0;
        parameters.maxStepNorm = 2.0;
        Pegasus pegasus(rollout, Eigen::MatrixXd::Zero(1, 1), parameters);
        const double before = pegasus.evaluate(pegasus.theta());
        for (int i = 0; i < 30; ++i)
            pegasus.iterate();
        const double after = pegasus.evaluate(pegasus.theta());
        QVERIFY2(after < 0.5 * before, qPrintable(QString("%1 -> %2").arg(before).arg(after)));
        QVERIFY(pegasus.theta()(0, 0) < 0.0);  // negative feedback was found
    }

    void observationAge_isCompensatedByEveryReferenceTracker() {
        // Observations two steps old of a robot that repeats the demonstration exactly: with the
        // age known, every tracker sees no error and applies the demonstration's action of now.
        auto demo = integratorDemonstration(Eigen::MatrixXd::Identity(2, 2), 40, 0.1);
        PdParameters gains;
        gains.errorCombination = Eigen::MatrixXd::Identity(2, 2);
        gains.kp = Eigen::Vector2d(3.0, 3.0);
        gains.kd = Eigen::Vector2d(0.5, 0.5);
        IlcParameters ilcParameters;
        ilcParameters.feedback = gains;
        ilcParameters.learningGain = Eigen::Vector2d(0.5, 0.5);
        std::vector<std::unique_ptr<Controller>> trackers;
        trackers.push_back(std::make_unique<PdController>(
            problemFor(demo, MatchingParameters::Mode::TimeDriven), gains, "pd"));
        trackers.push_back(std::make_unique<PdController>(
            problemFor(demo, MatchingParameters::Mode::LeastStateDeviation), gains, "pd-lsd"));
        trackers.push_back(std::make_unique<IlcController>(
            problemFor(demo, MatchingParameters::Mode::TimeDriven), ilcParameters));
        const int age = 2;
        for (auto& tracker : trackers) {
            for (bool compensate : {false, true}) {
                tracker->setLoopLatencySteps(compensate ? age : 0);
                tracker->reset(ResetMode::Cold);
                double worst = 0.0;
                for (int k = 0; k < demo->length(); ++k) {
                    const Eigen::VectorXd seen = demo->states.row(std::max(0, k - age)).transpose();
                    const ControlStep& out = tracker->step(seen);
                    worst = std::max(
                        worst,
                        (out.action - demo->actions.row(k).transpose()).cwiseAbs().maxCoeff());
                }
                if (compensate) {
                    QVERIFY2(worst < 1e-12, qPrintable(tracker->name()));
                } else {
                    QVERIFY2(worst > 0.01, qPrintable(tracker->name()));
                }
            }
        }
    }

    void ilc_convergesOnALinearPlantWhoseGainIsWrong() {
        // The plant's gain is 1.6 times the demonstration's and every trial starts 0.05 off:
        // a repeated disturbance that feedback alone leaves, and ILC learns away trial by trial.
        const Eigen::MatrixXd G = Eigen::MatrixXd::Identity(2, 2);
        auto demo = integratorDemonstration(G, 200, 0.1);
        IlcParameters parameters;
        parameters.feedback.errorCombination = Eigen::MatrixXd::Identity(2, 2);
        parameters.feedback.kp = Eigen::Vector2d(4.0, 4.0);
        parameters.feedback.kd = Eigen::Vector2d::Zero();
        parameters.learningGain = Eigen::Vector2d(2.0, 2.0);
        parameters.lead = 1;  // u_k shows in s_{k+1}
        parameters.cutoff = 0.0;
        IlcController ilc(problemFor(demo, MatchingParameters::Mode::TimeDriven), parameters);
        QCOMPARE(ilc.name(), QStringLiteral("ilc"));
        PdController pd(problemFor(demo, MatchingParameters::Mode::TimeDriven), parameters.feedback,
                        "pd");
        const double feedbackOnly = closedLoopCost(pd, *demo, G, 1.6);
        std::vector<double> costs;
        for (int trial = 0; trial < 30; ++trial) {
            costs.push_back(closedLoopCost(ilc, *demo, G, 1.6,
                                           trial == 0 ? ResetMode::Cold : ResetMode::WarmStart));
        }
        QCOMPARE(ilc.iterations(), 29);
        QVERIFY(std::abs(costs.front() - feedbackOnly) <= 1e-12);  // trial 1 is plain PD
        for (size_t i = 1; i < costs.size(); ++i)
            QVERIFY2(costs[i] < costs[i - 1], qPrintable(QString::number(i)));
        // What is left is the start error every trial begins with (e_0 cannot be learned away).
        QVERIFY2(costs.back() < 1e-2 * costs.front(),
                 qPrintable(QStringLiteral("%1 -> %2").arg(costs.front()).arg(costs.back())));
        // A cold reset forgets: back to plain PD.
        QVERIFY(std::abs(closedLoopCost(ilc, *demo, G, 1.6) - feedbackOnly) <= 1e-12);
        QVERIFY(ilc.feedforward().isZero());
    }

    void ilc_learnsNothingFromAPerfectTrialAndFiltersWithZeroPhase() {
        const Eigen::MatrixXd G = Eigen::MatrixXd::Identity(1, 1);
        auto demo = integratorDemonstration(G, 100, 0.05);
        IlcParameters parameters;
        parameters.feedback.errorCombination = Eigen::MatrixXd::Ones(1, 1);
        parameters.feedback.kp = Eigen::VectorXd::Constant(1, 1.0);
        parameters.feedback.kd = Eigen::VectorXd::Zero(1);
        parameters.learningGain = Eigen::VectorXd::Constant(1, 1.0);
        parameters.lead = 0;
        parameters.cutoff = 1.0;
        IlcController ilc(problemFor(demo, MatchingParameters::Mode::TimeDriven), parameters);
        // On the demonstration exactly: no error, nothing learned, the demonstration's actions.
        ilc.reset(ResetMode::Cold);
        for (int k = 0; k < demo->length(); ++k) {
            const ControlStep& out = ilc.step(demo->states.row(k).transpose());
            QVERIFY(std::abs(out.action[0] - demo->actions(k, 0)) <= 1e-15);
        }
        ilc.reset(ResetMode::WarmStart);
        QVERIFY(ilc.feedforward().isZero());
        // One unit error at the middle sample only: the update is -1 there, then the forward and
        // backward pass of the low-pass spread it symmetrically (zero phase) and keep its sum.
        for (int k = 0; k < demo->length(); ++k) {
            Eigen::VectorXd s = demo->states.row(k).transpose();
            if (k == 50)
                s[0] += 1.0;
            ilc.step(s);
        }
        ilc.reset(ResetMode::WarmStart);
        const Eigen::RowVectorXd f = ilc.feedforward().row(0);
        Eigen::Index peak = 0;
        f.minCoeff(&peak);
        QCOMPARE(peak, Eigen::Index(50));
        // Symmetric up to the ends of a finite record (a^49 = 2e-7 of the response is cut off).
        for (int d = 1; d < 20; ++d)
            QVERIFY2(std::abs(f[50 - d] - f[50 + d]) <= 1e-6, qPrintable(QString::number(d)));
        QVERIFY(std::abs(f.sum() + 1.0) <= 1e-6);
        QVERIFY(f[50] > -0.5);  // filtered: not the raw -1
    }

    void ilc_rejectsInconsistentParameters() {
        auto demo = integratorDemonstration(Eigen::MatrixXd::Identity(2, 2), 20, 0.1);
        IlcParameters bad;
        bad.feedback.errorCombination = Eigen::MatrixXd::Identity(2, 2);
        bad.feedback.kp = Eigen::Vector2d::Ones();
        bad.feedback.kd = Eigen::Vector2d::Zero();
        bad.learningGain = Eigen::Vector2d(1.0, -1.0);
        QVERIFY_THROWS_EXCEPTION(
            std::invalid_argument,
            IlcController(problemFor(demo, MatchingParameters::Mode::TimeDriven), bad));
        bad.learningGain = Eigen::VectorXd::Ones(3);
        QVERIFY_THROWS_EXCEPTION(
            std::invalid_argument,
            IlcController(problemFor(demo, MatchingParameters::Mode::TimeDriven), bad));
    }
};

QTEST_APPLESS_MAIN(TestBaselines)
#include "test_baselines.moc"
