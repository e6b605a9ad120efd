// Model-predictive parking: it parks the slide-car through a model that is right, falls back to
// its feedback law under a model that is wrong (the predicted tube) or fits badly, refits after
// each trial, and goes back to its first model on a cold reset.
#include "core/ActionMapping.h"
#include "sim/DemonstrationStyles.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/episodes/TrialMetrics.h"
#include "sim/planning/Identification.h"
#include "sim/planning/MpcController.h"
#include "sim/plants/PlantParameters.h"
#include "sim/tuning/MethodTuning.h"

#include <QtTest>

#include <cmath>

using namespace prisca;
using namespace prisca::sim;

namespace {

PlantParameters withValues(PlantParameters p,
                           const std::vector<std::pair<const char*, double>>& v) {
    const auto& specs = plantParameterSpecs(p.plant);
    for (const auto& [key, value] : v) {
        for (size_t i = 0; i < specs.size(); ++i) {
            if (specs[i].key == QLatin1String(key)) {
                p.values[i] = value;
            }
        }
    }
    return p;
}

struct Setup {
    std::shared_ptr<const core::Demonstration> demonstration =
        std::make_shared<core::Demonstration>(PlantCatalog::demonstrate("slidecar", 1));
    MethodTuning profile = [] {
        MethodTuning p = PlantCatalog::tuning(PlantCatalog::describe("slidecar"));
        // The tests are of the plan: mpc.plan-slide's bound off here (this demonstration slides
        // at about 1.0 m/s), which smallSlide_... tests on its own.
        p.mpc.planSlide = 0.0;
        return p;
    }();
    // The catalog car given as the model, with a plan-fit bound no model meets: the start law
    // drives every trial from its start.
    void noModelFitsWellEnough() {
        profile.mpc.planFit = 1e-6;
        profile.mpcModel =
            std::make_shared<const PlantParameters>(defaultPlantParameters("slidecar"));
    }
    Eigen::MatrixXd b() const {
        return core::fitActionMapping(*demonstration, profile.mapping,
                                      profile.info.deviationModel())
            .b;
    }
    std::unique_ptr<MpcController> mpc() const {
        auto controller = MethodCatalog::create("mpc", profile, demonstration, b());
        auto* mpc = dynamic_cast<MpcController*>(controller.get());
        if (!mpc) {
            return nullptr;
        }
        controller.release();
        return std::unique_ptr<MpcController>(mpc);
    }
    // One trial (seed 11, no perturbation) of `mpc` with PD+LSD stepped beside it on the same
    // observations: per step, what mpc sent, what the law would have sent, and what was seen.
    struct Beside {
        Eigen::VectorXd sent, law, observation;
    };
    std::vector<Beside> besideTheLaw(MpcController& mpc) const {
        auto law = MethodCatalog::create("pd-lsd", profile, demonstration, b());
        auto plant = PlantCatalog::create("slidecar");
        EpisodeSettings s = profile.episode(*demonstration, 0.0, 0.0);
        s.seed = 11;
        EpisodeStepper stepper(*plant, mpc, s);
        law->reset();
        std::vector<Beside> steps;
        while (!stepper.finished()) {
            const StepRecord& taken = stepper.step();
            steps.push_back({taken.action, law->step(taken.observation).action, taken.observation});
        }
        return steps;
    }
    // One trial of the catalog car (or `car`) at these levels; the parking error [m].
    double trial(core::Controller& controller, std::uint64_t seed, double level,
                 core::ResetMode reset = core::ResetMode::Cold,
                 const PlantParameters* car = nullptr,
                 std::vector<StepRecord>* steps = nullptr) const {
        auto plant = car ? PlantCatalog::create(*car) : PlantCatalog::create("slidecar");
        EpisodeSettings s = profile.episode(*demonstration, level, level);
        s.seed = seed;
        s.resetMode = reset;
        s.recordSteps = steps != nullptr;
        const EpisodeResult r = runEpisode(*plant, controller, s);
        if (steps) {
            *steps = r.steps;
        }
        const core::PlanarPoseIndices pose = *profile.info.pose;
        return parkingError(profile.info, *demonstration, r.finalState[pose.x],
                            r.finalState[pose.y], r.finalState[pose.heading])
            .position;
    }
};

}  // namespace

class TestMpc : public QObject {
    Q_OBJECT
  private slots:
    // Through the car's own model, from perfect measurements, it parks on the lot and never
    // leaves its tube.
    void rightModel_parksOnTheLot() {
        Setup setup;
        setup.profile.mpcModel =
            std::make_shared<const PlantParameters>(defaultPlantParameters("slidecar"));
        auto mpc = setup.mpc();
        QVERIFY(mpc);
        const double error = setup.trial(*mpc, 11, 0.0);
        QVERIFY2(mpc->mode() != MpcMode::Fallback, qPrintable(mpc->fallbackReason()));
        QVERIFY2(mpc->fallbackReason().isEmpty(), qPrintable(mpc->fallbackReason()));
        // The operator is told which law drove (the rig's result line, run's report).
        QVERIFY2(mpc->trialNote().startsWith(QLatin1String("planned through the model")),
                 qPrintable(mpc->trialNote()));
        QVERIFY2(error < 0.02, qPrintable(QString::number(error)));
        // With the realistic perturbation and sensor the measurements stay inside the tube too.
        for (std::uint64_t seed : {3, 4}) {
            setup.trial(*mpc, seed, 1.0);
            QVERIFY2(mpc->mode() != MpcMode::Fallback, qPrintable(mpc->fallbackReason()));
        }
    }

