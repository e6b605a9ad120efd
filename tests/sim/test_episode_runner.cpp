// The closed loop: measurement model, episode runner, parallel trials, the controller factory.
#include "core/ActionMapping.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/demonstrations/SlideCarDemonstrator.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/episodes/ParallelTrials.h"
#include "sim/episodes/TrialMetrics.h"
#include "sim/plants/MeasurementModel.h"
#include "sim/plants/SlideCar.h"
#include "sim/tuning/MethodTuning.h"

#include <QtTest>

#include <atomic>
#include <cmath>
#include <cstring>

using namespace prisca;
using namespace prisca::sim;

namespace {

bool identical(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

struct SlideCarSetup {
    std::shared_ptr<const core::Demonstration> demo =
        std::make_shared<core::Demonstration>(SlideCarDemonstrator::record(1));
    MethodTuning profile = PlantCatalog::tuning(SlideCar::describe());
    Eigen::MatrixXd fittedB =
        core::fitActionMapping(*demo, profile.mapping, profile.info.deviationModel()).b;

    EpisodeSettings settings(std::uint64_t seed) const {
        EpisodeSettings s;
        s.seed = seed;
        s.perturbation = Perturbation::realistic();
        s.measurement = profile.measurement;
        s.duration = demo->length() * demo->dt + profile.settleTime;
        s.stopAtRestAfter = demo->length() * demo->dt;
        return s;
    }
};

// Full throttle, full left, whatever it sees; its deviation is the pose itself (a demonstration
// that stands at the origin). Counts its steps.
class Runaway : public core::Controller {
  public:
    QString name() const override { return QStringLiteral("runaway"); }
    void reset(core::ResetMode) override { steps = 0; }
    const core::ControlStep& step(const Eigen::Ref<const Eigen::VectorXd>& observation) override {
        record.step = steps++;
        record.action = Eigen::Vector2d(1.0, 1.0);
        record.referenceAction = Eigen::Vector2d::Zero();
        record.deviation = observation;
        return record;
    }
    std::unique_ptr<core::Controller> clone() const override {
        return std::make_unique<Runaway>(*this);
    }
    core::ControlStep record;
    int steps = 0;
};

}  // namespace

class TestEpisodeRunner : public QObject {
    Q_OBJECT
  private slots:
    void measurement_delaysByItsLatency() {
        MeasurementParameters p;
        p.loopLatencySteps = 3;
        MeasurementModel sensor(p, 1);
        sensor.reset(Eigen::VectorXd::Constant(1, -1.0));
        for (int k = 0; k < 10; ++k) {
            const double seen = sensor.observe(Eigen::VectorXd::Constant(1, k))[0];
            QCOMPARE(seen, k < 3 ? -1.0 : double(k - 3));
        }
    }

    void measurement_dropsHoldTheLastSampleAtTheGivenRate() {
        MeasurementParameters p;
        p.dropProbability = 0.2;
        MeasurementModel sensor(p, 2);
        sensor.reset(Eigen::VectorXd::Zero(1));
        int drops = 0;
        double previous = 0.0;
        for (int k = 1; k <= 20000; ++k) {
            const double seen = sensor.observe(Eigen::VectorXd::Constant(1, k))[0];
            if (sensor.lastDropped()) {
                ++drops;
                QCOMPARE(seen, previous);
            } else {
                QCOMPARE(seen, double(k));
            }
            previous = seen;
        }
        QVERIFY2(std::abs(drops / 20000.0 - 0.2) < 0.01, qPrintable(QString::number(drops)));
    }

    void measurement_noiseHasTheGivenSpread() {
        MeasurementParameters p;
        p.noise = Eigen::Vector2d(0.5, 0.0);
        MeasurementModel sensor(p, 3);
        sensor.reset(Eigen::Vector2d::Zero());
        double sum = 0, sumSquares = 0;
        const int N = 40000;
        for (int k = 0; k < N; ++k) {
            const Eigen::VectorXd seen = sensor.observe(Eigen::Vector2d(1.0, 2.0));
            sum += seen[0] - 1.0;
            sumSquares += (seen[0] - 1.0) * (seen[0] - 1.0);
            QCOMPARE(seen[1], 2.0);
        }
        QVERIFY(std::abs(sum / N) < 0.01);
        QVERIFY(std::abs(std::sqrt(sumSquares / N) - 0.5) < 0.01);
        MeasurementParameters bad;
        bad.dropProbability = 1.0;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, MeasurementModel(bad, 1));
    }

