#include "sim/tuning/DiffDriveTuning.h"

#include <stdexcept>

namespace prisca::sim {

MethodTuning diffDriveTuning(const PlantInfo& info) {
    using Source = core::FeatureTerm::Source;
    MethodTuning p;
    p.info = info;
    // e = (longitudinal, lateral, heading, vx, vy, r) in the desired pose's frame. "Either wheel
    // forward, more speed and further along; the right wheel turns it left (and moves it left),
    // the left wheel right."
    QString error;
    const auto mapping =
        core::IntuitiveMapping::parse(QStringLiteral("1,-1,-1,1,0,-1;1,1,1,1,0,1"), &error);
    if (!mapping) {
        throw std::logic_error(error.toStdString());
    }
    p.mapping = *mapping;
    // Both wheels see the position along the path, the offset across it and the heading.
    p.features = core::FeatureMap({
        {{Source::Deviation, 0, 1.0}, {Source::Deviation, 1, 1.0}, {Source::Deviation, 2, 1.0}},
        {{Source::Deviation, 0, 1.0}, {Source::Deviation, 1, 1.0}, {Source::Deviation, 2, 1.0}},
    });
    p.matchingWeights = (Eigen::VectorXd(6) << 1.0, 1.0, 0.3, 0.2, 0.2, 0.05).finished();
    p.matchingWindow = 40;
    p.costWeights = (Eigen::VectorXd(6) << 1.0, 1.0, 0.3, 0.03, 0.03, 0.006).finished();
    // A ceiling camera at 40 Hz, as on the car's rig.
    p.measurement.noise = (Eigen::VectorXd(6) << 0.005, 0.005, 0.01, 0.03, 0.03, 0.05).finished();
    p.measurement.loopLatencySteps = 1;
    p.measurement.dropProbability = 0.02;
    p.compensateLoopLatency = true;
    p.lostTrackDistance = 1.0;
    p.settleTime = 2.0;
    // PRISCA as on the car: from the PD+H+LSD law below, the closed-loop gradient with an
    // effort cost, automatic scales.
    p.priscaFromPd = true;
    p.priscaAutomatic = true;
    p.prisca.horizon = 10;
    p.prisca.gamma = 0.95;
    p.prisca.stepSize.beta = 300.0;
    p.prisca.stepSize.scale = 0.1;
    p.prisca.gradient = core::PriscaParameters::Gradient::ClosedLoop;
    p.prisca.effortWeights = Eigen::Vector2d(3.0, 3.0);
    p.prisca.thetaBound = 0.0;
    p.pgsd.horizon = 5;
    p.pgsd.stepSize = 0.1;
    p.pgsd.thetaBound = 0.5;
    // PD: forward speed on the along-path error, turn on the offset and the heading, mixed into
    // the wheels as the operator's stick is (left = forward - turn, right = forward + turn).
    p.pd.errorCombination = (Eigen::MatrixXd(2, 6) << 1.0, -1.5, -1.0, 0, 0, 0,  //
                             1.0, 1.5, 1.0, 0, 0, 0)
                                .finished();
    p.pd.kp = Eigen::Vector2d(2.0, 2.0);
    p.pd.kd = Eigen::Vector2d(0.05, 0.05);
    p.pdHorizon = 4;
    p.ilcLearningScale = 0.03;
    p.ilcLead = 10;
    p.ilcCutoff = 0.5;
    p.ilcFeedbackScale = 0.5;
    p.lqrEffort = Eigen::Vector2d(1e-3, 1e-3);
    p.pegasus.scenarios = 4;
    p.pegasus.stepSize = 0.5;
    p.pegasus.perturbation = 0.05;
    p.pegasus.maxStepNorm = 0.5;
    p.oracle.objective = OracleParameters::Objective::FinalPose;
    p.oracle.replanEvery = 4;
    p.oracle.samples = 24;
    p.oracle.maxKnots = 8;
    return p;
}

}  // namespace prisca::sim