    // A deliberately wrong model (half the grip, a third of the motor): the measured pose leaves
    // the predicted tube and the feedback law finishes the trial; the right model does not.
    void wrongModel_theFallbackTakesOver() {
        Setup setup;
        setup.profile.mpc.planFit = 100.0;  // only the tube may call the fallback here
        setup.profile.mpc.refit = true;     // and no refit after the trial it finished
        setup.profile.mpcModel = std::make_shared<const PlantParameters>(
            withValues(defaultPlantParameters("slidecar"), {{"staticFriction", 0.3},
                                                            {"kineticFriction", 0.2},
                                                            {"maxDriveForce", 3.0},
                                                            {"topSpeed", 3.0}}));
        auto mpc = setup.mpc();
        setup.trial(*mpc, 11, 0.0);
        QCOMPARE(mpc->mode(), MpcMode::Fallback);
        QVERIFY2(mpc->fallbackReason().contains(QLatin1String("predicted tube")),
                 qPrintable(mpc->fallbackReason()));
        QVERIFY(mpc->fallbackStep() * setup.demonstration->dt >= setup.profile.mpc.tubeSeconds);
        QVERIFY(mpc->fallbackStep() < setup.demonstration->length());
        const QString note = mpc->trialNote();
        QVERIFY2(note.startsWith(QLatin1String("the feedback law drove from ")) &&
                     note.endsWith(mpc->fallbackReason()),
                 qPrintable(note));
        // A trial the fallback finished is no data for the model: no refit after it.
        setup.trial(*mpc, 12, 0.0, core::ResetMode::WarmStart);
        QCOMPARE(mpc->refits(), 0);

        // From the step it took over, its actions are the feedback law's own.
        auto again = setup.mpc();
        const auto steps = setup.besideTheLaw(*again);
        QCOMPARE(again->mode(), MpcMode::Fallback);
        const int from = again->fallbackStep() + 1;
        QVERIFY(from > 0 && from < static_cast<int>(steps.size()) - 10);
        for (size_t k = static_cast<size_t>(from); k < steps.size(); ++k) {
            QVERIFY((steps[k].sent - steps[k].law).norm() < 1e-12);
        }
    }

    // While the car parks, the model's rolling resistance follows what the model failed to
    // predict: a model with a third of the car's rolling resistance (and everything else right)
    // is corrected towards the car's, and parks closer than without the correction; with the
    // gain at 0 nothing is corrected.
    void rollingBias_followsTheCarWhileItParks() {
        Setup setup;
        const PlantParameters car = defaultPlantParameters("slidecar");
        const double rolling = car.value(QStringLiteral("rollingResistance"));
        setup.profile.mpcModel = std::make_shared<const PlantParameters>(
            withValues(car, {{"rollingResistance", rolling / 3.0}}));
        setup.profile.mpc.planFit = 1.0;       // planned through however it fits
        setup.profile.mpc.parkingSpeed = 0.0;  // and the plan parks it: no hand-over
        setup.profile.mpc.rollingBiasGain = 0.0;
        auto off = setup.mpc();
        const double uncorrected = setup.trial(*off, 11, 0.0);
        QCOMPARE(off->rollingCorrection(), 0.0);
        setup.profile.mpc.rollingBiasGain = 0.1;
        auto on = setup.mpc();
        const double corrected = setup.trial(*on, 11, 0.0);
        QCOMPARE(on->mode(), MpcMode::Planning);
        const double gap = rolling - rolling / 3.0;
        QVERIFY2(
            on->rollingCorrection() > 0.3 * gap && on->rollingCorrection() < 1.5 * gap,
            qPrintable(QStringLiteral("%1 for a gap of %2").arg(on->rollingCorrection()).arg(gap)));
        QVERIFY2(corrected < uncorrected,
                 qPrintable(QStringLiteral("%1 against %2").arg(corrected).arg(uncorrected)));
    }

    // On the way into the slide the model's steering offset follows a trim the car has and the
    // model has not (mpc.steer-bias), either way; with the gain 0 it stays 0.
    void steeringBias_followsTheCarsTrimOnTheStraight() {
        Setup setup;
        setup.profile.mpcModel =
            std::make_shared<const PlantParameters>(defaultPlantParameters("slidecar"));
        setup.profile.mpc.planFit = 1.0;  // planned through however it fits
        const auto trimmed = [&](MpcController& mpc, double trim) {
            auto plant = PlantCatalog::create("slidecar");
            QVERIFY(plant->setSteeringOffset(trim));  // the car's own trim
            EpisodeSettings s = setup.profile.episode(*setup.demonstration, 0.0, 0.0);
            s.seed = 11;
            s.recordSteps = false;
            runEpisode(*plant, mpc, s);
        };
        for (const double trim : {0.04, -0.04}) {
            setup.profile.mpc.steeringBiasGain = 0.1;
            auto on = setup.mpc();
            trimmed(*on, trim);
            QVERIFY2(std::abs(on->steeringBias() - trim) < 0.5 * std::abs(trim),
                     qPrintable(
                         QStringLiteral("%1 for a trim of %2").arg(on->steeringBias()).arg(trim)));
            setup.profile.mpc.steeringBiasGain = 0.0;
            auto off = setup.mpc();
            trimmed(*off, trim);
            QCOMPARE(off->steeringBias(), 0.0);
        }
        // A copy keeps it; a cold reset forgets it.
        setup.profile.mpc.steeringBiasGain = 0.1;
        auto mpc = setup.mpc();
        trimmed(*mpc, 0.04);
        QVERIFY(mpc->steeringBias() != 0.0);
        const auto copy = mpc->clone();
        QCOMPARE(dynamic_cast<const MpcController&>(*copy).steeringBias(), mpc->steeringBias());
        mpc->reset(core::ResetMode::Cold);
        QCOMPARE(mpc->steeringBias(), 0.0);
    }