    void episode_sameSeedSameTrialBitForBit() {
        const SlideCarSetup setup;
        auto run = [&](std::uint64_t seed) {
            SlideCar car;
            auto controller =
                MethodCatalog::create("prisca", setup.profile, setup.demo, setup.fittedB);
            return runEpisode(car, *controller, setup.settings(seed));
        };
        const EpisodeResult a = run(7), b = run(7), c = run(8);
        QVERIFY(a.stepCount > 100);
        QCOMPARE(a.stepCount, b.stepCount);
        QCOMPARE(static_cast<int>(a.steps.size()), a.stepCount);
        for (int k = 0; k < a.stepCount; ++k) {
            QVERIFY(identical(a.steps[k].state, b.steps[k].state));
            QVERIFY(identical(a.steps[k].action, b.steps[k].action));
            QVERIFY(identical(a.steps[k].parameters, b.steps[k].parameters));
        }
        QVERIFY(identical(a.finalState, b.finalState));
        QVERIFY(!identical(a.finalState, c.finalState));
        // The record carries what the operator plots: theta (p x m flattened) and the reference.
        const auto& features = setup.profile.priscaFeatures.value_or(setup.profile.features);
        QCOMPARE(a.steps.back().parameters.size(), features.featureCount() * 2);
        QVERIFY(a.steps.back().referenceIndex > 0);
    }

    void stepper_stepByStepIsTheSameTrialAsRunEpisode() {
        const SlideCarSetup setup;
        SlideCar car;
        auto controller = MethodCatalog::create("prisca", setup.profile, setup.demo, setup.fittedB);
        const EpisodeResult whole = runEpisode(car, *controller, setup.settings(5));
        EpisodeSettings settings = setup.settings(5);
        settings.recordSteps = false;  // the live view keeps its own copy of each step
        EpisodeStepper stepper(car, *controller, settings);
        int k = 0;
        while (!stepper.finished()) {
            const StepRecord& record = stepper.step();
            QVERIFY(k < whole.stepCount);
            QVERIFY(identical(record.state, whole.steps[k].state));
            QVERIFY(identical(record.action, whole.steps[k].action));
            QCOMPARE(record.referenceIndex, whole.steps[k].referenceIndex);
            ++k;
        }
        QCOMPARE(k, whole.stepCount);
        QCOMPARE(stepper.stepCount(), whole.stepCount);
        const EpisodeResult stepped = stepper.result();
        QVERIFY(stepped.steps.empty());
        QVERIFY(identical(stepped.finalState, whole.finalState));
        QCOMPARE(stepped.meanCost, whole.meanCost);
    }

    // A rig's measured loop latency replaces the sensor's and follows the same rule: the
    // controller compensates it where the tuning says so, never while the pose filter predicts
    // across it (the filter then predicts by the measured latency).
    void measuredLatency_oneRuleForTheCompensation() {
        const SlideCarSetup setup;
        const double dt = setup.demo->dt;
        EpisodeSettings base = setup.profile.episode(*setup.demo, 1.0, 1.0);
        QVERIFY(base.compensateLoopLatency);
        QVERIFY(base.measurement.loopLatencySteps != 5);
        const EpisodeSettings none = withLoopLatency(base, std::nullopt, dt);
        QCOMPARE(none.measurement.loopLatencySteps, base.measurement.loopLatencySteps);
        QCOMPARE(none.compensatedLoopLatencySteps(), base.compensatedLoopLatencySteps());
        const EpisodeSettings measured = withLoopLatency(base, 5.2 * dt, dt);
        QCOMPARE(measured.measurement.loopLatencySteps, 5);
        QCOMPARE(measured.compensatedLoopLatencySteps(), 5);
        // The tuning's switch off: told 0, measured or not.
        EpisodeSettings off = base;
        off.compensateLoopLatency = false;
        QCOMPARE(withLoopLatency(off, 5.2 * dt, dt).compensatedLoopLatencySteps(), 0);
        // The filter predicting: the controller is told 0, the filter's latency is the measured.
        EpisodeSettings filtered = base;
        filtered.poseFilter = true;
        filtered.poseFilterPredicts = true;
        const EpisodeSettings predicted = withLoopLatency(filtered, 5.2 * dt, dt);
        QCOMPARE(predicted.compensatedLoopLatencySteps(), 0);
        QCOMPARE(predicted.measurement.loopLatencySteps, 5);
        filtered.poseFilterPredicts = false;
        QCOMPARE(withLoopLatency(filtered, 5.2 * dt, dt).compensatedLoopLatencySteps(), 5);
        // Bounded, and a measurement that is not a number changes nothing.
        QCOMPARE(withLoopLatency(base, 100.0, dt).measurement.loopLatencySteps, 40);
        QCOMPARE(withLoopLatency(base, -1.0, dt).measurement.loopLatencySteps, 0);
        QCOMPARE(withLoopLatency(base, std::nan(""), dt).measurement.loopLatencySteps,
                 base.measurement.loopLatencySteps);
    }

