#include "sim/demonstrations/AcrobotDemonstrator.h"

#include "core/DeviationModel.h"

#include "sim/demonstrations/DemonstrationRecorder.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace prisca::sim {

namespace {

using core::kPi;

using core::wrapAngle;

// The swing the person has in mind: angle and rate of a sine whose amplitude grows along a
// smoothstep envelope (zero slope at both ends, so the arm starts and settles in gently).
struct Swing {
    double amplitude;
    double omega;     // [rad/s]
    double phase;     // [rad]
    double growTime;  // [s]

    Eigen::Vector2d at(double t) const {
        const double x = std::clamp(t / std::max(growTime, 1e-9), 0.0, 1.0);
        const double envelope = x * x * (3.0 - 2.0 * x);
        const double envelopeRate = t < growTime ? 6.0 * x * (1.0 - x) / growTime : 0.0;
        const double s = std::sin(omega * t - phase);
        const double c = std::cos(omega * t - phase);
        return {amplitude * envelope * s, amplitude * (envelopeRate * s + envelope * omega * c)};
    }
};

}  // namespace

core::Demonstration AcrobotDemonstrator::record(std::uint64_t seed,
                                                const SimulationTiming& timing) {
    return record(seed, Script{}, timing, AcrobotParameters{});
}

core::Demonstration AcrobotDemonstrator::record(std::uint64_t seed, const Script& script,
                                                const SimulationTiming& timing,
                                                const AcrobotParameters& arm,
                                                const Perturbation& conditions) {
    Acrobot plant(arm, timing);
    plant.reset(seed, conditions);
    DemonstrationRecorder recorder(plant.info(), timing.controlPeriod);

    const double omega = 2.0 * kPi / script.period;
    const Swing shoulder{script.shoulderAmplitude, omega, 0.0, script.growTime};
    // The counter-swing: opposite sign, trailing by elbowLag.
    const Swing elbow{-script.elbowAmplitude, omega, script.elbowLag, script.growTime};

    // The hand's jitter: an Ornstein-Uhlenbeck torque per joint, seeded and slowly wandering
    // (a person's tremor is smooth, not white).
    std::mt19937_64 draw(mixSeed(seed, 200));
    std::normal_distribution<double> normal(0.0, 1.0);
    const double dt = timing.controlPeriod;
    const double decay = std::exp(-dt / std::max(script.jitterCorrelation, 1e-9));
    const double kick = script.jitter * std::sqrt(1.0 - decay * decay);
    Eigen::Vector2d jitter(script.jitter * normal(draw), script.jitter * normal(draw));

    const Eigen::VectorXd& lower = plant.info().actionLower;
    const Eigen::VectorXd& upper = plant.info().actionUpper;
    const int samples = static_cast<int>(std::lround(script.duration / dt));
    Eigen::VectorXd s = plant.state();
    for (int k = 0; k < samples; ++k) {
        const double t = k * dt;
        const Eigen::Vector2d q1 = shoulder.at(t);
        const Eigen::Vector2d q2 = elbow.at(t);
        Eigen::VectorXd u(2);
        u[0] = script.shoulderStiffness * wrapAngle(q1[0] - s[0]) +
               script.shoulderDamping * (q1[1] - s[2]) + jitter[0];
        u[1] = script.elbowStiffness * wrapAngle(q2[0] - s[1]) +
               script.elbowDamping * (q2[1] - s[3]) + jitter[1];
        // Recorded as applied: the person cannot push past the motors' limits.
        u = u.cwiseMax(lower).cwiseMin(upper);
        recorder.record(s, u);
        s = plant.step(u);
        for (int j = 0; j < 2; ++j) {
            jitter[j] = decay * jitter[j] + kick * normal(draw);
        }
    }
    core::Demonstration d = recorder.demonstration();
    d.metadata.insert(QStringLiteral("source"), QStringLiteral("AcrobotDemonstrator"));
    d.metadata.insert(QStringLiteral("seed"), QString::number(seed));
    return d;
}

}  // namespace prisca::sim