    // The spin guard: on the way into the slide, a measured side slip far from every one the
    // demonstration had near that time hands the trial to the fallback law; the same slip
    // past the demonstration's fastest turn, or with the guard off, does not.
    void spinGuard_onTheWayIn_only() {
        Setup setup;
        setup.profile.mpcModel =
            std::make_shared<const PlantParameters>(defaultPlantParameters("slidecar"));
        const core::Demonstration& demo = *setup.demonstration;
        int peak = 0;
        for (int j = 0; j < demo.length(); ++j) {
            if (std::abs(demo.states(j, 5)) > std::abs(demo.states(peak, 5))) {
                peak = j;
            }
        }
        // The demonstration's own states, but from step `from` on the car slides sideways at
        // 30 deg of side slip (the body velocity turned, its speed kept).
        const auto drive = [&](MpcController& mpc, int from, int steps) {
            mpc.reset();
            for (int k = 0; k < steps && k < demo.length(); ++k) {
                Eigen::VectorXd state = demo.states.row(k).transpose();
                if (k >= from) {
                    const double speed = std::max(2.0, std::hypot(state[3], state[4]));
                    state[3] = speed * std::cos(0.52);
                    state[4] = speed * std::sin(0.52);
                    state[5] = demo.states(k, 5);
                }
                mpc.step(state);
            }
        };
        const int before = std::max(1, peak / 2);
        QVERIFY(peak > 10);
        auto mpc = setup.mpc();
        drive(*mpc, before, before + 6);
        QCOMPARE(mpc->mode(), MpcMode::Fallback);
        QVERIFY2(mpc->fallbackReason().contains(QLatin1String("spin")) &&
                     mpc->fallbackReason().contains(QLatin1String("side-slip")),
                 qPrintable(mpc->fallbackReason()));
        QVERIFY(mpc->fallbackStep() >= before &&
                mpc->fallbackStep() < before + setup.profile.mpc.tubeStrikes + 1);

        auto late = setup.mpc();
        drive(*late, peak + 1, peak + 8);
        QVERIFY2(late->mode() == MpcMode::Planning, qPrintable(late->fallbackReason()));

        MethodCatalog::setParameter(setup.profile, QStringLiteral("mpc.spin-slip=0"));
        QCOMPARE(setup.profile.mpc.spinYawRate, 0.0);
        auto off = setup.mpc();
        drive(*off, before, before + 6);
        QVERIFY2(off->mode() == MpcMode::Planning, qPrintable(off->fallbackReason()));
        MethodCatalog::setParameter(setup.profile, QStringLiteral("mpc.spin-slip=10"));
        QVERIFY(setup.profile.mpc.spinYawRate > 0.0);
    }

    // Before the demonstration's turn the plan changes its actions by at most the bound
    // (mpc.straight); from the turn on it corrects freely. Under a wrong model, which the plan
    // corrects hard, and with the tube and the spin guard out of the way.
    void straightCorrection_boundsThePlanBeforeTheTurn() {
        Setup setup;
        setup.profile.mpc.planFit = 100.0;
        setup.profile.mpc.tubePosition = 100.0;
        setup.profile.mpc.tubeHeading = 100.0;
        MethodCatalog::setParameter(setup.profile, QStringLiteral("mpc.spin-slip=0"));
        setup.profile.mpc.parkingSpeed = 0.0;  // every action after the turn the plan's
        setup.profile.mpcModel = std::make_shared<const PlantParameters>(withValues(
            defaultPlantParameters("slidecar"),
            {{"staticFriction", 0.6}, {"kineticFriction", 0.45}, {"maxDriveForce", 5.0}}));
        const core::Demonstration& demo = *setup.demonstration;
        const Eigen::VectorXd half =
            0.5 * (setup.profile.info.actionUpper - setup.profile.info.actionLower);
        // The largest change to the demonstration's actions, share of the half range, before
        // and from the turn; whether the plan drove throughout; where the turn begins.
        struct Changes {
            double before = 0.0;
            double after = 0.0;
            bool planned = false;
            int turn = 0;
        };
        const auto largest = [&](double bound) {
            MethodCatalog::setParameter(setup.profile,
                                        QStringLiteral("mpc.straight=%1").arg(bound));
            auto mpc = setup.mpc();
            auto plant = PlantCatalog::create("slidecar");
            EpisodeSettings s = setup.profile.episode(demo, 0.0, 0.0);
            s.seed = 11;
            EpisodeStepper stepper(*plant, *mpc, s);
            Changes most;
            most.turn = mpc->turnStart();
            while (!stepper.finished()) {
                const int k = stepper.stepCount();
                const StepRecord& taken = stepper.step();
                if (k >= demo.length()) {
                    break;
                }
                const double change =
                    ((taken.action - demo.actions.row(k).transpose()).array() / half.array())
                        .abs()
                        .maxCoeff();
                double& side = k < most.turn ? most.before : most.after;
                side = std::max(side, change);
            }
            most.planned = mpc->mode() == MpcMode::Planning;
            return most;
        };
        const Changes bounded = largest(0.05);
        QVERIFY(bounded.planned);
        QVERIFY2(bounded.turn > 10 && bounded.turn < demo.length() - 10,
                 qPrintable(QString::number(bounded.turn)));
        QVERIFY2(bounded.before <= 0.05 + 1e-9, qPrintable(QString::number(bounded.before)));
        QVERIFY2(bounded.after > 0.1, qPrintable(QString::number(bounded.after)));
        const Changes free = largest(2.0);
        QVERIFY(free.planned);
        QVERIFY2(free.before > 0.1, qPrintable(QString::number(free.before)));
    }

