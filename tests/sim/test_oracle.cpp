// The oracle plans on copies of the trial's plant. On a plant whose optimum is known (a planar
// point whose actuator gains differ from the demonstration's: scaling the actions by the gain
// ratio repeats the demonstration exactly) it must find that optimum without being told.
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/episodes/TrialMetrics.h"
#include "sim/planning/OracleController.h"
#include "sim/tuning/MethodTuning.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace prisca;
using namespace prisca::sim;

namespace {

// A point on the floor (x, y, heading and what the derived plant adds), stepped by the
// derived plant; heading fixed at 0.
class FloorPoint : public Plant {
  public:
    const PlantInfo& info() const override { return info_; }
    const SimulationTiming& timing() const override { return timing_; }
    Eigen::VectorXd reset(std::uint64_t, const Perturbation&) override {
        s_.setZero(info_.stateDimension());
        t_ = 0.0;
        return s_;
    }
    Eigen::VectorXd resetTo(const Eigen::VectorXd& s) override {
        s_ = s;
        return s_;
    }
    Eigen::VectorXd state() const override { return s_; }
    double time() const override { return t_; }

  protected:
    FloorPoint(const QString& name, QStringList extraStates, QStringList extraUnits) {
        info_.name = name;
        info_.stateNames = QStringList{"x", "y", "psi"} + extraStates;
        info_.stateUnits = QStringList{"m", "m", "rad"} + extraUnits;
        info_.angleIndices = {2};
        info_.pose = core::PlanarPoseIndices{0, 1, 2};
        s_.setZero(info_.stateDimension());
    }
    PlantInfo info_;
    SimulationTiming timing_;
    Eigen::VectorXd s_;
    double t_ = 0.0;
};

// x += dt gx ux, y += dt gy uy. Actions in [-2, 2].
class GainPoint : public FloorPoint {
  public:
    explicit GainPoint(Eigen::Vector2d gain) : FloorPoint("gainpoint", {}, {}), gain_(gain) {
        info_.actionNames = {"ux", "uy"};
        info_.actionUnits = {"m/s", "m/s"};
        info_.actionLower = Eigen::Vector2d(-2.0, -2.0);
        info_.actionUpper = Eigen::Vector2d(2.0, 2.0);
    }
    Eigen::VectorXd step(const Eigen::VectorXd& u) override {
        const Eigen::Vector2d a = u.cwiseMax(info_.actionLower).cwiseMin(info_.actionUpper);
        s_.head<2>() += timing_.controlPeriod * gain_.cwiseProduct(a);
        t_ += timing_.controlPeriod;
        return s_;
    }
    std::unique_ptr<Plant> clone(bool) const override { return std::make_unique<GainPoint>(*this); }

  private:
    Eigen::Vector2d gain_;
};

// A point that coasts: v += dt (g u - c v), x += dt v, on x only; it rests below 1 cm/s. The
// action pushes forward only (a brakeless car's throttle).
class CoastPoint : public FloorPoint {
  public:
    explicit CoastPoint(double gain) : FloorPoint("coastpoint", {"v"}, {"m/s"}), gain_(gain) {
        info_.actionNames = {"u"};
        info_.actionUnits = {"m/s^2"};
        info_.actionLower = Eigen::VectorXd::Zero(1);
        info_.actionUpper = Eigen::VectorXd::Constant(1, 2.0);
    }
    Eigen::VectorXd step(const Eigen::VectorXd& u) override {
        const double a = std::clamp(u[0], 0.0, 2.0);
        s_[3] += timing_.controlPeriod * (gain_ * a - 1.5 * s_[3]);
        s_[0] += timing_.controlPeriod * s_[3];
        t_ += timing_.controlPeriod;
        return s_;
    }
    bool atRest() const override { return std::abs(s_[3]) < 0.01; }
    std::unique_ptr<Plant> clone(bool) const override {
        return std::make_unique<CoastPoint>(*this);
    }