    void poseFilter_controllerSeesTheEstimateOfNow() {
        // The profile's episode carries the filter's parameters (the sensor's noise and latency,
        // densities from the demonstration); off by default. On, the controller is told latency
        // 0 and sees the estimate predicted to now: closer to the true state of now than the
        // raw observation, which is a step late.
        const SlideCarSetup setup;
        EpisodeSettings off = setup.profile.episode(*setup.demo, 1.0, 1.0);
        off.seed = 3;
        QVERIFY(!off.poseFilter);
        QCOMPARE(off.compensatedLoopLatencySteps(), setup.profile.measurement.loopLatencySteps);
        QVERIFY(off.compensatedLoopLatencySteps() > 0);
        QCOMPARE(off.poseFilterParameters.loopLatencySteps,
                 setup.profile.measurement.loopLatencySteps);
        QVERIFY((off.poseFilterParameters.accelerationDensity.array() > 0.0).all());
        EpisodeSettings on = off;
        on.poseFilter = true;
        QCOMPARE(on.compensatedLoopLatencySteps(), 0);
        auto positionError = [&](const EpisodeSettings& settings) {
            SlideCar car;
            auto controller = MethodCatalog::create("pd", setup.profile, setup.demo, setup.fittedB);
            const EpisodeResult result = runEpisode(car, *controller, settings);
            double sum = 0.0;
            for (const StepRecord& step : result.steps) {
                sum += (step.observation.head<2>() - step.state.head<2>()).squaredNorm();
            }
            return std::sqrt(sum / static_cast<double>(result.steps.size()));
        };
        const double raw = positionError(off), filtered = positionError(on);
        qInfo(
            "observation's position RMS error against the true state of now: raw %g m, "
            "filtered %g m",
            raw, filtered);
        QVERIFY2(filtered < 0.5 * raw, qPrintable(QStringLiteral("%1 %2").arg(filtered).arg(raw)));
        // Lagged: the estimate of the measurement's time, the controller compensating the latency
        // as without the filter; closer to the delayed true state than the raw observation.
        EpisodeSettings lagged = on;
        lagged.poseFilterPredicts = false;
        QCOMPARE(lagged.compensatedLoopLatencySteps(), setup.profile.measurement.loopLatencySteps);
        {
            SlideCar car;
            auto controller = MethodCatalog::create("pd", setup.profile, setup.demo, setup.fittedB);
            const EpisodeResult result = runEpisode(car, *controller, lagged);
            const int d = lagged.measurement.loopLatencySteps;
            double filteredThen = 0.0, rawNoise = 0.0;
            for (std::size_t k = d; k < result.steps.size(); ++k) {
                filteredThen +=
                    (result.steps[k].observation.head<2>() - result.steps[k - d].state.head<2>())
                        .squaredNorm();
            }
            rawNoise = std::pow(lagged.measurement.noise[0], 2) * 2;  // per sample, x and y
            filteredThen /= static_cast<double>(result.steps.size() - d);
            QVERIFY2(filteredThen < rawNoise,
                     qPrintable(QStringLiteral("%1 %2").arg(filteredThen).arg(rawNoise)));
        }
        // Only planar vehicles have a pose to filter.
        PlantInfo arm;
        arm.name = QStringLiteral("acrobot");
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 poseFilterFor(arm, MeasurementParameters{}, 0.025));
    }

    void episode_stopsAtRestAfterTheDemonstrationAndOnCancel() {
        const SlideCarSetup setup;
        SlideCar car;
        auto playback = MethodCatalog::create("playback", setup.profile, setup.demo, setup.fittedB);
        EpisodeSettings s = setup.settings(3);
        s.duration = 60.0;
        const EpisodeResult rested = runEpisode(car, *playback, s);
        QVERIFY(rested.duration < 20.0);
        QVERIFY(rested.duration >= s.stopAtRestAfter);
        QVERIFY(car.atRest());
        int polls = 0;
        const EpisodeResult cancelled = runEpisode(car, *playback, s, [&] { return ++polls > 10; });
        QVERIFY(cancelled.cancelled);
        QCOMPARE(cancelled.stepCount, 10);
    }

    // A car still moving when the duration ends runs out in neutral, the controller no longer
    // asked, and is scored where it rests; without a run-out it ends where the duration left it.
    void runOut_scoresTheCarWhereItRests() {
        const SlideCarSetup setup;
        EpisodeSettings s = setup.settings(5);
        s.duration = 1.0;  // full throttle to the end: moving at metres a second
        s.stopAtRestAfter = -1.0;
        SlideCar moving;
        Runaway first;
        const EpisodeResult cut = runEpisode(moving, first, s);
        QCOMPARE(cut.stepCount, 40);
        QCOMPARE(cut.runOutSeconds, 0.0);
        QVERIFY(!moving.atRest());
        s.runOutLimit = 10.0;
        SlideCar coasting;
        Runaway second;
        const EpisodeResult out = runEpisode(coasting, second, s);
        QVERIFY(coasting.atRest());
        QCOMPARE(second.steps, 40);  // the controller was not asked after the duration
        QVERIFY2(out.stepCount > 40 && out.stepCount < 40 + 400,
                 qPrintable(QString::number(out.stepCount)));
        QCOMPARE(out.runOutSeconds, (out.stepCount - 40) * 0.025);
        // The summary carries it to what the operator reads ("ran out 1.2 s in neutral").
        QCOMPARE(summarizeTrial(SlideCar::describe(), *setup.demo, out).runOutSeconds,
                 out.runOutSeconds);
        QCOMPARE(static_cast<int>(out.steps.size()), out.stepCount);
        for (size_t k = 40; k < out.steps.size(); ++k) {
            QVERIFY(out.steps[k].action.isZero());
        }
        QVERIFY(identical(out.steps[39].action, cut.steps[39].action));
        const core::PlanarPoseIndices at = *SlideCar::describe().pose;
        QVERIFY2(std::hypot(out.finalState[at.x] - cut.finalState[at.x],
                            out.finalState[at.y] - cut.finalState[at.y]) > 0.1,
                 "the car coasted on");
        // A run-out shorter than the coast: it ends there, still moving.
        s.runOutLimit = 0.1;
        SlideCar shortOut;
        Runaway third;
        QCOMPARE(runEpisode(shortOut, third, s).stepCount, 44);
        QVERIFY(!shortOut.atRest());
    }

    void lostTrack_endsTheTrialInFailsafe() {
        SlideCarSetup setup;
        for (const double distance : {0.0, 0.5}) {
            SlideCar car;
            Runaway controller;
            EpisodeSettings settings = setup.settings(4);
            settings.lostTrackDistance = distance;
            const EpisodeResult r = runEpisode(car, controller, settings);
            int tripped = -1;
            for (int k = 0; k < static_cast<int>(r.steps.size()) && tripped < 0; ++k) {
                if (r.steps[k].observation.head<2>().norm() > 0.5) {
                    tripped = k;
                }
            }
            QVERIFY(tripped > 0);  // full throttle leaves half a metre either way
            QCOMPARE(r.lostTrack, distance > 0.0);
            if (distance == 0.0) {
                QCOMPARE(controller.steps, r.stepCount);  // never guarded: driven to the end
                continue;
            }
            // From the step that saw it on: zero action, the controller no longer asked.
            QCOMPARE(controller.steps, tripped + 1);
            for (int k = tripped; k < static_cast<int>(r.steps.size()); ++k) {
                QVERIFY(r.steps[k].action.isZero());
            }
            QVERIFY(!r.steps[tripped - 1].action.isZero());
        }
        // A deviation that is not a number trips it too.
        core::LostTrackGuard guard(1.0, core::PlanarPoseIndices{});
        QVERIFY(!guard.check(Eigen::Vector3d(0.5, 0.5, 3.0)));
        QVERIFY(guard.check(Eigen::Vector3d(std::nan(""), 0.0, 0.0)));
        guard.reset();
        QVERIFY(!guard.tripped());
        QVERIFY(!core::LostTrackGuard(1.0, std::nullopt).check(Eigen::Vector3d(9.0, 9.0, 0.0)));
    }

    void parallelTrials_sameResultsWhateverTheThreadCount() {
        const SlideCarSetup setup;
        auto trial = [&](int i) {
            SlideCar car;
            auto controller =
                MethodCatalog::create("prisca", setup.profile, setup.demo, setup.fittedB);
            EpisodeSettings s = setup.settings(mixSeed(99, i));
            s.recordSteps = false;
            return runEpisode(car, *controller, s).finalState;
        };
        std::atomic<int> progressCalls{0};
        const auto one = runParallel<Eigen::VectorXd>(8, 1, trial);
        const auto two =
            runParallel<Eigen::VectorXd>(8, 2, trial, {}, [&](int, int) { ++progressCalls; });
        QCOMPARE(progressCalls.load(), 8);
        for (int i = 0; i < 8; ++i)
            QVERIFY(identical(one[i], two[i]));
        QVERIFY(!identical(one[0], one[1]));
    }

    void parallelTrials_cancelAndErrorsAreReported() {
        std::atomic<int> started{0};
        std::vector<bool> completed;
        const auto results = runParallel<int>(
            100, 2,
            [&](int i) {
                ++started;
                return i;
            },
            [&] { return started.load() >= 5; }, {}, &completed);
        QVERIFY(started.load() < 100);
        QCOMPARE(static_cast<int>(completed.size()), 100);
        QVERIFY(completed[0]);
        QVERIFY(!completed[99]);
        QVERIFY_THROWS_EXCEPTION(std::runtime_error, runParallel<int>(10, 2, [](int i) -> int {
                                     if (i == 4)
                                         throw std::runtime_error("trial 4 failed");
                                     return i;
                                 }));
    }

    void metrics_timeAlignedAndPathDistanceByHand() {
        // An L-shaped demonstration: (0,0) -> (1,0) -> (1,1), one sample per metre, heading 0.
        const PlantInfo info = SlideCar::describe();
        core::Demonstration demo;
        demo.dt = 0.1;
        demo.states = Eigen::MatrixXd::Zero(3, info.stateDimension());
        demo.actions = Eigen::MatrixXd::Zero(3, info.actionDimension());
        demo.states(1, info.pose->x) = 1.0;
        demo.states(2, info.pose->x) = 1.0;
        demo.states(2, info.pose->y) = 1.0;
        // Points on either side of the path, and one beyond its end.
        QCOMPARE(distanceToPath(info, demo, 0.5, 0.25), 0.25);
        QCOMPARE(distanceToPath(info, demo, 1.5, 0.5), 0.5);
        QCOMPARE(distanceToPath(info, demo, 1.0, 3.0), 2.0);
        QCOMPARE(distanceToPath(info, demo, -3.0, 4.0), 5.0);

        // A trial that follows the path one sample late: on the path all along, behind in time.
        EpisodeResult result;
        for (int k = 0; k < 3; ++k) {
            StepRecord step;
            step.state = demo.states.row(std::max(0, k - 1)).transpose();
            result.steps.push_back(step);
        }
        result.finalState = result.steps.back().state;
        const TrialSummary s = summarizeTrial(info, demo, result);
        QCOMPARE(s.pathRms, 0.0);
        // Time-aligned errors 0, 1, 1 m: RMS sqrt(2/3).
        QCOMPARE(s.trackingRms, std::sqrt(2.0 / 3.0));
        // Ends at (1, 0), the lot is (1, 1).
        QCOMPARE(s.finalPositionError, 1.0);
    }

    void factory_buildsEveryMethodForTheSlideCar() {
        const SlideCarSetup setup;
        for (const QString& method : MethodCatalog::ids()) {
            SlideCar car;
            auto controller =
                MethodCatalog::create(method, setup.profile, setup.demo, setup.fittedB);
            QCOMPARE(controller->name(), method);
            EpisodeSettings s = setup.settings(1);
            s.duration = 1.0;
            const EpisodeResult r = runEpisode(car, *controller, s);
            QCOMPARE(r.stepCount, 40);
            QVERIFY(r.finalState.allFinite());
        }
        QVERIFY_THROWS_EXCEPTION(
            std::invalid_argument,
            MethodCatalog::create("bogus", setup.profile, setup.demo, setup.fittedB));
    }
};

QTEST_APPLESS_MAIN(TestEpisodeRunner)
#include "test_episode_runner.moc"