    // Past the demonstration's fastest turn, once the car is slower than mpc.park-speed, the
    // feedback law (PD+LSD) parks it: from that step on the actions are the law's own, the
    // trial note says so, and it is no fallback (the trial stays data for a refit). With
    // mpc.park-near, not before the car is that near the lot. With the hand-over off the plan
    // drives to the end.
    void parking_theLawParksTheCarAfterTheSlide() {
        Setup setup;
        setup.profile.mpcModel =
            std::make_shared<const PlantParameters>(defaultPlantParameters("slidecar"));
        MethodCatalog::setParameter(setup.profile, QStringLiteral("mpc.park-speed=0.5"));
        QCOMPARE(setup.profile.mpc.parkingSpeed, 0.5);
        auto mpc = setup.mpc();
        const auto steps = setup.besideTheLaw(*mpc);
        QCOMPARE(mpc->mode(), MpcMode::Parking);
        QVERIFY(mpc->fallbackReason().isEmpty());
        const int from = mpc->fallbackStep();
        QVERIFY2(from > mpc->turnStart() && from < static_cast<int>(steps.size()) - 10,
                 qPrintable(QString::number(from)));
        const core::BodyVelocityIndices v = *setup.profile.info.bodyVelocity;
        const Eigen::VectorXd& seen = steps[static_cast<size_t>(from)].observation;
        const double speedAtHandOver = std::hypot(seen[v.forward], seen[v.lateral]);
        QVERIFY2(speedAtHandOver < 0.5, qPrintable(QString::number(speedAtHandOver)));
        for (size_t k = static_cast<size_t>(from); k < steps.size(); ++k) {
            QVERIFY((steps[k].sent - steps[k].law).norm() < 1e-12);
        }
        const QString note = mpc->trialNote();
        QVERIFY2(note.startsWith(QLatin1String("planned through the model")) &&
                     note.contains(QLatin1String("the feedback law parked it from")),
                 qPrintable(note));
        // With mpc.park-near (off by default) only once the car is that near the lot.
        QCOMPARE(setup.profile.mpc.parkingDistance, 0.0);
        setup.profile.mpc.parkingDistance = 0.2;
        auto near = setup.mpc();
        const auto nearSteps = setup.besideTheLaw(*near);
        QCOMPARE(near->mode(), MpcMode::Parking);
        const core::PlanarPoseIndices p = *setup.profile.info.pose;
        auto fromLot = [&](const Eigen::VectorXd& o) {
            return parkingError(setup.profile.info, *setup.demonstration, o[p.x], o[p.y],
                                o[p.heading])
                .position;
        };
        const double nearAtHandOver =
            fromLot(nearSteps[static_cast<size_t>(near->fallbackStep())].observation);
        QVERIFY2(nearAtHandOver < 0.2, qPrintable(QString::number(nearAtHandOver)));
        // At half that distance the hand-over waits until the car is nearer still (or never).
        setup.profile.mpc.parkingDistance = 0.5 * nearAtHandOver;
        auto nearer = setup.mpc();
        const auto planned = setup.besideTheLaw(*nearer);
        QVERIFY(nearer->fallbackReason().isEmpty());
        if (nearer->mode() == MpcMode::Parking) {
            const Eigen::VectorXd& at =
                planned[static_cast<size_t>(nearer->fallbackStep())].observation;
            QVERIFY2(fromLot(at) < 0.5 * nearAtHandOver, qPrintable(QString::number(fromLot(at))));
        }
        QVERIFY(nearer->fallbackStep() != near->fallbackStep());
        setup.profile.mpc.parkingDistance = 0.0;

        setup.profile.mpc.parkingSpeed = 0.0;
        auto off = setup.mpc();
        setup.trial(*off, 11, 0.0);
        QCOMPARE(off->mode(), MpcMode::Planning);
        QCOMPARE(off->fallbackStep(), -1);
    }