  private:
    double gain_;
};

// T steps of `nominal` driven by actionAt(k), recorded as its demonstration.
std::shared_ptr<core::Demonstration> recorded(Plant& nominal, int T,
                                              const std::function<Eigen::VectorXd(int)>& actionAt) {
    auto demo = std::make_shared<core::Demonstration>();
    demo->plant = nominal.info().name;
    demo->dt = nominal.timing().controlPeriod;
    demo->stateNames = nominal.info().stateNames;
    demo->stateUnits = nominal.info().stateUnits;
    demo->actionNames = nominal.info().actionNames;
    demo->actionUnits = nominal.info().actionUnits;
    demo->time.resize(T);
    demo->states.resize(T, nominal.info().stateDimension());
    demo->actions.resize(T, nominal.info().actionDimension());
    Eigen::VectorXd s = nominal.reset(0, Perturbation::none());
    for (int k = 0; k < T; ++k) {
        demo->time[k] = k * demo->dt;
        demo->states.row(k) = s.transpose();
        demo->actions.row(k) = actionAt(k).transpose();
        s = nominal.step(demo->actions.row(k).transpose());
    }
    return demo;
}

// The demonstration on the nominal point (gains 1): a smooth curve to (1.5, 0.8).
std::shared_ptr<core::Demonstration> demonstration(int T) {
    GainPoint nominal(Eigen::Vector2d(1.0, 1.0));
    return recorded(nominal, T, [T](int k) -> Eigen::VectorXd {
        const double phase = M_PI * k / (T - 1);
        return k == T - 1 ? Eigen::Vector2d::Zero()
                          : Eigen::Vector2d(0.6 * std::sin(phase) * 1.5 * M_PI / 2,
                                            0.8 * std::sin(2 * phase) + 0.4 * std::sin(phase));
    });
}

core::TrackingProblem problemFor(std::shared_ptr<const core::Demonstration> demo,
                                 const PlantInfo& info) {
    core::TrackingProblem problem;
    problem.demonstration = demo;
    problem.deviation = info.deviationModel();
    problem.matching.mode = core::MatchingParameters::Mode::TimeDriven;
    problem.limits = core::ActionLimits{info.actionLower, info.actionUpper};
    return problem;
}

}  // namespace

class TestOracle : public QObject {
    Q_OBJECT
  private slots:
    void finalPose_findsTheKnownOptimumOfAPlantWithWrongGains() {
        auto demo = demonstration(120);
        GainPoint plant(Eigen::Vector2d(1.3, 0.75));
        OracleParameters parameters;
        parameters.objective = OracleParameters::Objective::FinalPose;
        parameters.trialSteps = demo->length();
        parameters.samples = 32;
        OracleController oracle(problemFor(demo, plant.info()), parameters);
        EpisodeSettings episode;
        episode.duration = demo->length() * demo->dt;
        const EpisodeResult result = runEpisode(plant, oracle, episode);
        const Eigen::Vector2d lot = demo->states.row(demo->length() - 1).head<2>().transpose();
        const double miss = (result.finalState.head<2>() - lot).norm();
        // Playing the demonstration back misses by metres' worth of gain error ...
        GainPoint open(Eigen::Vector2d(1.3, 0.75));
        open.reset(0, Perturbation::none());
        for (int k = 0; k < demo->length(); ++k)
            open.step(demo->actions.row(k).transpose());
        const double playbackMiss = (open.state().head<2>() - lot).norm();
        QVERIFY2(playbackMiss > 0.2, qPrintable(QString::number(playbackMiss)));
        // ... the oracle parks within a millimetre, having found the compensation itself.
        QVERIFY2(miss < 1e-3, qPrintable(QString::number(miss)));
        QVERIFY(oracle.simulatedSteps() > demo->length());
    }

