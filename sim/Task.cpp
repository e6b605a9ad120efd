#include "Task.h"

#include "TaskCheck.h"

#include <stdexcept>

namespace prisca::sim {

Task makeTask(const MethodTuning& profile, std::shared_ptr<const core::Demonstration> demonstration,
              const core::ActionMappingFitOptions& options) {
    if (!demonstration) {
        throw std::invalid_argument("no demonstration");
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
    return task;
}

}  // namespace prisca::sim