    // mpc.park-approach: a car that rolls harder than the demonstration's (and the model's)
    // comes to rest short of the lot once the law parks it, the law's reference following it
    // along the path. With the approach on, after the hand-over the throttle pushes it on
    // towards the lot, the way the demonstration arrived, and it stops nearer. (A car that
    // coasts in about right gets the law's throttle unchanged:
    // parking_theLawParksTheCarAfterTheSlide, at the default 0.1 m.)
    void parkingApproach_carriesACarThatCoastsShortOn() {
        Setup setup;
        const PlantParameters model = defaultPlantParameters("slidecar");
        setup.profile.mpcModel = std::make_shared<const PlantParameters>(model);
        const PlantParameters car = withValues(
            model, {{"rollingResistance", 4.0 * model.value(QStringLiteral("rollingResistance"))}});
        QCOMPARE(setup.profile.mpc.parkingApproach, 0.1);
        setup.profile.mpc.parkingApproach = 0.0;
        const core::PlanarPoseIndices p = *setup.profile.info.pose;
        const core::Demonstration& demo = *setup.demonstration;
        const int end = demo.length() - 1;
        // How far short of the lot, along its heading the way the demonstration arrived.
        const double arrival =
            std::copysign(1.0, demo.states(end - static_cast<int>(0.5 / demo.dt),
                                           setup.profile.info.bodyVelocity->forward));
        auto shortOf = [&](const Eigen::VectorXd& s) {
            const double heading = demo.states(end, p.heading);
            return arrival * (std::cos(heading) * (demo.states(end, p.x) - s[p.x]) +
                              std::sin(heading) * (demo.states(end, p.y) - s[p.y]));
        };
        std::vector<StepRecord> off;
        auto law = setup.mpc();
        const double parkedByTheLaw = setup.trial(*law, 11, 0.0, core::ResetMode::Cold, &car, &off);
        QCOMPARE(law->mode(), MpcMode::Parking);
        const double shortByTheLaw = shortOf(off.back().state);
        QVERIFY2(shortByTheLaw > 0.08, qPrintable(QString::number(shortByTheLaw)));

        MethodCatalog::setParameter(setup.profile, QStringLiteral("mpc.park-approach=0.03"));
        QCOMPARE(setup.profile.mpc.parkingApproach, 0.03);
        std::vector<StepRecord> on;
        auto approach = setup.mpc();
        const double parked = setup.trial(*approach, 11, 0.0, core::ResetMode::Cold, &car, &on);
        QCOMPARE(approach->mode(), MpcMode::Parking);
        const double shortBy = shortOf(on.back().state);
        // Along the lot's heading it stops near it (this car also misses across: the model's
        // rolling is a quarter of its own), and no farther from the lot over all.
        QVERIFY2(std::abs(shortBy) < 0.4 * shortByTheLaw && parked < parkedByTheLaw,
                 qPrintable(QStringLiteral("%1 m short, %2 m from the lot; the law's %3, %4")
                                .arg(shortBy)
                                .arg(parked)
                                .arg(shortByTheLaw)
                                .arg(parkedByTheLaw)));
        // The push: after the hand-over, throttle the way the demonstration arrived.
        const int throttle = 0;
        QCOMPARE(demo.actionNames[throttle], QStringLiteral("throttle"));
        double pushed = 0.0;
        for (size_t k = static_cast<size_t>(approach->fallbackStep()); k < on.size(); ++k) {
            pushed = std::max(pushed, arrival * on[k].action[throttle]);
        }
        QVERIFY2(pushed > 0.05, qPrintable(QString::number(pushed)));
        QVERIFY2(approach->trialNote().contains(QLatin1String("pushed on towards the lot from")),
                 qPrintable(approach->trialNote()));
        QVERIFY2(!law->trialNote().contains(QLatin1String("pushed on")),
                 qPrintable(law->trialNote()));
    }

    // A model that fits its data worse than the bound is not planned through at all: ILC's
    // loop with its learning off drives the whole trial (not PD+LSD, the planned trials'
    // fallback).
    void poorFit_theStartLawDrivesFromTheStart() {
        Setup setup;
        setup.noModelFitsWellEnough();
        auto mpc = setup.mpc();
        QCOMPARE(mpc->mode(), MpcMode::Fallback);
        QCOMPARE(mpc->fallbackStep(), 0);
        QVERIFY2(mpc->fallbackReason().contains(QLatin1String("fits its data")),
                 qPrintable(mpc->fallbackReason()));
        QCOMPARE(mpc->trialNote(),
                 QStringLiteral("the feedback law drove: %1").arg(mpc->fallbackReason()));
        QVERIFY(mpc->modelFit() > 0.0);
        MethodTuning gentle = setup.profile;
        gentle.ilcLearningScale = 0.0;
        auto ilc = MethodCatalog::create("ilc", gentle, setup.demonstration, setup.b());
        auto lsd = MethodCatalog::create("pd-lsd", setup.profile, setup.demonstration, setup.b());
        const double byMpc = setup.trial(*mpc, 3, 1.0);
        QCOMPARE(byMpc, setup.trial(*ilc, 3, 1.0));
        QVERIFY(byMpc != setup.trial(*lsd, 3, 1.0));
        QCOMPARE(mpc->mode(), MpcMode::Fallback);
        // The trial's summary carries why (the window's Messages line says it).
        auto plant = PlantCatalog::create("slidecar");
        EpisodeSettings settings = setup.profile.episode(*setup.demonstration, 1.0, 1.0);
        settings.seed = 3;
        const EpisodeResult result = runEpisode(*plant, *mpc, settings);
        QCOMPARE(summarizeTrial(setup.profile.info, *setup.demonstration, result).controllerNote,
                 mpc->trialNote());
    }