    // A plant that coasts on after the trial's last step: the plan is scored where it comes to
    // rest in neutral, as the trial is (EpisodeSettings::runOutLimit), not where the last step
    // left it. A weaker motor than the demonstration's (0.7) and a trial that ends 1 s after the
    // demonstration: planned to the last step only, the point is still moving there and rests
    // 3.6 cm from the lot (measured); planned to where it rests, within 2 mm.
    void finalPose_aPlantStillMovingIsScoredWhereItRests() {
        const int T = 120;
        CoastPoint nominal(1.0);
        // Pushed for 1 s, then it coasts to rest.
        const auto demo = recorded(
            nominal, T, [](int k) { return Eigen::VectorXd::Constant(1, k < 40 ? 1.5 : 0.0); });
        const double lot = demo->states(T - 1, 0);
        double rested[2] = {0.0, 0.0};
        for (const int runOut : {0, 1}) {
            OracleParameters parameters;
            parameters.objective = OracleParameters::Objective::FinalPose;
            parameters.trialSteps = T + 40;
            parameters.runOutSteps = runOut * 400;
            parameters.samples = 32;
            CoastPoint weak(0.7);
            OracleController oracle(problemFor(demo, weak.info()), parameters);
            EpisodeSettings episode;
            episode.duration = parameters.trialSteps * demo->dt;
            episode.runOutLimit = 10.0;
            const EpisodeResult result = runEpisode(weak, oracle, episode);
            QVERIFY(weak.atRest());
            rested[runOut] = std::abs(result.finalState[0] - lot);
        }
        QVERIFY2(rested[1] < 0.002, qPrintable(QString::number(rested[1])));
        QVERIFY2(rested[0] > 10.0 * std::max(rested[1], 0.001),
                 qPrintable(QStringLiteral("%1 against %2").arg(rested[0]).arg(rested[1])));
    }

    // An ensemble: the plan must park every model, so on a point whose x-gain the models
    // disagree on (1.1, 1.3 and 1.5) it is the least-squares compromise, and the plant of
    // gain 1.3 stops short by X (1 - 1.3 (1.1 + 1.3 + 1.5) / (1.1^2 + 1.3^2 + 1.5^2)), 1.55 %
    // of the x travel, where the plan on that plant alone parks exactly. Planned once (open
    // loop), so the compromise shows whole.
    void finalPose_anEnsembleIsPlannedForAsAWhole() {
        auto demo = demonstration(120);
        auto finalX = [&](bool ensemble) {
            GainPoint plant(Eigen::Vector2d(1.3, 0.75));
            GainPoint lower(Eigen::Vector2d(1.1, 0.75));
            GainPoint higher(Eigen::Vector2d(1.5, 0.75));
            OracleParameters parameters;
            parameters.objective = OracleParameters::Objective::FinalPose;
            parameters.trialSteps = demo->length();
            parameters.replanEvery = demo->length();
            parameters.samples = 32;
            OracleController oracle(problemFor(demo, plant.info()), parameters);
            oracle.attachPlant(&plant);
            if (ensemble) {
                oracle.attachEnsemble({&lower, &higher});
            }
            plant.reset(0, Perturbation::none());
            lower.reset(0, Perturbation::none());
            higher.reset(0, Perturbation::none());
            oracle.reset();
            for (int k = 0; k < demo->length(); ++k) {
                plant.step(oracle.step(plant.state()).action);
            }
            return plant.state()[0];
        };
        const double X = demo->states(demo->length() - 1, 0);
        const double alone = finalX(false);
        const double together = finalX(true);
        const double expected = X * 1.3 * (1.1 + 1.3 + 1.5) / (1.1 * 1.1 + 1.3 * 1.3 + 1.5 * 1.5);
        QVERIFY2(std::abs(alone - X) < 1e-3 * X, qPrintable(QString::number(alone)));
        QVERIFY2(std::abs(together - expected) < 2e-3 * X,
                 qPrintable(QStringLiteral("%1 expected %2").arg(together).arg(expected)));
    }

