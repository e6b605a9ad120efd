#include "app/LabSession.h"
#include "app/LabSession_p.h"

#include "core/DemonstrationCsv.h"
#include "core/FileIo.h"
#include "sim/DemonstrationStyles.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/planning/IdentificationReport.h"
#include "sim/run/Task.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace prisca::app {

using session::scripted;

LabSession::LabSession(QObject* parent) : QObject(parent) {}

void LabSession::setPlantParameters(std::shared_ptr<const sim::PlantParameters> parameters) {
    if (parameters && parameters->plant != task_.plant) {
        throw std::invalid_argument(tr("the plant file %1 describes a %2, not a %3")
                                        .arg(parameters->source, parameters->plant, task_.plant)
                                        .toStdString());
    }
    const bool rerecord = demonstrationSource_.isEmpty();
    auto demonstration =
        rerecord ? scripted(task_.plant, scriptedStyle_, scriptedSeed_, parameters.get())
                 : task_.demonstration;
    // Nobody tuned a car described by a file: the controllers start from its demonstration
    // (the operator may choose the tuned start again in the Controller panel).
    sim::MethodTuning profile = task_.profile;
    profile.start =
        parameters ? sim::MethodTuning::Start::Demonstration : sim::MethodTuning::Start::Tuned;
    task_ = sim::makeTask(profile, std::move(demonstration), fitOptions_, std::move(parameters));
    emit plantParametersChanged();
    if (rerecord) {
        emit demonstrationChanged();
    }
    emit fitChanged();
    dropModel(tr("the plant's physical parameters changed"));
    emit controllerChanged();
}

void LabSession::setPlant(const QString& plant) {
    if (!sim::PlantCatalog::names().contains(plant)) {
        throw std::invalid_argument(QStringLiteral("unknown plant '%1'").arg(plant).toStdString());
    }
    const QString style = sim::DemonstrationStyles::classic(plant);
    task_ = sim::makeTask(sim::PlantCatalog::tuning(sim::PlantCatalog::describe(plant)),
                          scripted(plant, style, 1, nullptr), fitOptions_);
    scriptedStyle_ = style;
    scriptedSeed_ = 1;
    demonstrationSource_.clear();
    emit plantChanged(task_.plant);
    emit plantParametersChanged();
    emit demonstrationChanged();
    emit fitChanged();
    dropModel(tr("the target changed"));
    emit controllerChanged();
}

void LabSession::setDemonstration(std::shared_ptr<const core::Demonstration> demonstration,
                                  const QString& source) {
    if (!demonstration) {
        throw std::invalid_argument(tr("no demonstration").toStdString());
    }
    // Checked and fitted before anything changes, as the CLI makes its task (sim::makeTask): a
    // demonstration that is refused leaves the session as it was (its own with its fit).
    try {
        task_ = sim::makeTask(task_.profile, std::move(demonstration), fitOptions_,
                              task_.plantParameters);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(tr("the demonstration does not fit the %1: %2")
                                        .arg(task_.plant, QString::fromStdString(e.what()))
                                        .toStdString());
    }
    demonstrationSource_ = source;
    emit demonstrationChanged();
    emit fitChanged();
    if (model_) {
        dropModel(tr("the demonstration changed"));
        emit controllerChanged();
    }
}

QString LabSession::demonstrationDescription() const {
    return demonstrationSource_.isEmpty()
               ? tr("the scripted operator (%1, seed %2)").arg(scriptedStyle_).arg(scriptedSeed_)
               : QDir::toNativeSeparators(demonstrationSource_);
}

void LabSession::setDemonstrationSource(const QString& source) {
    demonstrationSource_ = source;
    emit demonstrationSourceChanged();
}

void LabSession::setScriptedDemonstration(const QString& style, std::uint64_t seed) {
    if (!sim::DemonstrationStyles::contains(task_.plant, style)) {
        throw std::invalid_argument(
            tr("the %1 has no demonstration style '%2'").arg(task_.plant, style).toStdString());
    }
    task_ = sim::makeTask(task_.profile,
                          scripted(task_.plant, style, seed, task_.plantParameters.get()),
                          fitOptions_, task_.plantParameters);
    demonstrationSource_.clear();
    scriptedStyle_ = style;
    scriptedSeed_ = seed;
    emit demonstrationChanged();
    emit fitChanged();
    if (model_) {
        dropModel(tr("the demonstration changed"));
        emit controllerChanged();
    }
}

void LabSession::setProfile(const sim::MethodTuning& profile) {
    const bool mappingChanged =
        profile.mapping.signs.rows() != task_.profile.mapping.signs.rows() ||
        profile.mapping.signs.cols() != task_.profile.mapping.signs.cols() ||
        profile.mapping.signs != task_.profile.mapping.signs;
    if (mappingChanged) {
        task_ = sim::makeTask(profile, task_.demonstration, fitOptions_, task_.plantParameters);
    } else {
        task_.profile = profile;
    }
    // The model mpc plans through is the session's (a profile reset to its defaults keeps it).
    applyModelToProfile();
    if (mappingChanged) {
        emit fitChanged();
    }
    emit controllerChanged();
}

void LabSession::setIdentifiedModel(
    std::shared_ptr<const sim::IdentificationResult> model,
    const std::shared_ptr<const core::Demonstration>& identifiedFrom) {
    if (model) {
        if (!model->ok()) {
            throw std::invalid_argument(tr("an identification that was refused or cancelled is "
                                           "no model")
                                            .toStdString());
        }
        if (model->parameters.plant != task_.plant) {
            throw std::invalid_argument(tr("the model is of a %1, the target a %2")
                                            .arg(model->parameters.plant, task_.plant)
                                            .toStdString());
        }
        if (identifiedFrom != task_.demonstration) {
            throw std::invalid_argument(
                tr("the demonstration changed while the model was identified").toStdString());
        }
    }
    model_ = std::move(model);
    applyModelToProfile();
    emit identifiedModelChanged(QString());
    emit controllerChanged();
}

sim::PlantParameters LabSession::identificationPrior() const {
    return sim::measuredPrior(task_.plantParameters ? *task_.plantParameters
                                                    : sim::defaultPlantParameters(task_.plant));
}

void LabSession::dropModel(const QString& reason) {
    const bool had = model_ != nullptr;
    model_.reset();
    applyModelToProfile();
    if (had) {
        emit identifiedModelChanged(reason);
    }
}

void LabSession::applyModelToProfile() {
    task_.profile.mpcModel =
        model_ ? std::make_shared<const sim::PlantParameters>(model_->parameters) : nullptr;
}

void LabSession::setFitOptions(const core::ActionMappingFitOptions& options) {
    task_ = sim::makeTask(task_.profile, task_.demonstration, options, task_.plantParameters);
    fitOptions_ = options;
    emit fitChanged();
}

void LabSession::setMethod(const QString& method) {
    if (!sim::MethodCatalog::contains(method)) {
        throw std::invalid_argument(
            QStringLiteral("unknown method '%1' (one of: %2)")
                .arg(method, sim::MethodCatalog::ids().join(QLatin1Char(' ')))
                .toStdString());
    }
    method_ = method;
    emit controllerChanged();
}

}  // namespace prisca::app
