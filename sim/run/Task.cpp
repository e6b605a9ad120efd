#include "sim/run/Task.h"

#include "sim/run/TaskCheck.h"

#include <stdexcept>

namespace prisca::sim {

Task makeTask(const MethodTuning& profile, std::shared_ptr<const core::Demonstration> demonstration,
              const core::ActionMappingFitOptions& options,
              std::shared_ptr<const PlantParameters> plantParameters) {
    if (!demonstration) {
        throw std::invalid_argument("no demonstration");
    }
    if (plantParameters) {
        if (plantParameters->plant != profile.info.name) {
            throw std::invalid_argument(
                QStringLiteral("the plant file %1 describes a %2, not a %3")
                    .arg(plantParameters->source, plantParameters->plant, profile.info.name)
                    .toStdString());
        }
        if (const QString problem =
                plantParametersProblem(plantParameters->plant, plantParameters->values);
            !problem.isEmpty()) {
            throw std::invalid_argument(problem.toStdString());
        }
    }
    checkDemonstrationFor(*demonstration, profile.info);
    if (profile.mapping.controls() != profile.info.actionDimension() ||
        profile.mapping.states() != profile.info.stateDimension()) {
        throw std::invalid_argument(
            QStringLiteral("the sign model B~ is %1 x %2; the %3 needs %4 x %5")
                .arg(profile.mapping.controls())
                .arg(profile.mapping.states())
                .arg(profile.info.name)
                .arg(profile.info.actionDimension())
                .arg(profile.info.stateDimension())
                .toStdString());
    }
    Task task;
    task.plant = profile.info.name;
    task.profile = profile;
    task.timing.controlPeriod = demonstration->dt;
    task.fit = core::fitActionMapping(*demonstration, profile.mapping,
                                      profile.info.deviationModel(), options);
    task.demonstration = std::move(demonstration);
    task.plantParameters = std::move(plantParameters);
    return task;
}

}  // namespace prisca::sim