    // A demonstration identification refuses (this one has no slide) has no model to plan
    // through: the start law, ILC's loop, drives every trial from its
    // start, and the trial note names the refusal.
    void refusedDemonstration_theStartLawDrives() {
        Setup setup;
        setup.demonstration = std::make_shared<core::Demonstration>(
            DemonstrationStyles::record("slidecar", "keyboard-90-right", 1));
        QVERIFY(identificationDataProblem("slidecar", {*setup.demonstration})
                    .startsWith(QLatin1String("no slide")));
        // Setup switches mpc's own bound off, so the refusal is identification's; by default
        // the bound would hand this demonstration to the start law first.
        QVERIFY(largestSidewaysSpeed(*setup.demonstration, setup.profile.info.bodyVelocity) <
                MpcParameters{}.planSlide);
        auto mpc = setup.mpc();
        QVERIFY(mpc);
        QCOMPARE(mpc->mode(), MpcMode::Fallback);
        QCOMPARE(mpc->fallbackStep(), 0);
        QVERIFY2(mpc->trialNote().startsWith(
                     QLatin1String("the feedback law drove: no model to plan through (no slide: ")),
                 qPrintable(mpc->trialNote()));
        auto lsd = MethodCatalog::create("pd-lsd", setup.profile, setup.demonstration, setup.b());
        MethodTuning gentle = setup.profile;
        gentle.ilcLearningScale = 0.0;
        auto ilc = MethodCatalog::create("ilc", gentle, setup.demonstration, setup.b());
        const double byMpc = setup.trial(*mpc, 3, 1.0);
        QCOMPARE(byMpc, setup.trial(*ilc, 3, 1.0));
        QVERIFY(byMpc != setup.trial(*lsd, 3, 1.0));
    }

    // The start law is ILC's loop with its learning (mpc.start-learning): on a day the model is
    // not planned through, each trial it drives learns from the ones before as ILC's own row
    // does, a cold reset forgets, and with the parameter off every trial is as the first.
    void startLaw_learnsFromTheTrialsItDrives() {
        Setup setup;
        setup.noModelFitsWellEnough();
        auto mpc = setup.mpc();
        QCOMPARE(mpc->fallbackStep(), 0);
        auto ilc = MethodCatalog::create("ilc", setup.profile, setup.demonstration, setup.b());
        const double first = setup.trial(*mpc, 3, 1.0);
        QCOMPARE(first, setup.trial(*ilc, 3, 1.0));
        const double second = setup.trial(*mpc, 3, 1.0, core::ResetMode::WarmStart);
        QCOMPARE(second, setup.trial(*ilc, 3, 1.0, core::ResetMode::WarmStart));
        QVERIFY2(second != first, "the second trial is the first's: nothing was learned");
        QCOMPARE(setup.trial(*mpc, 3, 1.0), first);

        setup.profile.mpc.startLearning = false;
        auto still = setup.mpc();
        QCOMPARE(setup.trial(*still, 3, 1.0), first);
        QCOMPARE(setup.trial(*still, 3, 1.0, core::ResetMode::WarmStart), first);
    }

    // mpc.law-choice: on a day no trial is planned through, once the start law's trials park
    // farther than mpc.plan-trust on average the next is the fallback law's (PD+LSD) from its
    // start, and from then on the one of the two with the lower mean of the day drives; the
    // start law learns only from the trials it drove. Off: the start law drives every trial.
    void lawChoice_theDaysTrialsChooseTheLawThatDrives() {
        Setup setup;
        setup.noModelFitsWellEnough();
        setup.profile.mpc.lawChoice = true;
        setup.profile.mpc.planTrust = 1e-4;  // every trial parks farther than 0.1 mm
        auto mpc = setup.mpc();
        auto ilc = MethodCatalog::create("ilc", setup.profile, setup.demonstration, setup.b());
        auto pdLsd = MethodCatalog::create("pd-lsd", setup.profile, setup.demonstration, setup.b());
        const double first = setup.trial(*mpc, 3, 1.0);
        QCOMPARE(first, setup.trial(*ilc, 3, 1.0));
        QVERIFY2(!mpc->trialNote().contains(QLatin1String("fallback law drives")),
                 qPrintable(mpc->trialNote()));

        const double second = setup.trial(*mpc, 3, 1.0, core::ResetMode::WarmStart);
        QVERIFY2(mpc->trialNote().contains(QLatin1String("the fallback law drives it from its "
                                                         "start, as the start law parked this "
                                                         "day's trial")),
                 qPrintable(mpc->trialNote()));
        QCOMPARE(second, setup.trial(*pdLsd, 3, 1.0));
        QCOMPARE(mpc->dayRecord().startLaw.size(), size_t{1});
        QVERIFY(mpc->dayRecord().fallbackLaw.empty());

        const double third = setup.trial(*mpc, 3, 1.0, core::ResetMode::WarmStart);
        const MpcDayRecord& day = mpc->dayRecord();
        QCOMPARE(day.startLaw.size(), size_t{1});
        QCOMPARE(day.fallbackLaw.size(), size_t{1});
        QVERIFY(day.planned.empty());
        QVERIFY(day.startLaw.front() != day.fallbackLaw.front());
        if (day.fallbackLaw.front() < day.startLaw.front()) {
            QVERIFY2(mpc->trialNote().contains(QLatin1String("the fallback law drives it")),
                     qPrintable(mpc->trialNote()));
            QCOMPARE(third, second);
        } else {
            QVERIFY2(!mpc->trialNote().contains(QLatin1String("fallback law drives")),
                     qPrintable(mpc->trialNote()));
            // ILC's loop has learned from its own trial only, not from PD+LSD's.
            QCOMPARE(third, setup.trial(*ilc, 3, 1.0, core::ResetMode::WarmStart));
        }

        setup.profile.mpc.lawChoice = false;
        auto alone = setup.mpc();
        setup.trial(*alone, 3, 1.0);
        setup.trial(*alone, 3, 1.0, core::ResetMode::WarmStart);
        QCOMPARE(alone->dayRecord().startLaw.size(), size_t{1});
        QVERIFY(alone->dayRecord().fallbackLaw.empty());
        QVERIFY2(!alone->trialNote().contains(QLatin1String("fallback law drives")),
                 qPrintable(alone->trialNote()));
    }

