#include "EpisodeRunner.h"

namespace prisca::sim {

EpisodeResult runEpisode(Plant& plant, core::Controller& controller,
                         const EpisodeSettings& settings, const std::function<bool()>& cancelled) {
    EpisodeResult result;
    Eigen::VectorXd state = plant.reset(settings.seed, settings.perturbation);
    // The sensor's noise stream is its own, so changing the plant's draws never shifts it.
    MeasurementModel sensor(settings.measurement, mixSeed(settings.seed, 7));
    sensor.reset(state);
    controller.reset(settings.resetMode);

    const double dt = plant.timing().controlPeriod;
    const int maxSteps = static_cast<int>(settings.duration / dt + 0.5);
    double costSum = 0.0;
    int k = 0;
    for (; k < maxSteps; ++k) {
        if (cancelled && cancelled()) {
            result.cancelled = true;
            break;
        }
        const double t = k * dt;
        if (settings.stopAtRestAfter >= 0.0 && t >= settings.stopAtRestAfter && plant.atRest()) {
            break;
        }
        const Eigen::VectorXd observation = sensor.observe(state);
        const core::ControlStep& control = controller.step(observation);
        costSum += control.cost;
        if (settings.recordSteps) {
            StepRecord record;
            record.time = t;
            record.state = state;
            record.observation = observation;
            record.referenceIndex = control.referenceIndex;
            record.deviation = control.deviation;
            record.action = control.action;
            record.referenceAction = control.referenceAction;
            record.cost = control.cost;
            if (const Eigen::MatrixXd* theta = controller.learnedParameters()) {
                record.parameters = theta->reshaped();
            }
            result.steps.push_back(std::move(record));
        }
        state = plant.step(control.action);
    }
    result.finalState = state;
    result.stepCount = k;
    result.duration = k * dt;
    result.meanCost = k > 0 ? costSum / k : 0.0;
    return result;
}

}  // namespace prisca::sim
