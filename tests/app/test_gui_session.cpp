// The Task and Controller panels and the session file driven offscreen: sessions saved and
// opened with their parameters, scripted demonstrations, feature scales and limits, bad files.
#include "GuiTestSupport.h"
#include "sim/PlantCatalog.h"
#include "sim/plants/SlideCar.h"
#include "sim/run/RunSetup.h"

using namespace prisca::app;
using namespace prisca::test;

class TestGuiSession : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { initGuiTestCase("test_gui_session"); }
    void init() { resetGuiState(); }

    void session_fullDiskRefusedAndThePreviousFileKept() {
        QTemporaryDir dir;
        const QString path = dir.filePath("session.json");
        QFile old(path);
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("{\"the previous session\": true}\n");
        old.close();
        LabSession session;
        session.setPlant(QStringLiteral("slidecar"));
        QString error;
        {
            const FileSizeLimit full(64);
            QVERIFY(full.active());
            QVERIFY(!session.save(path, &error));
        }
        QVERIFY2(error.contains(path), qPrintable(error));
        QVERIFY(old.open(QIODevice::ReadOnly));
        QCOMPARE(old.readAll(), QByteArray("{\"the previous session\": true}\n"));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
                 QStringList{"session.json"});
        // Hostile files are refused before they are read: a device, a FIFO.
        QVERIFY(!session.open(QStringLiteral("/dev/zero"), &error));
        QVERIFY2(error.contains("not a regular file"), qPrintable(error));
        const QByteArray fifo = QFile::encodeName(dir.filePath("fifo"));
        QCOMPARE(::mkfifo(fifo.constData(), 0600), 0);
        QVERIFY(!session.open(dir.filePath("fifo"), &error));  // would block forever if opened
        QVERIFY2(error.contains("not a regular file"), qPrintable(error));
        QCOMPARE(session.plant(), QStringLiteral("slidecar"));
    }

    void session_savedAndOpenedWithItsParameters() {
        QTemporaryDir dir;
        const QString path = dir.filePath("session.json");
        {
            Window w;
            w.find<QComboBox>("target")->setCurrentIndex(
                w.find<QComboBox>("target")->findData(QStringLiteral("aircraft")));
            // activated() is what an operator's choice emits.
            emit w.find<QComboBox>("target")->activated(
                w.find<QComboBox>("target")->currentIndex());
            QCOMPARE(w.window.session().plant(), QStringLiteral("aircraft"));
            w.find<QSpinBox>("prisca.H")->setValue(17);
            auto* method = w.find<QComboBox>("method");
            method->setCurrentIndex(method->findData(QStringLiteral("pgsd")));
            emit method->activated(method->currentIndex());
            QCOMPARE(w.window.session().method(), QStringLiteral("pgsd"));
            // The panel shows the method's own parameters, as its catalog entry declares them.
            QVERIFY(!w.find<QSpinBox>("prisca.H"));
            // An edit changes that value alone: a value finer than its box shows is kept.
            prisca::sim::MethodTuning fine = w.window.session().profile();
            prisca::sim::MethodCatalog::setParameter(fine, "pgsd.alpha=0.1234567");
            w.window.session().setProfile(fine);
            w.find<QSpinBox>("pgsd.H")->setValue(7);
            QCOMPARE(w.window.session().profile().pgsd.stepSize, 0.1234567);
            QVERIFY(w.window.saveSession(path));
        }
        Window w;
        QCOMPARE(w.window.session().plant(), QStringLiteral("aircraft"));  // remembered target
        w.find<QComboBox>("target")->setCurrentIndex(1);
        emit w.find<QComboBox>("target")->activated(1);
        QCOMPARE(w.window.session().plant(), QStringLiteral("acrobot"));
        QVERIFY(w.window.openSession(path));
        QCOMPARE(w.window.session().plant(), QStringLiteral("aircraft"));
        QCOMPARE(w.window.session().method(), QStringLiteral("pgsd"));
        QCOMPARE(w.window.session().profile().prisca.horizon, 17);
        QCOMPARE(w.window.session().profile().pgsd.horizon, 7);
        QCOMPARE(w.find<QSpinBox>("pgsd.H")->value(), 7);
        QCOMPARE(w.find<QComboBox>("target")->currentData().toString(), QStringLiteral("aircraft"));
    }

    void task_savedAsNamesTheSavedFile() {
        QTemporaryDir dir;
        Window w;
        const QString path = dir.filePath(QStringLiteral("kept.csv"));
        answerFileDialog(this, path,
                         [&] { w.find<QAbstractButton>("saveDemonstration")->click(); });
        QVERIFY(QFile::exists(path));
        QCOMPARE(w.window.session().demonstrationSource(), path);
        QVERIFY2(w.find<QLabel>("demonstrationInfo")->text().contains(QLatin1String("kept.csv")),
                 qPrintable(w.find<QLabel>("demonstrationInfo")->text()));
    }

    // A plant file loaded by the Task panel's button: shown by name, the scripted demonstration
    // recorded again on that car, the runs' plant built from it, saved with the session and
    // read back without the file; a bad file is refused by key and range, changing nothing.
    void task_plantFileLoadedShownSavedAndRefused() {
        QTemporaryDir dir;
        const QString carPath = dir.filePath("mycar.json");
        QFile car(carPath);
        QVERIFY(car.open(QIODevice::WriteOnly));
        car.write(R"({"plant": "slidecar", "parameters": {"mass": 2.3, "maxDriveForce": 7}})");
        car.close();
        const QString sessionPath = dir.filePath("with-car.json");
        {
            Window w;
            auto& session = w.window.session();
            QVERIFY(!session.plantParameters());
            QCOMPARE(w.find<QLabel>("plantFileInfo")->text(), QStringLiteral("the catalog's"));
            QVERIFY(!w.find<QAbstractButton>("clearPlantFile")->isEnabled());
            const auto demoBefore = session.demonstration();
            answerFileDialog(this, carPath,
                             [&] { w.find<QAbstractButton>("openPlantFile")->click(); });
            QVERIFY(session.plantParameters());
            QCOMPARE(session.plantParameters()->value("mass"), 2.3);
            QCOMPARE(w.find<QLabel>("plantFileInfo")->text(), QStringLiteral("mycar.json"));
            QVERIFY(w.find<QAbstractButton>("clearPlantFile")->isEnabled());
            // Nobody tuned this car: the controllers start from the demonstration.
            QCOMPARE(session.profile().start, prisca::sim::MethodTuning::Start::Demonstration);
            // The scripted operator drove the heavier car: another demonstration.
            QVERIFY(session.demonstration() != demoBefore);
            QVERIFY(session.demonstration()->states.bottomRows(1) !=
                    demoBefore->states.bottomRows(1));
            const prisca::sim::RunSetup setup(session.task(), QStringLiteral("pd"));
            auto plant = setup.makePlant();
            auto* slideCar = dynamic_cast<prisca::sim::SlideCar*>(plant.get());
            QVERIFY(slideCar);
            QCOMPARE(slideCar->parameters().mass, 2.3);
            QString error;
            QVERIFY2(session.save(sessionPath, &error), qPrintable(error));
            // A bad file: the message names the key, the value and the range.
            QFile bad(dir.filePath("bad.json"));
            QVERIFY(bad.open(QIODevice::WriteOnly));
            bad.write(R"({"plant": "slidecar", "parameters": {"wheelbase": 3}})");
            bad.close();
            const QString text = answerMessageBox(this, [&] {
                QVERIFY(!w.find<TaskPanel>("taskPanel")->openPlantParameters(bad.fileName()));
            });
            QVERIFY2(text.contains("wheelbase = 3 m is outside [0.08, 0.8] m"), qPrintable(text));
            QCOMPARE(session.plantParameters()->value("mass"), 2.3);
        }
        QVERIFY(QFile::remove(carPath));  // the session holds the values themselves
        Window w;
        QString error;
        QVERIFY2(w.window.session().open(sessionPath, &error), qPrintable(error));
        QVERIFY(w.window.session().plantParameters());
        QCOMPARE(w.window.session().plantParameters()->value("maxDriveForce"), 7.0);
        QCOMPARE(w.find<QLabel>("plantFileInfo")->text(), QStringLiteral("mycar.json"));
        QCOMPARE(w.window.session().profile().start,
                 prisca::sim::MethodTuning::Start::Demonstration);
        w.find<QAbstractButton>("clearPlantFile")->click();
        QVERIFY(!w.window.session().plantParameters());
        QCOMPARE(w.window.session().profile().start, prisca::sim::MethodTuning::Start::Tuned);
        QCOMPARE(w.find<QLabel>("plantFileInfo")->text(), QStringLiteral("the catalog's"));
    }

    void task_scriptedStyleAndSeedAreUsedShownAndSaved() {
        QTemporaryDir dir;
        const QString path = dir.filePath("styled.json");
        {
            Window w;
            auto* style = w.find<QComboBox>("demonstrationStyle");
            QCOMPARE(style->count(),
                     static_cast<int>(
                         prisca::sim::DemonstrationStyles::of(QStringLiteral("slidecar")).size()));
            QCOMPARE(style->currentData().toString(), QStringLiteral("stick-180-left"));
            style->setCurrentIndex(style->findData(QStringLiteral("keyboard-90-right")));
            w.find<QSpinBox>("demonstrationSeed")->setValue(5);
            QTest::mouseClick(w.find<QPushButton>("scriptedDemonstration"), Qt::LeftButton);
            QCOMPARE(w.window.session().scriptedStyle(), QStringLiteral("keyboard-90-right"));
            QCOMPARE(w.window.session().scriptedSeed(), std::uint64_t(5));
            const auto expected = prisca::sim::DemonstrationStyles::record(
                QStringLiteral("slidecar"), QStringLiteral("keyboard-90-right"), 5);
            QCOMPARE(w.window.session().demonstration()->actions, expected.actions);
            QVERIFY2(
                w.find<QLabel>("demonstrationInfo")->text().contains("keyboard-90-right, seed 5"),
                qPrintable(w.find<QLabel>("demonstrationInfo")->text()));
            // The ILC fields (shown with ILC chosen) apply to the session like every other
            // parameter.
            auto* method = w.find<QComboBox>("method");
            method->setCurrentIndex(method->findData(QStringLiteral("ilc")));
            emit method->activated(method->currentIndex());
            w.find<QSpinBox>("ilc.lead")->setValue(4);
            QCOMPARE(w.window.session().profile().ilcLead, 4);
            QVERIFY(w.window.saveSession(path));
        }
        Window w;
        w.find<QComboBox>("target")->setCurrentIndex(1);
        emit w.find<QComboBox>("target")->activated(1);
        QVERIFY(w.window.openSession(path));
        QCOMPARE(w.window.session().scriptedStyle(), QStringLiteral("keyboard-90-right"));
        QCOMPARE(w.window.session().scriptedSeed(), std::uint64_t(5));
        QCOMPARE(w.find<QComboBox>("demonstrationStyle")->currentData().toString(),
                 QStringLiteral("keyboard-90-right"));
        QCOMPARE(w.find<QSpinBox>("demonstrationSeed")->value(), 5);
        QCOMPARE(w.window.session().profile().ilcLead, 4);
        // A session naming a style the plant does not have is refused, naming the choices.
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QByteArray json = file.readAll();
        file.close();
        json.replace("keyboard-90-right", "moonwalk");
        QString error;
        QVERIFY(!w.window.session().fromJson(json, QStringLiteral("bad.json"), &error));
        QVERIFY2(error.contains("scriptedStyle") && error.contains("stick-180-left"),
                 qPrintable(error));
    }

    void controller_featureScalesAndLimitsAreCheckedAppliedAndSaved() {
        QTemporaryDir dir;
        const QString path = dir.filePath("limits.json");
        {
            Window w;
            // Every parameter is labelled (with the paper's symbol).
            auto* form = w.find<QWidget>("controllerPanel")->findChild<QFormLayout*>();
            QVERIFY(form);
            QStringList names = {"method"};
            for (const prisca::sim::MethodParameter& p :
                 prisca::sim::MethodCatalog::get("prisca").parameters) {
                names << QString::fromLatin1(p.name);
            }
            QVERIFY(names.size() > 10);
            for (const QString& name : names) {
                auto* label =
                    qobject_cast<QLabel*>(form->labelForField(w.window.findChild<QWidget*>(name)));
                QVERIFY2(label && !label->text().isEmpty(), qPrintable(name));
            }
            QCOMPARE(
                qobject_cast<QLabel*>(form->labelForField(w.find<QWidget>("prisca.H")))->text(),
                QStringLiteral("Horizon H:"));
            // One box per control for the PD gains, each with its control's value.
            QCOMPARE(w.find<QDoubleSpinBox>("pd.kp[1]")->value(),
                     w.window.session().profile().pd.kp[1]);
            auto* features = w.find<QTableWidget>("featureScales");
            auto* limits = w.find<QTableWidget>("actionLimits");
            auto* problem = w.find<QLabel>("controllerProblem");
            // The slide-car's PRISCA derives alpha_0 and its feature scales from the
            // demonstration: those fields are not the operator's until automatic is off.
            auto* automatic = w.find<QCheckBox>("prisca.automatic");
            QVERIFY(automatic->isChecked());
            QVERIFY(!features->isEnabled());
            QVERIFY(!w.find<QDoubleSpinBox>("prisca.alpha0")->isEnabled());
            automatic->setChecked(false);
            QVERIFY(!w.window.session().profile().priscaAutomatic);
            QVERIFY(features->isEnabled());
            QVERIFY(w.find<QDoubleSpinBox>("prisca.alpha0")->isEnabled());
            // A start from the demonstration derives the law and the scales: the PD gains and
            // alpha_0 are not the operator's then.
            auto* start = w.find<QComboBox>("start");
            QVERIFY(w.find<QDoubleSpinBox>("pd.kp[0]")->isEnabled());
            start->setCurrentIndex(1);
            emit start->activated(1);
            QVERIFY(w.window.session().profile().start ==
                    prisca::sim::MethodTuning::Start::Demonstration);
            QVERIFY(!w.find<QDoubleSpinBox>("pd.kp[0]")->isEnabled());
            QVERIFY(!w.find<QDoubleSpinBox>("prisca.alpha0")->isEnabled());
            QVERIFY(!features->isEnabled());
            start->setCurrentIndex(0);
            emit start->activated(0);
            QVERIFY(w.window.session().profile().start == prisca::sim::MethodTuning::Start::Tuned);
            QVERIFY(w.find<QDoubleSpinBox>("pd.kp[0]")->isEnabled());
            QVERIFY(w.find<QDoubleSpinBox>("prisca.alpha0")->isEnabled());
            // PRISCA (the method shown) has features of its own: those are the ones edited.
            auto edited = [&w] {
                const auto& profile = w.window.session().profile();
                return profile.priscaFeatures.value_or(profile.features).terms()[1][0].scale;
            };
            const double before = edited();
            features->item(1, 0)->setText(QStringLiteral("lots"));
            QVERIFY2(problem->text().contains("steering"), qPrintable(problem->text()));
            QCOMPARE(edited(), before);
            features->item(1, 0)->setText(QStringLiteral("2.5"));
            QVERIFY(problem->text().isEmpty());
            QCOMPARE(edited(), 2.5);
            // Beyond what the car can do: refused with the range named.
            limits->item(1, 1)->setText(QStringLiteral("3"));
            QVERIFY2(problem->text().contains("[-1, 1]"), qPrintable(problem->text()));
            QCOMPARE(w.window.session().profile().info.actionUpper[1], 1.0);
            limits->item(1, 1)->setText(QStringLiteral("0.6"));
            QCOMPARE(w.window.session().profile().info.actionUpper[1], 0.6);
            // PRISCA's form: the slide-car's starts from the PD law and learns through the
            // closed loop with an effort cost; the operator can go back to the paper's start
            // and gradient.
            auto* fromPd = w.find<QCheckBox>("prisca.from-pd");
            auto* gradient = w.find<QComboBox>("prisca.gradient");
            auto* effort = w.find<QDoubleSpinBox>("prisca.effort");
            QVERIFY(fromPd->isChecked());
            QCOMPARE(gradient->currentIndex(), 1);
            QCOMPARE(effort->value(), 3.0);
            QCOMPARE(w.find<QDoubleSpinBox>("prisca.theta-bound")->text(), QStringLiteral("none"));
            fromPd->setChecked(false);
            gradient->setCurrentIndex(0);
            emit gradient->activated(0);
            effort->setValue(0.0);
            QVERIFY(!w.window.session().profile().priscaFromPd);
            QCOMPARE(w.window.session().profile().prisca.gradient,
                     prisca::core::PriscaParameters::Gradient::OneStep);
            QCOMPARE(w.window.session().profile().prisca.effortWeights.size(), 0);
            effort->setValue(1.5);
            QVERIFY(w.window.saveSession(path));
        }
        Window w;
        QVERIFY(w.window.openSession(path));
        const auto& reopened = w.window.session().profile();
        QCOMPARE(reopened.priscaFeatures.value_or(reopened.features).terms()[1][0].scale, 2.5);
        QCOMPARE(w.window.session().profile().info.actionUpper[1], 0.6);
        QCOMPARE(w.find<QTableWidget>("actionLimits")->item(1, 1)->text(), QStringLiteral("0.6"));
        QVERIFY(!w.window.session().profile().priscaFromPd);
        QCOMPARE(w.window.session().profile().prisca.gradient,
                 prisca::core::PriscaParameters::Gradient::OneStep);
        QCOMPARE(w.window.session().profile().prisca.effortWeights,
                 Eigen::Vector2d(1.5, 1.5).eval());
        QVERIFY(!w.find<QCheckBox>("prisca.from-pd")->isChecked());
        QCOMPARE(w.find<QDoubleSpinBox>("prisca.effort")->value(), 1.5);
        QVERIFY(!w.window.session().profile().priscaAutomatic);
        QVERIFY(!w.find<QCheckBox>("prisca.automatic")->isChecked());
        QVERIFY(w.find<QTableWidget>("featureScales")->isEnabled());
    }

    void session_isRememberedBetweenRunsOfTheApplication() {
        {
            Window w;
            w.find<QSpinBox>("prisca.H")->setValue(23);
            QVERIFY(w.window.close());
        }
        Window w;
        QCOMPARE(w.window.session().profile().prisca.horizon, 23);
        QCOMPARE(w.find<QSpinBox>("prisca.H")->value(), 23);
        // A damaged copy in the settings is ignored: the application still starts.
        QSettings().setValue("session/last", QByteArray("{ not json"));
        Window fresh;
        QCOMPARE(fresh.window.session().plant(), QStringLiteral("slidecar"));
        QCOMPARE(fresh.window.session().profile().prisca.horizon,
                 prisca::sim::PlantCatalog::tuning(
                     prisca::sim::PlantCatalog::describe(QStringLiteral("slidecar")))
                     .prisca.horizon);
    }

    void session_ofAnEarlierVersionGetsTodaysTuning() {
        Window w;
        QTemporaryDir dir;
        // A session of an earlier version: its PRISCA/PD/ILC parameters were tuned for an
        // earlier PRISCA, so today's defaults stand in for them and the operator is told; the
        // rest (here the matching window) is read as saved. The same values in a session of
        // today's version are applied.
        for (const int version : {1, 2}) {
            const QString old = dir.filePath(QStringLiteral("v%1.json").arg(version));
            QFile v(old);
            QVERIFY(v.open(QIODevice::WriteOnly));
            v.write(QStringLiteral("{ \"format\": \"prisca-session\", \"version\": %1, "
                                   "\"plant\": \"slidecar\", \"matchingWindow\": 33, "
                                   "\"prisca\": {\"stepScale\": 3, \"thetaBound\": 1}, "
                                   "\"pd\": {\"kp\": [0.5, 1]} }")
                        .arg(version)
                        .toUtf8());
            v.close();
            QVERIFY(w.window.openSession(old));
            const prisca::sim::MethodTuning& opened = w.window.session().profile();
            const prisca::sim::MethodTuning defaults =
                prisca::sim::PlantCatalog::tuning(prisca::sim::PlantCatalog::describe("slidecar"));
            QCOMPARE(opened.matchingWindow, 33);
            const QString status = w.window.statusBar()->currentMessage();
            if (version == 1) {
                QCOMPARE(opened.prisca.stepSize.scale, defaults.prisca.stepSize.scale);
                QCOMPARE(opened.prisca.thetaBound, defaults.prisca.thetaBound);
                QCOMPARE(opened.pd.kp, defaults.pd.kp);
                QVERIFY2(status.contains("earlier"), qPrintable(status));
            } else {
                QCOMPARE(opened.prisca.stepSize.scale, 3.0);
                QCOMPARE(opened.prisca.thetaBound, 1.0);
                QCOMPARE(opened.pd.kp, Eigen::Vector2d(0.5, 1.0));
                QVERIFY2(!status.contains("earlier"), qPrintable(status));
            }
        }
    }

    void demonstrationOfAnotherPlantOrTooShort_isRefusedAndTheSessionKeepsItsOwn() {
        QTemporaryDir dir;
        Window w;
        w.window.session().setPlant("aircraft");
        const auto before = w.window.session().demonstration();
        const Eigen::MatrixXd fitBefore = w.window.session().fit().b;
        // A slide-car's demonstration in an aircraft session: same column count, another plant.
        const QString car = dir.filePath("car.csv");
        prisca::core::FileError error;
        QVERIFY(prisca::core::writeDemonstrationCsv(
            prisca::sim::PlantCatalog::demonstrate("slidecar", 2), car, &error));
        QString text = answerMessageBox(this, [&] {
            QVERIFY(!w.find<prisca::app::TaskPanel>("taskPanel")->openDemonstration(car));
        });
        QVERIFY2(text.contains("car.csv") && text.contains("slidecar"), qPrintable(text));
        QCOMPARE(w.window.session().demonstration(), before);
        QCOMPARE(w.window.session().fit().b, fitBefore);
        // An aircraft demonstration of three samples: refused, and nothing half-changed.
        prisca::core::Demonstration shortDemo =
            prisca::sim::PlantCatalog::demonstrate("aircraft", 2);
        shortDemo.states.conservativeResize(3, Eigen::NoChange);
        shortDemo.actions.conservativeResize(3, Eigen::NoChange);
        shortDemo.time.conservativeResize(3);
        QVERIFY_THROWS_EXCEPTION(
            std::invalid_argument,
            w.window.session().setDemonstration(
                std::make_shared<prisca::core::Demonstration>(shortDemo), "short.csv"));
        QCOMPARE(w.window.session().demonstration(), before);
        QCOMPARE(w.window.session().fit().b, fitBefore);
        QCOMPARE(w.window.session().plant(), QStringLiteral("aircraft"));
    }

    void badFiles_getAClearMessageAndChangeNothing() {
        QTemporaryDir dir;
        Window w;
        const auto demoBefore = w.window.session().demonstration();

        const QString garbage = dir.filePath("garbage.json");
        QFile f(garbage);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(
            "{ \"format\": \"prisca-session\", \"plant\": \"slidecar\", \"prisca\": {\"gamma\": 7} "
            "}");
        f.close();
        QString text = answerMessageBox(this, [&] { QVERIFY(!w.window.openSession(garbage)); });
        QVERIFY2(text.contains("garbage.json") && text.contains("gamma"), qPrintable(text));
        QFile f2(garbage);
        QVERIFY(f2.open(QIODevice::WriteOnly));
        f2.write(
            "{ \"format\": \"prisca-session\", \"plant\": \"slidecar\", "
            "\"prisca\": {\"gradient\": \"sideways\"} }");
        f2.close();
        text = answerMessageBox(this, [&] { QVERIFY(!w.window.openSession(garbage)); });
        QVERIFY2(text.contains("gradient") && text.contains("closed-loop"), qPrintable(text));
        QFile f3(garbage);
        QVERIFY(f3.open(QIODevice::WriteOnly));
        f3.write(
            "{ \"format\": \"prisca-session\", \"plant\": \"slidecar\", "
            "\"prisca\": {\"automatic\": \"yes\"} }");
        f3.close();
        text = answerMessageBox(this, [&] { QVERIFY(!w.window.openSession(garbage)); });
        QVERIFY2(text.contains("'prisca.automatic'") && text.contains("on | off"),
                 qPrintable(text));

        const QString notJson = dir.filePath("not.json");
        QFile g(notJson);
        QVERIFY(g.open(QIODevice::WriteOnly));
        g.write("\x01\x02 nonsense");
        g.close();
        text = answerMessageBox(this, [&] { QVERIFY(!w.window.openSession(notJson)); });
        QVERIFY2(text.contains("not valid JSON"), qPrintable(text));

        // A demonstration with a NaN: the reader names the line; the session keeps its own.
        const QString csv = dir.filePath("bad-demo.csv");
        QFile h(csv);
        QVERIFY(h.open(QIODevice::WriteOnly));
        h.write(
            "# prisca-demonstration 1\n# plant: slidecar\n# dt: 0.025\n"
            "# states: x[m], y[m], psi[rad], vx[m/s], vy[m/s], r[rad/s]\n"
            "# actions: throttle[1], steering[1]\n"
            "t,x,y,psi,vx,vy,r,throttle,steering\n"
            "0,0,0,0,0,0,0,0,0\n0.025,0,nan,0,0,0,0,0,0\n");
        h.close();
        auto* task = w.find<TaskPanel>("taskPanel");
        text = answerMessageBox(this, [&] { QVERIFY(!task->openDemonstration(csv)); });
        QVERIFY2(text.contains("bad-demo.csv") && text.contains(":8"), qPrintable(text));
        QCOMPARE(w.window.session().demonstration(), demoBefore);
    }
};

QTEST_MAIN(TestGuiSession)
#include "test_gui_session.moc"
