#include "app/cli/TaskSetup.h"

#include "sim/MethodCatalog.h"

#include "app/cli/CliSupport.h"
#include "core/DemonstrationCsv.h"
#include "sim/DemonstrationStyles.h"
#include "sim/PlantCatalog.h"

#include <cstdio>

namespace prisca::app::cli {

Task loadTask(const QString& plant, const QString& demonstrationPath, const QString& mask,
              const core::ActionMappingFitOptions& options) {
    return taskFor(plant, readDemonstration(demonstrationPath), demonstrationPath, mask, options);
}

Task scriptedTaskFor(const QString& plant, const core::Demonstration& scripted,
                     const QString& sourceName) {
    // Through the format's text, in memory: a scripted demonstration passes the same checks as
    // a recorded file (and no scratch file can fail on a full disk).
    QString problem;
    const QByteArray text = core::formatDemonstrationCsv(scripted, &problem);
    if (text.isEmpty()) {
        throw UsageError(QStringLiteral("%1: %2").arg(sourceName, problem));
    }
    core::FileError error;
    auto demonstration = core::parseDemonstrationCsv(text, sourceName, &error);
    if (!demonstration) {
        throw UsageError(error.toString());
    }
    return taskFor(plant, std::move(*demonstration), sourceName, QString());
}

Task taskFor(const QString& plant, core::Demonstration demonstration,
             const QString& demonstrationPath, const QString& mask,
             const core::ActionMappingFitOptions& options) {
    const QString name = plant.isEmpty() ? demonstration.plant : plant;
    if (!sim::PlantCatalog::contains(name)) {
        throw UsageError(QStringLiteral("%1: unknown plant '%2' (one of: %3; or give --plant)")
                             .arg(demonstrationPath, name, sim::PlantCatalog::names().join(' ')));
    }
    const sim::PlantInfo info = sim::PlantCatalog::describe(name);
    sim::MethodTuning profile = sim::PlantCatalog::tuning(info);
    if (!mask.isEmpty()) {
        QString error;
        auto parsed = core::IntuitiveMapping::parse(mask, &error);
        if (!parsed) {
            throw UsageError(QStringLiteral("--mask: %1").arg(error));
        }
        if (parsed->controls() != info.actionDimension() ||
            parsed->states() != info.stateDimension()) {
            throw UsageError(
                QStringLiteral("--mask is %1 x %2; the %3 needs %4 rows (controls) of %5 "
                               "entries (states)")
                    .arg(parsed->controls())
                    .arg(parsed->states())
                    .arg(name)
                    .arg(info.actionDimension())
                    .arg(info.stateDimension()));
        }
        profile.mapping = *parsed;
    }
    if (actionsNeverChange(demonstration)) {
        // Playback or PD of it is legitimate; learning from it is not (no stick moved).
        std::fprintf(stderr,
                     "prisca-cli: warning: %s: the actions never change, so B_v is fitted from "
                     "nothing (PRISCA keeps only the signs of B~)\n",
                     qPrintable(core::printable(demonstrationPath)));
    }
    try {
        // Checked and fitted as the window's session is (sim::makeTask).
        return sim::makeTask(profile,
                             std::make_shared<const core::Demonstration>(std::move(demonstration)),
                             options);
    } catch (const std::invalid_argument& e) {
        throw UsageError(
            QStringLiteral("%1: %2").arg(demonstrationPath, QString::fromStdString(e.what())));
    }
}

bool actionsNeverChange(const core::Demonstration& demonstration) {
    const Eigen::MatrixXd& u = demonstration.actions;
    return u.rows() > 0 && (u.rowwise() - u.row(0)).cwiseAbs().maxCoeff() == 0.0;
}

QString checkedPlant(const QString& name) {
    if (!sim::PlantCatalog::contains(name)) {
        throw UsageError(QStringLiteral("unknown plant '%1' (one of: %2)")
                             .arg(name, sim::PlantCatalog::names().join(' ')));
    }
    return name;
}

Task loadOrDemonstrate(const QString& plant, const QString& demonstrationPath,
                       std::uint64_t demoSeed, const sim::RecordingConditions& conditions) {
    if (!demonstrationPath.isEmpty()) {
        return loadTask(plant, demonstrationPath, QString());
    }
    checkedPlant(plant);
    return scriptedTask(plant, sim::DemonstrationStyles::classic(plant), demoSeed, conditions);
}

Task scriptedTask(const QString& plant, const QString& style, std::uint64_t seed,
                  const sim::RecordingConditions& conditions) {
    checkedPlant(plant);
    if (!sim::DemonstrationStyles::contains(plant, style)) {
        throw UsageError(QStringLiteral("unknown %1 style '%2' (one of: %3)")
                             .arg(plant, style, sim::DemonstrationStyles::names(plant).join(' ')));
    }
    return scriptedTaskFor(plant,
                           sim::DemonstrationStyles::record(plant, style, seed, {}, conditions),
                           QStringLiteral("%1 %2 seed %3").arg(plant, style).arg(seed));
}

void addPlantParametersOption(CommandLine& line) {
    line.addValue("plant-params",
                  "The plant's physical parameters from this plant file (JSON; `prisca-cli plant "
                  "--plant NAME --print-params --format json` writes one to edit). Default: the "
                  "catalog's plant.",
                  "file");
}

std::shared_ptr<const sim::PlantParameters> plantParametersOption(const CommandLine& line,
                                                                  const QString& plant) {
    if (!line.isSet("plant-params")) {
        return nullptr;
    }
    QString error;
    auto parameters = sim::readPlantParameters(line.value("plant-params"), plant, &error);
    if (!parameters) {
        throw UsageError(QStringLiteral("--plant-params: %1").arg(error));
    }
    return std::make_shared<const sim::PlantParameters>(std::move(*parameters));
}

Task taskFromOptions(const CommandLine& line, const QString& plant) {
    const auto parameters = plantParametersOption(line, plant);
    sim::RecordingConditions conditions;
    conditions.parameters = parameters.get();
    Task task = loadOrDemonstrate(
        plant, line.value("demo"),
        static_cast<std::uint64_t>(line.integer("demo-seed", 0, 1LL << 62)), conditions);
    task.plantParameters = parameters;
    return task;
}

QStringList stylesOption(const CommandLine& line, const QString& plant) {
    const QString value = line.value("styles");
    const QStringList styles = value == QLatin1String("all")
                                   ? sim::DemonstrationStyles::names(plant)
                                   : value.split(QLatin1Char(','), Qt::SkipEmptyParts);
    if (styles.isEmpty()) {
        throw UsageError(QStringLiteral("--styles: no style given"));
    }
    if (const QString unknown = sim::DemonstrationStyles::unknownStyleIn(plant, styles);
        !unknown.isEmpty()) {
        throw UsageError(QStringLiteral("--styles: %1").arg(unknown));
    }
    return styles;
}

void addMethodParameterOptions(CommandLine& line) {
    line.addValue("param",
                  "Set a method parameter, NAME=VALUE (repeatable; one value per control, "
                  "comma-separated, where it has one per control). 'prisca-cli methods' lists "
                  "every method's parameters with units, ranges and each plant's default.",
                  "NAME=VALUE");
    line.addValue("start",
                  "The feedback law PRISCA and the PD family start from: 'tuned' (the plant "
                  "profile's PD gains; the default on catalog plants) or 'demo' (derived from "
                  "the demonstration, the fit and the actuator limits alone; the default with "
                  "--plant-params or --variants). The same as "
                  "--param start=VALUE, applied before every --param.",
                  "demo|tuned");
    line.addValue("model",
                  "The car mpc plans through: a plant file (as `prisca-cli identify` writes "
                  "one). Default: identified from the demonstration when the run starts.",
                  "file");
}

void applyMethodParameters(const CommandLine& line, sim::MethodTuning& profile,
                           bool plantFromFile) {
    if (!line.isSet("start") && plantFromFile) {
        // Nobody tuned a car described by a file: start from its demonstration.
        profile.start = sim::MethodTuning::Start::Demonstration;
    }
    if (line.isSet("start")) {
        const QString start = line.value("start");
        if (start != QLatin1String("demo") && start != QLatin1String("tuned")) {
            throw UsageError(QStringLiteral("--start: '%1' is not one of: demo tuned").arg(start));
        }
        profile.start = start == QLatin1String("demo") ? sim::MethodTuning::Start::Demonstration
                                                       : sim::MethodTuning::Start::Tuned;
    }
    if (line.isSet("model")) {
        QString error;
        const auto model = sim::readPlantParameters(line.value("model"), profile.info.name, &error);
        if (!model) {
            throw UsageError(QStringLiteral("--model: %1").arg(error));
        }
        profile.mpcModel = std::make_shared<const sim::PlantParameters>(*model);
    }
    for (const QString& assignment : line.values("param")) {
        try {
            sim::MethodCatalog::setParameter(profile, assignment);
        } catch (const std::invalid_argument& e) {
            throw UsageError(QStringLiteral("--param: %1").arg(QString::fromUtf8(e.what())));
        }
    }
}

void addRunSettingsOptions(CommandLine& line, const QString& trainingHelp) {
    const sim::RunSettings defaults;
    line.addValue("seed", "Seed of the evaluation trials (training trials have their own stream).",
                  "N", QString::number(defaults.seed));
    line.addValue("perturbation", "Plant perturbation level (0 nominal, 1 realistic).", "level",
                  QString::number(defaults.perturbation));
    line.addValue("perturbation-model",
                  "How the plant's variation spreads over the trials: 'session' (a lab day: the "
                  "car's mismatch drawn once for the day, a battery drift trial by trial, a little "
                  "variation per trial) or 'trial' (each trial draws its own).",
                  "session|trial", sim::perturbationModelName(defaults.perturbationModel));
    line.addValue("sensor", "Sensor noise level (0 perfect, 1 realistic).", "level",
                  QString::number(defaults.sensor));
    line.addValue("pose-filter",
                  "Pass the sensor's observations through the pose filter (an extended Kalman "
                  "filter bridging dropped samples and gating outliers) before the controller: "
                  "'on' hands it the estimate predicted across the latency to now (it is told "
                  "latency 0), 'lagged' the estimate at the measurement's time (it compensates "
                  "the latency itself), 'off' the raw observation. Planar vehicles only.",
                  "on|lagged|off",
                  defaults.poseFilter ? QStringLiteral("on") : QStringLiteral("off"));
    if (!trainingHelp.isEmpty()) {
        line.addValue("training-trials", trainingHelp, "N",
                      QString::number(defaults.trainingTrials));
    }
    line.addValue("jobs", "Worker threads.", "N", QString::number(defaults.threads));
}

void readRunSettings(const CommandLine& line, sim::RunSettings& settings, bool training) {
    settings.seed = static_cast<std::uint64_t>(line.integer("seed", 0, 1LL << 62));
    settings.perturbation = line.number("perturbation", 0.0, 10.0);
    settings.sensor = line.number("sensor", 0.0, 10.0);
    const QString model = line.value("perturbation-model");
    if (const auto parsed = sim::perturbationModelFromName(model)) {
        settings.perturbationModel = *parsed;
    } else {
        throw UsageError(
            QStringLiteral("--perturbation-model: '%1' is not one of session, trial").arg(model));
    }
    const QString filter = line.value("pose-filter");
    if (filter != QLatin1String("on") && filter != QLatin1String("lagged") &&
        filter != QLatin1String("off")) {
        throw UsageError(
            QStringLiteral("--pose-filter: '%1' is none of on, lagged, off").arg(filter));
    }
    settings.poseFilter = filter != QLatin1String("off");
    settings.poseFilterPredicts = filter == QLatin1String("on");
    if (training) {
        settings.trainingTrials = static_cast<int>(line.integer("training-trials", 0, 100000));
    }
    settings.threads = static_cast<int>(line.integer("jobs", 1, 256));
}

}  // namespace prisca::app::cli