    // A demonstration whose slide is smaller than mpc.plan-slide is not planned through: no
    // model is identified for it, the start law drives every trial from its start, and the note
    // says why. Just over its largest sideways speed the bound applies to a given model too; just
    // under it the model is planned through.
    void smallSlide_theStartLawDrivesWithoutAModel() {
        Setup setup;
        const double slide =
            largestSidewaysSpeed(*setup.demonstration, setup.profile.info.bodyVelocity);
        QVERIFY2(slide > 0.5 && slide < 3.0, qPrintable(QString::number(slide)));
        setup.profile.mpc.planSlide = slide + 0.01;
        auto mpc = setup.mpc();
        QVERIFY(mpc);
        QCOMPARE(mpc->demonstrationSlide(), slide);
        QCOMPARE(mpc->mode(), MpcMode::Fallback);
        QCOMPARE(mpc->fallbackStep(), 0);
        QVERIFY(std::isnan(mpc->modelFit()));  // nothing identified
        QVERIFY2(mpc->trialNote().startsWith(
                     QStringLiteral("the feedback law drove: the demonstration slides at most %1 "
                                    "m/s sideways")
                         .arg(slide, 0, 'f', 2)),
                 qPrintable(mpc->trialNote()));
        MethodTuning gentle = setup.profile;
        gentle.ilcLearningScale = 0.0;
        auto ilc = MethodCatalog::create("ilc", gentle, setup.demonstration, setup.b());
        QCOMPARE(setup.trial(*mpc, 3, 1.0), setup.trial(*ilc, 3, 1.0));
        QCOMPARE(mpc->mode(), MpcMode::Fallback);

        setup.profile.mpcModel =
            std::make_shared<const PlantParameters>(defaultPlantParameters("slidecar"));
        QCOMPARE(setup.mpc()->mode(), MpcMode::Fallback);
        setup.profile.mpc.planSlide = slide - 0.01;
        QCOMPARE(setup.mpc()->mode(), MpcMode::Planning);
    }

    // After each trial the model is refit on the demonstration and the trials before it, and
    // kept when it predicts that trial better; a cold reset goes back to the first model. A
    // clone carries the refit model and is independent.
    void refit_afterEachTrial_coldResetForgets() {
        Setup setup;
        // A start a little off the car, so the refit has something to move.
        const PlantParameters off = withValues(defaultPlantParameters("slidecar"),
                                               {{"maxDriveForce", 8.2}, {"drivelineDrag", 0.6}});
        setup.profile.mpcModel = std::make_shared<const PlantParameters>(off);
        setup.profile.mpc.planFit = 1.0;  // planned through however it fits: trials are data
        setup.profile.mpc.refit = true;
        setup.profile.mpc.refitEvaluations = 40;  // a short search moves a start this far off
        auto mpc = setup.mpc();
        setup.trial(*mpc, 5, 1.0, core::ResetMode::Cold);
        QCOMPARE(mpc->refits(), 0);
        // Refit on the demonstration, judged on trial 5; then on it and trial 5, judged on 6.
        setup.trial(*mpc, 6, 1.0, core::ResetMode::WarmStart);
        setup.trial(*mpc, 7, 1.0, core::ResetMode::WarmStart);
        QVERIFY2(mpc->refits() >= 1, qPrintable(QString::number(mpc->refits())));
        QVERIFY(mpc->model().values != off.values);
        const int refits = mpc->refits();
        auto copy = mpc->clone();
        auto* copied = dynamic_cast<MpcController*>(copy.get());
        QVERIFY(copied);
        QCOMPARE(copied->model().values, mpc->model().values);
        mpc->reset(core::ResetMode::Cold);
        QCOMPARE(mpc->refits(), 0);
        QCOMPARE(mpc->model().values, off.values);
        QCOMPARE(copied->refits(), refits);
        // Off (the default), the trials change nothing.
        setup.profile.mpc.refit = false;
        auto fixed = setup.mpc();
        setup.trial(*fixed, 5, 1.0, core::ResetMode::Cold);
        setup.trial(*fixed, 6, 1.0, core::ResetMode::WarmStart);
        setup.trial(*fixed, 7, 1.0, core::ResetMode::WarmStart);
        QCOMPARE(fixed->refits(), 0);
        QCOMPARE(fixed->model().values, off.values);
    }

