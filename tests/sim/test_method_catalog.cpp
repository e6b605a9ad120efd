// The factory builds each method as the profile and the paper say: PRISCA's paper row is
// Algorithm 1 as printed, the oracle knows the trial's length, ILC learns around the PD gains.
#include "core/ActionMapping.h"
#include "core/IlcController.h"
#include "core/PriscaController.h"
#include "sim/DemonstrationStyles.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/episodes/TrialMetrics.h"
#include "sim/planning/OracleController.h"

#include <QSet>
#include <QtTest>

using namespace prisca;
using namespace prisca::sim;

class TestMethodCatalog : public QObject {
    Q_OBJECT
  private:
    std::shared_ptr<const core::Demonstration> demo_ =
        std::make_shared<core::Demonstration>(PlantCatalog::demonstrate("slidecar", 2));
    MethodTuning profile_ = PlantCatalog::tuning(PlantCatalog::describe("slidecar"));

  private slots:
    void priscaPaper_isAlgorithm1AsPrinted() {
        auto controller =
            MethodCatalog::create("prisca-paper", profile_, demo_, Eigen::MatrixXd::Zero(2, 6));
        auto* prisca = dynamic_cast<core::PriscaController*>(controller.get());
        QVERIFY(prisca);
        QCOMPARE(prisca->name(), QStringLiteral("prisca-paper"));
        const core::PriscaParameters& p = prisca->parameters();
        QCOMPARE(p.baselineMode, core::LocalOptimalBaseline::Mode::PaperEq15);
        QVERIFY(p.useBaseline && p.useInverseDepreciation);
        QCOMPARE(p.stepSize.scale, 1.0);  // eq. 3 as printed: alpha_k = beta / (k + beta)
        QCOMPARE(p.thetaBound, 0.0);
        QCOMPARE(p.gradient, core::PriscaParameters::Gradient::OneStep);
        QCOMPARE(p.effectHorizon, 1);
        QCOMPARE(p.prior.kp.size(), 0);  // from theta = 0, no feedback to start from
        // eq. 8 read literally: the state change against the action change, unconstrained.
        core::ActionMappingFitOptions literal;
        literal.target = core::ActionMappingFitOptions::Target::StateChange;
        literal.nonNegative = false;
        literal.robust = false;
        const core::ActionMappingFit fit = core::fitActionMapping(
            *demo_, profile_.mapping, profile_.info.deviationModel(), literal);
        QVERIFY((prisca->stateEffect() - demo_->dt * fit.b).cwiseAbs().maxCoeff() < 1e-15);
    }

    void prisca_isTheProfilesVariantWithTheGivenFit() {
        const Eigen::MatrixXd B = Eigen::MatrixXd::Constant(2, 6, 0.5);
        auto controller = MethodCatalog::create("prisca", profile_, demo_, B);
        auto* prisca = dynamic_cast<core::PriscaController*>(controller.get());
        QVERIFY(prisca);
        QCOMPARE(prisca->parameters().thetaBound, profile_.prisca.thetaBound);
        // The slide-car's PRISCA starts from the PD+H+LSD law, the profile's gains and horizon.
        QVERIFY(profile_.priscaFromPd);
        QCOMPARE(prisca->parameters().prior.kp, profile_.pd.kp);
        QCOMPARE(prisca->parameters().prior.kd, profile_.pd.kd);
        QCOMPARE(prisca->parameters().prior.horizon, profile_.pdHorizon);
        QVERIFY((prisca->stateEffect() - demo_->dt * B).cwiseAbs().maxCoeff() < 1e-15);
    }

