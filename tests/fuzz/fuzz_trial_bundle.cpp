// The trial-bundle reader the window's replay dialog and `prisca-cli replay` share, on arbitrary
// files: the input is bundle.json, demonstration.csv and samples.csv separated by lines "%%%%".
// It never crashes; a refused bundle says why; an accepted one is something the dialog can show
// (a known plant, a demonstration with the pose's columns, found poses on the floor, finite
// times) and its summary (what replay prints) is computed without a fault.
#include "FuzzTarget.h"

#include "rig/TrialBundle.h"
#include "sim/PlantCatalog.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <cmath>

using prisca::rig::TrialBundle;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static QTemporaryDir* const scratch = new QTemporaryDir;
    const QByteArray input(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const QList<QByteArray> parts = QByteArray(input).replace("\n%%%%\n", "\x01").split('\x01');
    const QString folder = scratch->filePath(QStringLiteral("bundle"));
    QDir(folder).removeRecursively();
    QDir().mkpath(folder + QStringLiteral("/frames"));
    const char* names[] = {"bundle.json", "demonstration.csv", "samples.csv"};
    for (int i = 0; i < 3 && i < parts.size(); ++i) {
        QFile file(QDir(folder).filePath(QLatin1String(names[i])));
        FUZZ_CHECK(file.open(QIODevice::WriteOnly));
        file.write(parts[i]);
    }
    QString error;
    const auto bundle = TrialBundle::load(folder, &error);
    if (!bundle) {
        FUZZ_CHECK(!error.isEmpty());
        return 0;
    }
    const QString plant = bundle->header.value("plant").toString(QStringLiteral("slidecar"));
    FUZZ_CHECK(prisca::sim::PlantCatalog::contains(plant));
    const prisca::sim::PlantInfo info = prisca::sim::PlantCatalog::describe(plant);
    FUZZ_CHECK(bundle->demonstration && bundle->demonstration->length() > 0);
    if (info.pose) {
        FUZZ_CHECK(bundle->demonstration->states.cols() > info.pose->x &&
                   bundle->demonstration->states.cols() > info.pose->y &&
                   bundle->demonstration->states.cols() > info.pose->heading);
    }
    for (const prisca::rig::BundleSample& s : bundle->samples) {
        FUZZ_CHECK(std::isfinite(s.t));
        if (s.found) {
            FUZZ_CHECK(std::isfinite(s.x) && std::isfinite(s.y) && std::isfinite(s.psi));
            FUZZ_CHECK(std::abs(s.x) <= 1e4 && std::abs(s.y) <= 1e4);
        }
    }
    const QJsonObject summary = prisca::rig::summarizeBundle(*bundle);
    FUZZ_CHECK(summary.value("samples").toInt() == static_cast<int>(bundle->samples.size()));
    prisca::rig::recordedRuns(*bundle);
    return 0;
}