    // A long demonstration: the plan tracks until the end is within finalPoseWindow, then aims
    // at the final pose, so the work per control step does not grow with the length (it did:
    // every plan simulated to the trial's end), and it still parks.
    void finalPose_onALongDemonstrationCostsTheSamePerStep() {
        auto perStep = [](int T, double* miss) {
            auto demo = demonstration(T);
            GainPoint plant(Eigen::Vector2d(1.3, 0.75));
            OracleParameters parameters;
            parameters.objective = OracleParameters::Objective::FinalPose;
            parameters.trialSteps = demo->length();
            parameters.finalPoseWindow = 100;
            OracleController oracle(problemFor(demo, plant.info()), parameters);
            EpisodeSettings episode;
            episode.duration = demo->length() * demo->dt;
            const EpisodeResult result = runEpisode(plant, oracle, episode);
            const Eigen::Vector2d lot = demo->states.row(demo->length() - 1).head<2>().transpose();
            *miss = (result.finalState.head<2>() - lot).norm();
            return static_cast<double>(oracle.simulatedSteps()) / demo->length();
        };
        double shortMiss = 0.0, longMiss = 0.0;
        const double shortCost = perStep(400, &shortMiss);
        const double longCost = perStep(3200, &longMiss);
        QVERIFY2(
            longCost < 1.5 * shortCost,
            qPrintable(
                QStringLiteral("%1 vs %2 simulated steps per step").arg(longCost).arg(shortCost)));
        QVERIFY2(longMiss < 1e-2, qPrintable(QString::number(longMiss)));
    }

    void tracking_followsTheTimedPathOfAPlantWithWrongGains() {
        auto demo = demonstration(160);
        GainPoint plant(Eigen::Vector2d(0.8, 1.25));
        OracleParameters parameters;
        parameters.objective = OracleParameters::Objective::Tracking;
        parameters.horizon = 20;
        parameters.knotSpacing = 5;
        parameters.replanEvery = 2;
        parameters.samples = 32;
        OracleController oracle(problemFor(demo, plant.info()), parameters);
        EpisodeSettings episode;
        episode.duration = demo->length() * demo->dt;
        const EpisodeResult result = runEpisode(plant, oracle, episode);
        const TrialSummary summary = summarizeTrial(plant.info(), *demo, result);
        // Open loop, the point drifts off by tens of centimetres; the optimum tracks exactly.
        QVERIFY2(summary.trackingRms < 0.01, qPrintable(QString::number(summary.trackingRms)));
    }

    void slideCar_nominalTrialIsTheDemonstrationExactly() {
        // No perturbation and no noise: the demonstration's own actions are optimal, and the
        // oracle must not move away from them.
        auto demo = std::make_shared<core::Demonstration>(
            PlantCatalog::demonstrate(QStringLiteral("slidecar"), 3));
        const MethodTuning profile = PlantCatalog::tuning(PlantCatalog::describe("slidecar"));
        auto oracle = MethodCatalog::create(QStringLiteral("oracle"), profile, demo,
                                            Eigen::MatrixXd::Zero(2, 6));
        auto plant = PlantCatalog::create(QStringLiteral("slidecar"));
        EpisodeSettings episode = profile.episode(*demo, 0.0, 0.0);
        const EpisodeResult result = runEpisode(*plant, *oracle, episode);
        const TrialSummary summary = summarizeTrial(plant->info(), *demo, result);
        QVERIFY2(summary.finalPositionError < 1e-3,
                 qPrintable(QString::number(summary.finalPositionError)));
    }

    void step_withoutAPlantIsRefused() {
        auto demo = demonstration(20);
        GainPoint plant(Eigen::Vector2d(1.0, 1.0));
        OracleController oracle(problemFor(demo, plant.info()), OracleParameters{});
        QVERIFY_THROWS_EXCEPTION(std::logic_error, oracle.step(Eigen::VectorXd::Zero(3)));
    }
};

QTEST_APPLESS_MAIN(TestOracle)
#include "test_oracle.moc"