    void prisca_learnsWithoutABoundAndSettles() {
        // The product's slide-car PRISCA has no bound on theta: 100 consecutive trials on the
        // realistic plant and sensor (a tuning style, a development seed set) must all park
        // (nothing diverges), and theta must settle: the last 50 trials move it by at most a
        // fifth of where it ends.
        QCOMPARE(profile_.prisca.thetaBound, 0.0);
        auto demo = std::make_shared<const core::Demonstration>(
            DemonstrationStyles::record("slidecar", "stick-180-left", 300));
        const Eigen::MatrixXd B =
            core::fitActionMapping(*demo, profile_.mapping, profile_.info.deviationModel()).b;
        auto controller = MethodCatalog::create("prisca", profile_, demo, B);
        auto plant = PlantCatalog::create("slidecar");
        Eigen::MatrixXd middle;
        double worst = 0.0;
        for (int t = 0; t < 100; ++t) {
            EpisodeSettings e = profile_.episode(*demo, 1.0, 1.0);
            e.seed = mixSeed(300, t);
            e.recordSteps = false;
            e.resetMode = t ? core::ResetMode::WarmStart : core::ResetMode::Cold;
            const EpisodeResult r = runEpisode(*plant, *controller, e);
            QVERIFY(!r.lostTrack);
            worst = std::max(worst, summarizeTrial(plant->info(), *demo, r).finalPositionError);
            if (t == 49) {
                middle = *controller->learnedParameters();
            }
        }
        const Eigen::MatrixXd& end = *controller->learnedParameters();
        QVERIFY(end.allFinite());
        QVERIFY2(worst < 0.3, qPrintable(QString::number(worst)));
        QVERIFY2((end - middle).cwiseAbs().maxCoeff() <= 0.2 * end.cwiseAbs().maxCoeff(),
                 qPrintable(QStringLiteral("theta %1 %2 -> %3 %4")
                                .arg(middle(0, 0))
                                .arg(middle(0, 1))
                                .arg(end(0, 0))
                                .arg(end(0, 1))));
        QVERIFY(end.cwiseAbs().maxCoeff() > 0.0);  // it did learn
    }

    void automaticDefaults_comeFromTheDemonstration() {
        // A car driving straight along x at 2 m/s: over the automatic window (1 s, 40 samples at
        // 40 Hz) its longitudinal deviation is 2 m and its heading's 0. The longitudinal feature
        // is scaled to 1 / 2 m; the heading's, with nothing to measure it by, keeps its preset.
        core::Demonstration demo = *demo_;
        const int T = 200;
        demo.dt = 0.025;
        demo.time = Eigen::VectorXd::LinSpaced(T, 0.0, (T - 1) * demo.dt);
        demo.states.setZero(T, 6);
        demo.actions.setZero(T, 2);
        for (int k = 0; k < T; ++k) {
            demo.states(k, 0) = 2.0 * k * demo.dt;
            demo.states(k, 3) = 2.0;
        }
        QCOMPARE(MethodTuning::automaticWindow(demo), 40);
        const core::FeatureMap preset = MethodCatalog::featuresOf(profile_, "prisca");
        const core::FeatureMap automatic = profile_.automaticFeatures("prisca", demo);
        QCOMPARE(automatic.terms().size(), preset.terms().size());
        for (size_t l = 0; l < preset.terms().size(); ++l) {
            for (size_t i = 0; i < preset.terms()[l].size(); ++i) {
                const core::FeatureTerm& term = automatic.terms()[l][i];
                QCOMPARE(term.index, preset.terms()[l][i].index);
                const double expected = term.index == 0 ? 0.5 : preset.terms()[l][i].scale;
                QVERIFY2(std::abs(term.scale - expected) < 1e-9,
                         qPrintable(QStringLiteral("term %1: %2").arg(term.index).arg(term.scale)));
            }
        }
        demo.dt = 0.05;
        QCOMPARE(MethodTuning::automaticWindow(demo), 20);
        // The factory's PRISCA takes them when the profile asks, and the normalised step.
        QVERIFY(profile_.priscaAutomatic);
        auto shared = std::make_shared<const core::Demonstration>(*demo_);
        auto controller =
            MethodCatalog::create("prisca", profile_, shared, Eigen::MatrixXd::Constant(2, 6, 0.5));
        auto* prisca = dynamic_cast<core::PriscaController*>(controller.get());
        QVERIFY(prisca);
        QVERIFY(prisca->parameters().stepSize.normalised);
        QCOMPARE(prisca->parameters().stepSize.scale, MethodTuning::automaticStep);
        MethodTuning preset2 = profile_;
        preset2.priscaAutomatic = false;
        controller =
            MethodCatalog::create("prisca", preset2, shared, Eigen::MatrixXd::Constant(2, 6, 0.5));
        prisca = dynamic_cast<core::PriscaController*>(controller.get());
        QVERIFY(!prisca->parameters().stepSize.normalised);
        QCOMPARE(prisca->parameters().stepSize.scale, profile_.prisca.stepSize.scale);
    }