    // mpc.plan-trust: the day's trials choose who drives. A planned trial that parks farther
    // than the bound sends the next trial to the start law; after that the one with the lower
    // mean of the day drives (the plan on a tie). Each trial's measured miss is recorded for
    // whoever drove it; a copy keeps the day, a cold reset forgets it; off (0) the plan drives
    // every trial.
    void planTrust_theDaysTrialsChooseWhoDrives() {
        Setup setup;
        setup.profile.mpcModel =
            std::make_shared<const PlantParameters>(defaultPlantParameters("slidecar"));
        QCOMPARE(setup.profile.mpc.planTrust, 0.1);
        setup.profile.mpc.planTrust = 0.0;
        auto planned = [](const MpcController& c) {
            return !(c.mode() == MpcMode::Fallback && c.fallbackStep() == 0);
        };
        auto off = setup.mpc();
        for (int t = 0; t < 3; ++t) {
            setup.trial(*off, 5 + t, 1.0,
                        t == 0 ? core::ResetMode::Cold : core::ResetMode::WarmStart);
            QVERIFY(planned(*off));
        }

        // A bound no trial meets: the second trial is the start law's.
        MethodCatalog::setParameter(setup.profile, QStringLiteral("mpc.plan-trust=0.1"));
        QCOMPARE(setup.profile.mpc.planTrust, 0.001);
        auto mpc = setup.mpc();
        const double first = setup.trial(*mpc, 5, 1.0, core::ResetMode::Cold);
        QVERIFY(planned(*mpc));
        QVERIFY(mpc->dayRecord().planned.empty() && mpc->dayRecord().startLaw.empty());
        const double second = setup.trial(*mpc, 6, 1.0, core::ResetMode::WarmStart);
        QCOMPARE(mpc->dayRecord().planned.size(), size_t{1});
        QVERIFY(mpc->dayRecord().startLaw.empty());
        // The record is the measured miss: the camera's view of where the trial ended.
        QVERIFY2(std::abs(mpc->dayRecord().planned[0] - first) < 0.01,
                 qPrintable(
                     QStringLiteral("%1 against %2").arg(mpc->dayRecord().planned[0]).arg(first)));
        QVERIFY(!planned(*mpc));
        QVERIFY2(mpc->trialNote().contains(QLatin1String("more than the 0.1 cm it may")),
                 qPrintable(mpc->trialNote()));
        setup.trial(*mpc, 7, 1.0, core::ResetMode::WarmStart);
        QCOMPARE(mpc->dayRecord().startLaw.size(), size_t{1});
        QVERIFY(std::abs(mpc->dayRecord().startLaw[0] - second) < 0.01);
        const bool planWins = mpc->dayRecord().planned[0] <= mpc->dayRecord().startLaw[0];
        QCOMPARE(planned(*mpc), planWins);
        if (!planWins) {
            QVERIFY2(
                mpc->trialNote().contains(QLatin1String("the start law parked this day's trial ")),
                qPrintable(mpc->trialNote()));
        }
        auto copy = mpc->clone();
        auto* copied = dynamic_cast<MpcController*>(copy.get());
        QVERIFY(copied);
        QCOMPARE(copied->dayRecord().planned, mpc->dayRecord().planned);
        QCOMPARE(copied->dayRecord().startLaw, mpc->dayRecord().startLaw);
        mpc->reset(core::ResetMode::Cold);
        QVERIFY(mpc->dayRecord().planned.empty() && mpc->dayRecord().startLaw.empty());
        QVERIFY(planned(*mpc));

        // A bound every trial meets: the plan keeps the day.
        MethodCatalog::setParameter(setup.profile, QStringLiteral("mpc.plan-trust=500"));
        auto trusted = setup.mpc();
        for (int t = 0; t < 3; ++t) {
            setup.trial(*trusted, 5 + t, 1.0,
                        t == 0 ? core::ResetMode::Cold : core::ResetMode::WarmStart);
            QVERIFY(planned(*trusted));
        }
    }

    // Without a model it identifies one from the demonstration; a plant identification does
    // not know is refused with the reason.
    void noModel_identifiesFromTheDemonstration() {
        Setup setup;
        setup.profile.mpc.identifyEvaluations = 60;
        auto mpc = setup.mpc();
        QVERIFY(mpc);
        QVERIFY(mpc->modelFit() >= 0.0);
        QVERIFY(mpc->modelFit() < 0.05);

        const MethodTuning acrobot = PlantCatalog::tuning(PlantCatalog::describe("acrobot"));
        auto demo = std::make_shared<core::Demonstration>(PlantCatalog::demonstrate("acrobot", 1));
        try {
            MethodCatalog::create("mpc", acrobot, demo, Eigen::MatrixXd::Zero(1, 4));
            QFAIL("mpc on the acrobot was accepted");
        } catch (const std::invalid_argument& e) {
            QVERIFY2(QString::fromUtf8(e.what()).contains(QLatin1String("'acrobot'")), e.what());
        }
    }
};

QTEST_GUILESS_MAIN(TestMpc)
#include "test_mpc.moc"
