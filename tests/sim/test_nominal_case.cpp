// The nominal case: with no perturbation and a perfect sensor the plant is the one the
// demonstration was recorded on, so every closed-loop method must repeat it (park within 1 cm on
// every slide-car style) and action playback must repeat it.
#include "sim/DemonstrationStyles.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/experiments/Table1Protocol.h"

#include <QtTest>

using namespace prisca;
using namespace prisca::sim;

class TestNominalCase : public QObject {
    Q_OBJECT
  private slots:
    void everyMethod_parksOnEveryStyle_data() {
        QTest::addColumn<QString>("method");
        QTest::addColumn<double>("toleranceCm");
        for (const QString& method : MethodCatalog::ids()) {
            if (method == QLatin1String("pegasus")) {
                continue;  // no Table I row: it trains offline on its own scenarios
            }
            if (method == QLatin1String("mpc")) {
                // It identifies a car per cell (seconds, minutes under the sanitizers);
                // test_mpc checks it parks the nominal car through the right model.
                continue;
            }
            // Playback replays the very actions: it ends where the demonstration's last sample
            // was, up to the creep of a car at rest (the table's 0.00 cm).
            const double tolerance = method == QLatin1String("playback") ? 0.005 : 1.0;
            QTest::newRow(qPrintable(method)) << method << tolerance;
        }
    }
    void everyMethod_parksOnEveryStyle() {
        QFETCH(QString, method);
        QFETCH(double, toleranceCm);
        const QString plant = QStringLiteral("slidecar");
        Table1ProtocolSettings settings;
        settings.table.methods = {method};
        settings.table.trials = 1;
        settings.table.run.trainingTrials = 2;
        settings.table.run.perturbation = 0.0;
        settings.table.run.sensor = 0.0;
        settings.table.run.threads = 2;
        settings.styles = DemonstrationStyles::names(plant);
        settings.seedSets = {7};
        const MethodTuning profile = PlantCatalog::tuning(PlantCatalog::describe(plant));
        const Table1ProtocolResult result = runTable1Protocol(settings, profile);
        QCOMPARE(static_cast<int>(result.cells[0].size()),
                 static_cast<int>(settings.styles.size()));
        for (const core::ProtocolCell& cell : result.cells[0]) {
            QCOMPARE(cell.row.position.count, 1);
            QVERIFY2(cell.row.position.maximum <= toleranceCm,
                     qPrintable(QStringLiteral("%1 on %2: %3 cm")
                                    .arg(method, cell.style)
                                    .arg(cell.row.position.maximum)));
            QVERIFY2(cell.row.orientation.maximum <= 1.0,
                     qPrintable(QStringLiteral("%1 on %2: %3 deg")
                                    .arg(method, cell.style)
                                    .arg(cell.row.orientation.maximum)));
        }
    }
};

QTEST_APPLESS_MAIN(TestNominalCase)
#include "test_nominal_case.moc"