    void oracle_knowsTheTrialsLength() {
        auto controller =
            MethodCatalog::create("oracle", profile_, demo_, Eigen::MatrixXd::Zero(2, 6));
        auto* oracle = dynamic_cast<OracleController*>(controller.get());
        QVERIFY(oracle);
        const EpisodeSettings trial = profile_.episode(*demo_, 1.0, 1.0);
        QCOMPARE(oracle->parameters().trialSteps,
                 static_cast<int>(trial.duration / demo_->dt + 0.5));
        QCOMPARE(oracle->parameters().objective, OracleParameters::Objective::FinalPose);
        QCOMPARE(oracle->parameters().feedback.rows(), 2);
    }

    void ilc_learnsAroundThePdGains() {
        auto controller =
            MethodCatalog::create("ilc", profile_, demo_, Eigen::MatrixXd::Zero(2, 6));
        auto* ilc = dynamic_cast<core::IlcController*>(controller.get());
        QVERIFY(ilc);
        QCOMPARE(ilc->parameters().feedback.kp,
                 Eigen::VectorXd(profile_.pd.kp * profile_.ilcFeedbackScale));
        QCOMPARE(ilc->parameters().learningGain,
                 Eigen::VectorXd(profile_.ilcLearningScale * profile_.pd.kp));
        QCOMPARE(ilc->parameters().lead, profile_.ilcLead);
    }

    // Every parameter is declared once, and its declaration is what reads, writes, formats,
    // parses and checks it; its value lives in a field of the plant's tuning (every plant has
    // one that check() allows): on every plant, each default round-trips through the text the
    // command line and the session use.
    void parameters_areDeclaredOnceAndRoundTripOnEveryPlant() {
        QSet<QString> names;
        for (const MethodParameter* p : MethodCatalog::parameters()) {
            const QString name = QString::fromLatin1(p->name);
            QVERIFY2(!names.contains(name), qPrintable(name));
            names.insert(name);
            QVERIFY2(QString::fromUtf8(p->help).size() > 10, qPrintable(name));
            QCOMPARE(MethodCatalog::parameter(name), p);
            QVERIFY2(p->get && p->set, qPrintable(name));  // every value in a tuning's field
            for (const QString& plant : PlantCatalog::names()) {
                MethodTuning profile = PlantCatalog::tuning(PlantCatalog::describe(plant));
                const Eigen::VectorXd value = p->value(profile);
                const int m = profile.info.actionDimension();
                QVERIFY2(p->check(value, m).isEmpty(),
                         qPrintable(plant + ": " + p->check(value, m)));
                QString error;
                const auto parsed = p->parse(p->format(value), m, &error);
                QVERIFY2(parsed && parsed->isApprox(value), qPrintable(plant + ": " + error));
                MethodCatalog::setParameter(profile, name + QLatin1Char('=') + p->format(value));
                QVERIFY(p->value(profile).isApprox(value));
            }
        }
        // The same declaration where several methods share a parameter.
        const auto named = [](const MethodSpec& spec, const char* name) {
            for (const MethodParameter& p : spec.parameters) {
                if (QLatin1String(p.name) == QLatin1String(name)) {
                    return &p;
                }
            }
            return static_cast<const MethodParameter*>(nullptr);
        };
        QVERIFY(named(MethodCatalog::get("pd"), "pd.kp"));
        QCOMPARE(named(MethodCatalog::get("pd"), "pd.kp")->name,
                 named(MethodCatalog::get("ilc"), "pd.kp")->name);
        QVERIFY(!named(MethodCatalog::get("playback"), "pd.kp"));
    }

    void setParameter_changesTheProfileOrSaysWhatIsAllowed() {
        MethodTuning profile = profile_;
        MethodCatalog::setParameter(profile, "prisca.H=17");
        QCOMPARE(profile.prisca.horizon, 17);
        MethodCatalog::setParameter(profile, "pd.kp=0.5,2");
        QCOMPARE(profile.pd.kp, Eigen::Vector2d(0.5, 2.0).eval());
        MethodCatalog::setParameter(profile, "pd.kd=0.25");  // one number for every control
        QCOMPARE(profile.pd.kd, Eigen::Vector2d(0.25, 0.25).eval());
        MethodCatalog::setParameter(profile, "prisca.gradient=one-step");
        QVERIFY(profile.prisca.gradient == core::PriscaParameters::Gradient::OneStep);
        MethodCatalog::setParameter(profile, "prisca.automatic=off");
        QVERIFY(!profile.priscaAutomatic);
        // A method's own parameter with no field in the profile: kept by name.
        MethodCatalog::setParameter(profile, "lqr.terminal=3");
        QCOMPARE(MethodCatalog::value(profile, "lqr.terminal")[0], 3.0);
        const auto refused = [&](const char* assignment, const char* words) {
            try {
                MethodCatalog::setParameter(profile, QString::fromLatin1(assignment));
            } catch (const std::invalid_argument& e) {
                return QString::fromUtf8(e.what()).contains(QLatin1String(words));
            }
            return false;
        };
        QVERIFY(refused("prisca.H=0", "prisca.H: 0 is outside 1 .. 1000"));
        QVERIFY(refused("prisca.H=2.5", "outside"));
        QVERIFY(refused("prisca.gamma=nan", "outside 0 .. 1"));
        QVERIFY(refused("prisca.gradient=sideways", "one-step | closed-loop"));
        QVERIFY(refused("pd.kp=1,2,3", "pd.kp takes 2 values"));
        QVERIFY(refused("nope=1", "no method has a parameter 'nope'"));
        QVERIFY(refused("prisca.H", "is not NAME=VALUE"));
        QCOMPARE(profile.prisca.horizon, 17);  // nothing half-applied
        // Per-plant defaults: the LQR's effort is the acrobot's own.
        const MethodTuning acrobot = PlantCatalog::tuning(PlantCatalog::describe("acrobot"));
        QVERIFY(MethodCatalog::value(acrobot, "lqr.effort")[0] !=
                MethodCatalog::value(profile_, "lqr.effort")[0]);
    }

    void catalog_isOneTableEveryListComesFrom() {
        // Ids unique and labelled; every entry builds a controller that calls itself by its id.
        QSet<QString> seen, labels;
        const Eigen::MatrixXd B = Eigen::MatrixXd::Constant(2, 6, 0.5);
        for (const MethodSpec& spec : MethodCatalog::all()) {
            QVERIFY2(!seen.contains(spec.id), qPrintable(spec.id));
            seen.insert(spec.id);
            QVERIFY2(!spec.label.isEmpty() && !labels.contains(spec.label), qPrintable(spec.id));
            labels.insert(spec.label);
            QVERIFY(spec.create);
            auto controller = MethodCatalog::create(spec.id, profile_, demo_, B);
            QVERIFY(controller);
            QCOMPARE(controller->name(), spec.id);
            QCOMPARE(&MethodCatalog::get(spec.id), &spec);
        }
        // The traits the experiments read, as the paper's protocol has them.
        QCOMPARE(MethodCatalog::table1Ids(),
                 QStringList({"prisca", "prisca-paper", "pd", "pd-selected", "pd-h", "pd-lsd",
                              "pd-h-lsd", "lqr", "playback", "pgsd", "ilc", "mpc", "oracle"}));
        // mpc runs when named: it identifies a car per cell, and the slide-car only.
        QCOMPARE(MethodCatalog::defaultTable1Ids(),
                 QStringList({"prisca", "prisca-paper", "pd", "pd-selected", "pd-h", "pd-lsd",
                              "pd-h-lsd", "lqr", "playback", "pgsd", "ilc", "oracle"}));
        QVERIFY(!MethodCatalog::curveIds().contains("pd-selected"));
        QVERIFY(MethodCatalog::curveIds().contains("pegasus"));
        QStringList online, limits, own;
        for (const MethodSpec& spec : MethodCatalog::all()) {
            if (spec.learnsOnline)
                online << spec.id;
            if (spec.limit)
                limits << spec.id;
            if (spec.ownFeatures)
                own << spec.id;
        }
        QCOMPARE(online, QStringList({"prisca", "prisca-paper", "pgsd", "ilc", "mpc"}));
        QCOMPARE(limits, QStringList({"oracle"}));
        QCOMPARE(own, QStringList({"prisca", "prisca-paper"}));
        QVERIFY(MethodCatalog::get("oracle").simulationOnly);
        QCOMPARE(MethodCatalog::get("pegasus").training, MethodSpec::Training::Pegasus);
        QCOMPARE(MethodCatalog::get("pd-selected").training, MethodSpec::Training::SelectPdGains);
        QCOMPARE(MethodCatalog::find("magic"), nullptr);
    }

    void unknownMethod_namesTheKnownOnes() {
        try {
            MethodCatalog::create("magic", profile_, demo_, Eigen::MatrixXd::Zero(2, 6));
            QFAIL("no exception");
        } catch (const std::invalid_argument& e) {
            QVERIFY(QString::fromStdString(e.what()).contains("prisca-paper"));
        }
    }
};

QTEST_APPLESS_MAIN(TestMethodCatalog)
#include "test_method_catalog.moc"
