// The acrobot: the analytic "book" equations, the Box2D plant against them, seeding, limits and
// the scripted demonstrator.
#include "sim/demonstrations/AcrobotDemonstrator.h"
#include "sim/plants/Acrobot.h"
#include "sim/plants/AcrobotEquations.h"

#include <QtTest>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

using namespace prisca::sim;

namespace {

constexpr double kPi = 3.14159265358979323846;

double wrap(double a) {
    return std::remainder(a, 2.0 * kPi);
}

// The elbow acceleration of the underactuated acrobot exactly as the "book" dynamics write it (an
// independent transcription, not a call into AcrobotEquations).
double bookElbowAcceleration(const Eigen::Vector4d& s, double a) {
    const double m1 = 1.0, m2 = 1.0, l1 = 1.0, lc1 = 0.5, lc2 = 0.5, I1 = 1.0, I2 = 1.0, g = 9.8;
    const double theta1 = s[0], theta2 = s[1], dtheta1 = s[2], dtheta2 = s[3];
    const double d1 =
        m1 * lc1 * lc1 + m2 * (l1 * l1 + lc2 * lc2 + 2 * l1 * lc2 * std::cos(theta2)) + I1 + I2;
    const double d2 = m2 * (lc2 * lc2 + l1 * lc2 * std::cos(theta2)) + I2;
    const double phi2 = m2 * lc2 * g * std::cos(theta1 + theta2 - kPi / 2.);
    const double phi1 = -m2 * l1 * lc2 * dtheta2 * dtheta2 * std::sin(theta2) -
                        2 * m2 * l1 * lc2 * dtheta2 * dtheta1 * std::sin(theta2) +
                        (m1 * lc1 + m2 * l1) * g * std::cos(theta1 - kPi / 2) + phi2;
    return (a + d2 / d1 * phi1 - m2 * l1 * lc2 * dtheta1 * dtheta1 * std::sin(theta2) - phi2) /
           (m2 * lc2 * lc2 + I2 - d2 * d2 / d1);
}

// The book's shoulder acceleration given the elbow's: ddth1 = -(d2 ddth2 + phi1) / d1.
double bookShoulderAcceleration(const Eigen::Vector4d& s, double ddtheta2) {
    const double theta1 = s[0], theta2 = s[1], dtheta1 = s[2], dtheta2 = s[3];
    const double d1 = 0.25 + (1 + 0.25 + std::cos(theta2)) + 2;
    const double d2 = (0.25 + 0.5 * std::cos(theta2)) + 1;
    const double phi2 = 0.5 * 9.8 * std::cos(theta1 + theta2 - kPi / 2.);
    const double phi1 = -0.5 * dtheta2 * dtheta2 * std::sin(theta2) -
                        2 * 0.5 * dtheta2 * dtheta1 * std::sin(theta2) +
                        1.5 * 9.8 * std::cos(theta1 - kPi / 2) + phi2;
    return -(d2 * ddtheta2 + phi1) / d1;
}

using TorqueProgram = std::function<Eigen::Vector2d(int step)>;

struct Agreement {
    double angle = 0.0;  // max |wrapped angle difference| [rad]
    double rate = 0.0;   // max |rate difference| [rad/s]
    double gap = 0.0;    // max pin gap of the Box2D joints [m]
};

// Runs the Box2D plant and RK4 of the equations (fine step) side by side from the same state
// under the same held torques for `steps` control periods.
Agreement compare(Acrobot& plant, const Eigen::Vector4d& start, const TorqueProgram& torque,
                  int steps, double fineStep = 1e-4) {
    const AcrobotEquations equations{plant.parameters().links};
    Eigen::Vector4d reference = start;
    plant.resetTo(start);
    Agreement worst;
    for (int k = 0; k < steps; ++k) {
        const Eigen::VectorXd s = plant.step(torque(k));
        const Eigen::Vector2d tau = plant.appliedTorque();  // what the plant applied (clamped)
        reference = equations.integrate(reference, tau, plant.timing().controlPeriod, fineStep);
        worst.angle = std::max({worst.angle, std::abs(wrap(s[0] - reference[0])),
                                std::abs(wrap(s[1] - reference[1]))});
        worst.rate =
            std::max({worst.rate, std::abs(s[2] - reference[2]), std::abs(s[3] - reference[3])});
        worst.gap = std::max(worst.gap, plant.jointGap());
    }
    return worst;
}

Eigen::Vector2d smallTorque(int k) {
    const double t = k * 0.025;
    return {1.5 * std::sin(1.3 * t), 0.8 * std::cos(2.1 * t)};
}

Eigen::Vector2d largeTorque(int k) {
    const double t = k * 0.025;
    return {8.0 * std::sin(3.0 * t), -6.0 * std::sin(4.0 * t + 0.5)};
}

const Eigen::Vector4d kLargeStart(1.5, -1.0, 0.5, -1.0);

// The largest |E - E0| of the unactuated Box2D arm over `seconds`.
double energyDrift(int substeps, double seconds, double* final = nullptr) {
    SimulationTiming timing;
    timing.physicsSubsteps = substeps;
    Acrobot plant({}, timing);
    const AcrobotEquations equations;
    Eigen::Vector4d s = plant.resetTo(Eigen::Vector4d(1.2, 0.8, 0.0, 0.0));
    const double e0 = equations.energy(s);
    double worst = 0.0;
    const int steps = static_cast<int>(std::lround(seconds / timing.controlPeriod));
    for (int k = 0; k < steps; ++k) {
        s = plant.step(Eigen::Vector2d::Zero());
        worst = std::max(worst, std::abs(equations.energy(s) - e0));
    }
    if (final) {
        *final = equations.energy(s) - e0;
    }
    return worst;
}

// A trial on a realistically perturbed plant under a fixed torque program.
std::vector<Eigen::VectorXd> run(Acrobot& plant, std::uint64_t seed, int steps) {
    std::vector<Eigen::VectorXd> states{plant.reset(seed, Perturbation::realistic())};
    for (int k = 0; k < steps; ++k) {
        const double t = k * plant.timing().controlPeriod;
        states.push_back(plant.step(Eigen::Vector2d(6.0 * std::sin(2.0 * t), 3.0 * std::cos(t))));
    }
    return states;
}

template <typename F>
bool throwsInvalidArgument(F&& f) {
    try {
        f();
    } catch (const std::invalid_argument&) {
        return true;
    }
    return false;
}

double correlation(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    const Eigen::VectorXd x = a.array() - a.mean();
    const Eigen::VectorXd y = b.array() - b.mean();
    return x.dot(y) / std::sqrt(x.squaredNorm() * y.squaredNorm());
}

}  // namespace

class TestAcrobot : public QObject {
    Q_OBJECT
  private slots:
    // --- the analytic equations -------------------------------------------------------------

    void equations_reduceToBookFormulaWithoutShoulderTorque() {
        const AcrobotEquations equations;
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> angle(-kPi, kPi);
        std::uniform_real_distribution<double> rate(-8.0, 8.0);
        std::uniform_real_distribution<double> torque(-10.0, 10.0);
        double worst = 0.0;
        for (int i = 0; i < 2000; ++i) {
            const Eigen::Vector4d s(angle(rng), angle(rng), rate(rng), rate(rng));
            const double tau2 = torque(rng);
            const Eigen::Vector4d ds = equations.derivative(s, Eigen::Vector2d(0.0, tau2));
            const double book2 = bookElbowAcceleration(s, tau2);
            const double book1 = bookShoulderAcceleration(s, book2);
            QCOMPARE(ds[0], s[2]);
            QCOMPARE(ds[1], s[3]);
            const double e = std::max(std::abs(ds[2] - book1) / std::max(1.0, std::abs(book1)),
                                      std::abs(ds[3] - book2) / std::max(1.0, std::abs(book2)));
            worst = std::max(worst, e);
        }
        qInfo("book reduction (tau1 = 0): worst relative difference %.3g", worst);
        QVERIFY2(worst < 1e-12, qPrintable(QString::number(worst)));
    }

    void equations_kinematicsAndPotentialFollowConvention() {
        const AcrobotEquations equations;
        const AcrobotPoints down = equations.points(Eigen::Vector4d::Zero());
        QVERIFY((down.elbow - Eigen::Vector2d(0, -1)).norm() < 1e-15);
        QVERIFY((down.tip - Eigen::Vector2d(0, -2)).norm() < 1e-15);
        QVERIFY((down.centre2 - Eigen::Vector2d(0, -1.5)).norm() < 1e-15);
        // Counter-clockwise: theta1 = +90 deg puts the elbow on +x; theta2 = -90 deg then points
        // link 2 straight down again.
        const AcrobotPoints bent = equations.points(Eigen::Vector4d(kPi / 2, -kPi / 2, 0, 0));
        QVERIFY((bent.elbow - Eigen::Vector2d(1, 0)).norm() < 1e-15);
        QVERIFY((bent.tip - Eigen::Vector2d(1, -1)).norm() < 1e-15);
        QVERIFY((bent.centre1 - Eigen::Vector2d(0.5, 0)).norm() < 1e-15);
        // Potential = sum of m g y of the centres of mass; at rest there is no kinetic energy.
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<double> angle(-kPi, kPi);
        for (int i = 0; i < 100; ++i) {
            const Eigen::Vector4d s(angle(rng), angle(rng), 0, 0);
            const AcrobotPoints p = equations.points(s);
            QVERIFY(std::abs(equations.potentialEnergy(s) - 9.8 * (p.centre1.y() + p.centre2.y())) <
                    1e-12);
            QCOMPARE(equations.kineticEnergy(s), 0.0);
        }
        QVERIFY(std::abs(equations.energy(Eigen::Vector4d::Zero()) + 19.6) < 1e-12);
    }

    void equations_kineticEnergyMatchesPointVelocities() {
        // Brute force: 1/2 m v^2 of each centre (central differences of the kinematics) plus
        // 1/2 I w^2 of each link, against the mass-matrix form (I about the centre of mass).
        const AcrobotEquations equations;
        std::mt19937_64 rng(11);
        std::uniform_real_distribution<double> angle(-kPi, kPi);
        std::uniform_real_distribution<double> rate(-5.0, 5.0);
        double worst = 0.0;
        for (int i = 0; i < 200; ++i) {
            const Eigen::Vector4d s(angle(rng), angle(rng), rate(rng), rate(rng));
            const double h = 1e-6;
            Eigen::Vector4d ahead = s;
            Eigen::Vector4d behind = s;
            ahead.head<2>() += h * s.tail<2>();
            behind.head<2>() -= h * s.tail<2>();
            const AcrobotPoints pa = equations.points(ahead);
            const AcrobotPoints pb = equations.points(behind);
            const Eigen::Vector2d v1 = (pa.centre1 - pb.centre1) / (2 * h);
            const Eigen::Vector2d v2 = (pa.centre2 - pb.centre2) / (2 * h);
            const double w1 = s[2];
            const double w2 = s[2] + s[3];
            const double brute =
                0.5 * (v1.squaredNorm() + v2.squaredNorm()) + 0.5 * (w1 * w1 + w2 * w2);
            worst = std::max(worst, std::abs(brute - equations.kineticEnergy(s)));
        }
        qInfo("kinetic energy vs point velocities: worst difference %.3g J", worst);
        QVERIFY2(worst < 1e-6, qPrintable(QString::number(worst)));
    }

    void equations_rk4ConservesEnergyAtFineStep() {
        const AcrobotEquations equations;
        Eigen::Vector4d s(1.2, 0.8, 0.0, 0.0);
        const double e0 = equations.energy(s);
        double worst = 0.0;
        for (int k = 0; k < 400; ++k) {  // 10 s of a chaotic swing
            s = equations.integrate(s, Eigen::Vector2d::Zero(), 0.025, 1e-4);
            worst = std::max(worst, std::abs(equations.energy(s) - e0));
        }
        qInfo("RK4 at 1e-4 s, 10 s unactuated: max |E - E0| = %.3g J (E0 = %.3f J)", worst, e0);
        QVERIFY2(worst < 1e-9, qPrintable(QString::number(worst)));
    }

    void equations_constantTorqueWorkEqualsEnergyGain() {
        // Held torques are conservative: E(T) - E(0) = tau . (q(T) - q(0)). A wrong generalised
        // force mapping (tau2 acting on link 2's absolute angle, say) breaks this.
        const AcrobotEquations equations;
        const Eigen::Vector2d tau(3.0, -2.0);
        const Eigen::Vector4d s0(0.3, -0.4, 0.5, 1.0);
        const Eigen::Vector4d s1 = equations.integrate(s0, tau, 2.0, 1e-4);
        const double gain = equations.energy(s1) - equations.energy(s0);
        const double work = tau.dot(s1.head<2>() - s0.head<2>());
        qInfo("held torque over 2 s: energy gain %.6f J, work %.6f J, difference %.3g J", gain,
              work, gain - work);
        QVERIFY(std::abs(gain) > 0.1);
        QVERIFY2(std::abs(gain - work) < 1e-9, qPrintable(QString::number(gain - work)));
    }

    // --- the Box2D plant against the equations ------------------------------------------------

    void box2d_agreesWithEquations_smallSwingOverSeconds() {
        Acrobot plant;
        const Agreement a = compare(plant, Eigen::Vector4d(0.1, -0.05, 0.0, 0.0), smallTorque, 320);
        qInfo(
            "Box2D vs RK4, small swing 8 s: max angle error %.3g rad, rate error %.3g rad/s, "
            "pin gap %.3g m",
            a.angle, a.rate, a.gap);
        // Measured 2.8e-3 rad and 4.5e-3 rad/s (first-order error of the 2.5 ms physics step).
        QVERIFY2(a.angle < 5e-3, qPrintable(QString::number(a.angle)));
        QVERIFY2(a.rate < 8e-3, qPrintable(QString::number(a.rate)));
    }

    void box2d_agreesWithEquations_largeSwing() {
        Acrobot plant;
        const Agreement a = compare(plant, kLargeStart, largeTorque, 60);
        qInfo(
            "Box2D vs RK4, large swing 1.5 s: max angle error %.3g rad, rate error %.3g rad/s, "
            "pin gap %.3g m",
            a.angle, a.rate, a.gap);
        // Measured 7.5e-3 rad, 2.5e-2 rad/s and a 1.1e-4 m pin gap.
        QVERIFY2(a.angle < 0.015, qPrintable(QString::number(a.angle)));
        QVERIFY2(a.rate < 0.05, qPrintable(QString::number(a.rate)));
        QVERIFY2(a.gap < 5e-4, qPrintable(QString::number(a.gap)));
    }

    void box2d_elbowOnlyAgreesWithBookAcrobot() {
        AcrobotParameters parameters;
        parameters.elbowOnly = true;
        Acrobot plant(parameters);
        // tau1 is asked for throughout but must be forced to 0: the book's underactuated arm.
        const TorqueProgram torque = [](int k) {
            return Eigen::Vector2d(5.0, 4.0 * std::sin(0.1 * k));
        };
        const AcrobotEquations equations;
        Eigen::Vector4d reference(0.4, 0.3, 0.0, 0.0);
        plant.resetTo(reference);
        double angle = 0.0;
        double rate = 0.0;
        for (int k = 0; k < 120; ++k) {
            const Eigen::VectorXd s = plant.step(torque(k));
            QCOMPARE(plant.appliedTorque()[0], 0.0);
            const Eigen::Vector2d tau(0.0, torque(k)[1]);
            reference = equations.integrate(reference, tau, 0.025, 1e-4);
            angle = std::max(
                {angle, std::abs(wrap(s[0] - reference[0])), std::abs(wrap(s[1] - reference[1]))});
            rate = std::max({rate, std::abs(s[2] - reference[2]), std::abs(s[3] - reference[3])});
        }
        qInfo("Box2D vs RK4, elbow only 3 s: max angle error %.3g rad, rate error %.3g rad/s",
              angle, rate);
        // Measured 1.7e-2 rad and 2.3e-2 rad/s.
        QVERIFY2(angle < 0.035, qPrintable(QString::number(angle)));
        QVERIFY2(rate < 0.05, qPrintable(QString::number(rate)));
    }

    void box2d_convergesToEquationsAsStepShrinks() {
        // What is left of the disagreement is Box2D's first-order time step, not a modelling
        // error: halving the physics step halves it (a wrong inertia or anchor would not shrink).
        std::vector<double> errors;
        for (int substeps : {10, 20, 40}) {
            SimulationTiming timing;
            timing.physicsSubsteps = substeps;
            Acrobot plant({}, timing);
            const Agreement a = compare(plant, kLargeStart, largeTorque, 60);
            errors.push_back(a.angle);
            qInfo(
                "large swing, %d substeps (h = %.3g s): max angle error %.3g rad, rate %.3g rad/s",
                substeps, timing.physicsStep(), a.angle, a.rate);
        }
        for (std::size_t i = 1; i < errors.size(); ++i) {
            const double ratio = errors[i] / errors[i - 1];
            QVERIFY2(ratio > 0.35 && ratio < 0.65, qPrintable(QString::number(ratio)));
        }
    }

    void box2d_energyDriftUnactuatedIsBounded() {
        // Box2D integrates semi-implicitly (symplectic Euler) in float and projects the velocities
        // onto the pin constraints each step; that projection dissipates energy at a rate of
        // order h. Measured at 400 Hz over 10 s from E0 - E_rest = 16.3 J: -0.47 J (2.9 %), and
        // about half that at twice the rate.
        double final = 0.0;
        double finalFine = 0.0;
        const double drift = energyDrift(10, 10.0, &final);
        const double driftFine = energyDrift(20, 10.0, &finalFine);
        qInfo(
            "Box2D unactuated 10 s: max |E - E0| = %.3g J at 400 Hz (final %.3g J), "
            "%.3g J at 800 Hz (final %.3g J)",
            drift, final, driftFine, finalFine);
        QVERIFY2(drift < 0.7, qPrintable(QString::number(drift)));
        QVERIFY2(final < 0.0, "the arm gained energy: the integration is unstable");
        const double ratio = driftFine / drift;
        QVERIFY2(ratio > 0.35 && ratio < 0.7, qPrintable(QString::number(ratio)));
    }

    // --- the plant's contract -------------------------------------------------------------------

    void info_describesTheAcrobot() {
        const Acrobot plant;
        const PlantInfo& info = plant.info();
        QCOMPARE(info.name, QStringLiteral("acrobot"));
        QCOMPARE(info.stateNames, QStringList({"theta1", "theta2", "dtheta1", "dtheta2"}));
        QCOMPARE(info.stateUnits, QStringList({"rad", "rad", "rad/s", "rad/s"}));
        QCOMPARE(info.actionNames, QStringList({"tau1", "tau2"}));
        QCOMPARE(info.actionUnits, QStringList({"N m", "N m"}));
        QCOMPARE(info.actionLower, Eigen::VectorXd(Eigen::Vector2d(-10.0, -10.0)));
        QCOMPARE(info.actionUpper, Eigen::VectorXd(Eigen::Vector2d(10.0, 10.0)));
        QCOMPARE(info.angleIndices, std::vector<int>({0, 1}));
        QVERIFY(!info.pose.has_value());
        AcrobotParameters elbowOnly;
        elbowOnly.elbowOnly = true;
        const PlantInfo under = Acrobot::describe(elbowOnly);
        QCOMPARE(under.actionDimension(), 2);
        QCOMPARE(under.actionLower[0], 0.0);
        QCOMPARE(under.actionUpper[0], 0.0);
        QCOMPARE(under.actionUpper[1], 10.0);
    }

    void reset_nominalStartHangsAtRest() {
        Acrobot plant;
        const Eigen::VectorXd s0 = plant.reset(42, Perturbation::none());
        QCOMPARE(s0, Eigen::VectorXd(Eigen::Vector4d::Zero()));
        QCOMPARE(plant.time(), 0.0);
        QVERIFY(plant.atRest());
        Eigen::VectorXd s;
        for (int k = 0; k < 40; ++k) {
            s = plant.step(Eigen::Vector2d::Zero());
        }
        QVERIFY2(s.cwiseAbs().maxCoeff() < 1e-9, "the hanging arm moved by itself");
        QVERIFY(plant.atRest());
        QVERIFY(std::abs(plant.time() - 1.0) < 1e-12);
        plant.step(Eigen::Vector2d(0.0, 5.0));
        QVERIFY(!plant.atRest());
    }

    void reset_realisticPerturbationIsSmallAndSeeded() {
        Acrobot plant;
        QSet<double> firstAngles;
        for (std::uint64_t seed = 1; seed <= 20; ++seed) {
            const Eigen::VectorXd s = plant.reset(seed, Perturbation::realistic());
            // 0.05 rad std: within 5 sigma, at rest.
            QVERIFY(s.head<2>().cwiseAbs().maxCoeff() < 0.25);
            QVERIFY(s.head<2>().cwiseAbs().maxCoeff() > 0.0);
            QCOMPARE(s.tail<2>(), Eigen::VectorXd(Eigen::Vector2d::Zero()));
            const AcrobotConstants& c = plant.trialEquations().constants;
            QVERIFY(c.m2 != 1.0 && std::abs(c.m2 - 1.0) < 0.25);
            QCOMPARE(c.I2, c.m2);  // mass and inertia scale together
            QCOMPARE(c.m1, 1.0);
            QVERIFY(plant.trialJointDamping() >= 0.0 && plant.trialJointDamping() < 0.25);
            firstAngles.insert(s[0]);
        }
        QCOMPARE(firstAngles.size(), 20);
        // resetTo goes back to the nominal arm.
        plant.resetTo(Eigen::Vector4d::Zero());
        QCOMPARE(plant.trialEquations().constants.m2, 1.0);
        QCOMPARE(plant.trialJointDamping(), 0.0);
    }

    void reset_sameSeedGivesIdenticalTrajectory_differentSeedsDiffer() {
        Acrobot a;
        Acrobot b;
        const auto first = run(a, 1234, 200);
        const auto again = run(b, 1234, 200);
        const auto reused = run(a, 1234, 200);  // nothing of the previous trial leaks
        const auto other = run(b, 1235, 200);
        QCOMPARE(first.size(), again.size());
        bool differs = false;
        for (std::size_t k = 0; k < first.size(); ++k) {
            QVERIFY2(first[k] == again[k], qPrintable(QString("step %1").arg(k)));
            QVERIFY2(first[k] == reused[k], qPrintable(QString("step %1").arg(k)));
            differs = differs || (first[k] - other[k]).cwiseAbs().maxCoeff() > 1e-3;
        }
        QVERIFY(differs);
    }

    void step_clampsTorquesToLimits() {
        Acrobot plant;
        Acrobot reference;
        const Eigen::Vector4d start(0.2, -0.1, 0.3, 0.0);
        plant.resetTo(start);
        reference.resetTo(start);
        for (int k = 0; k < 20; ++k) {
            const Eigen::VectorXd s = plant.step(Eigen::Vector2d(100.0, -35.0));
            QCOMPARE(plant.appliedTorque(), Eigen::Vector2d(10.0, -10.0));
            QCOMPARE(s, reference.step(Eigen::Vector2d(10.0, -10.0)));
        }
        // A broken command drives nothing.
        plant.step(Eigen::Vector2d(std::numeric_limits<double>::quiet_NaN(),
                                   std::numeric_limits<double>::infinity()));
        QCOMPARE(plant.appliedTorque(), Eigen::Vector2d(0.0, 0.0));
        QVERIFY(plant.state().allFinite());

        // Elbow only: the shoulder torque is forced to 0.
        AcrobotParameters elbowOnly;
        elbowOnly.elbowOnly = true;
        Acrobot under(elbowOnly);
        under.resetTo(start);
        under.step(Eigen::Vector2d(5.0, 3.0));
        QCOMPARE(under.appliedTorque(), Eigen::Vector2d(0.0, 3.0));

        // With actuator noise the torque varies but never leaves the limits.
        Acrobot noisy;
        noisy.reset(9, Perturbation{0.0, 0.0, 3.0});
        double spread = 0.0;
        for (int k = 0; k < 400; ++k) {
            noisy.step(Eigen::Vector2d(10.0, -5.0));
            const Eigen::Vector2d u = noisy.appliedTorque();
            QVERIFY(u[0] <= 10.0 && u[0] >= -10.0);
            spread = std::max(spread, std::abs(u[1] + 5.0));
        }
        QVERIFY(spread > 0.0 && spread < 5.0);  // 0.6 N m std at level 3
    }

    void step_rejectsWrongActionSize() {
        Acrobot plant;
        QVERIFY(throwsInvalidArgument([&] { plant.step(Eigen::VectorXd(1)); }));
        QVERIFY(throwsInvalidArgument([&] { plant.step(Eigen::VectorXd(3)); }));
    }

    void resetTo_rejectsWrongSizeOrNonFinite() {
        Acrobot plant;
        QVERIFY(throwsInvalidArgument([&] { plant.resetTo(Eigen::VectorXd(3)); }));
        QVERIFY(throwsInvalidArgument([&] { plant.resetTo(Eigen::VectorXd::Zero(5)); }));
        Eigen::VectorXd nan = Eigen::Vector4d::Zero();
        nan[2] = std::numeric_limits<double>::quiet_NaN();
        QVERIFY(throwsInvalidArgument([&] { plant.resetTo(nan); }));
        Eigen::VectorXd inf = Eigen::Vector4d::Zero();
        inf[0] = std::numeric_limits<double>::infinity();
        QVERIFY(throwsInvalidArgument([&] { plant.resetTo(inf); }));
        QVERIFY(!throwsInvalidArgument([&] { plant.resetTo(Eigen::Vector4d::Zero()); }));
    }

    void resetTo_setsStateExactlyWithPinsClosed() {
        Acrobot plant;
        plant.step(Eigen::Vector2d(3.0, 3.0));
        const Eigen::Vector4d wanted(2.0, -1.0, 1.5, -2.5);
        const Eigen::VectorXd s = plant.resetTo(wanted);
        // Box2D stores floats: 1e-6 is a few float ulps.
        QVERIFY2((s - wanted).cwiseAbs().maxCoeff() < 1e-6,
                 qPrintable(QString::number((s - wanted).cwiseAbs().maxCoeff())));
        QVERIFY(plant.jointGap() < 1e-6);
        QCOMPARE(plant.time(), 0.0);
        // Angles come back wrapped to (-pi, pi].
        const Eigen::VectorXd w = plant.resetTo(Eigen::Vector4d(4.0, -4.0, 0.0, 0.0));
        QVERIFY(std::abs(w[0] - (4.0 - 2 * kPi)) < 1e-6);
        QVERIFY(std::abs(w[1] - (2 * kPi - 4.0)) < 1e-6);
    }

    void step_keepsAnglesWrappedAndPinsClosedWhileSpinning() {
        // Full torque on both joints for 10 s spins the arm up to tens of rad/s.
        Acrobot plant;
        plant.resetTo(Eigen::Vector4d::Zero());
        double fastest = 0.0;
        double gap = 0.0;
        for (int k = 0; k < 400; ++k) {
            const Eigen::VectorXd s = plant.step(Eigen::Vector2d(10.0, 10.0));
            QVERIFY(s.allFinite());
            QVERIFY(s[0] > -kPi && s[0] <= kPi && s[1] > -kPi && s[1] <= kPi);
            fastest = std::max({fastest, std::abs(s[2]), std::abs(s[3])});
            gap = std::max(gap, plant.jointGap());
        }
        qInfo("spinning 10 s at full torque: fastest %.1f rad/s, largest pin gap %.3g m", fastest,
              gap);
        QVERIFY(fastest > 10.0);
        QVERIFY2(gap < 5e-3, qPrintable(QString::number(gap)));  // Box2D's linear slop
    }

    // --- the scripted demonstrator
    // ----------------------------------------------------------------

    void demonstrator_recordsValidNonTrivialSwing() {
        const prisca::core::Demonstration d = AcrobotDemonstrator::record(5);
        QCOMPARE(d.validate(), QString());
        QCOMPARE(d.plant, QStringLiteral("acrobot"));
        QCOMPARE(d.dt, 0.025);
        QCOMPARE(d.length(), 320);  // 8 s at 40 Hz
        QCOMPARE(d.stateDimension(), 4);
        QCOMPARE(d.actionDimension(), 2);
        const Eigen::VectorXd th1 = d.states.col(0);
        const Eigen::VectorXd th2 = d.states.col(1);
        qInfo(
            "demonstration: shoulder %.2f..%.2f rad, elbow %.2f..%.2f rad, |tau| <= %.2f N m, "
            "shoulder-elbow correlation %.2f",
            th1.minCoeff(), th1.maxCoeff(), th2.minCoeff(), th2.maxCoeff(),
            d.actions.cwiseAbs().maxCoeff(), correlation(th1, th2));
        // A real swing both ways (> 30 deg at the shoulder, > 15 deg at the elbow) ...
        QVERIFY(th1.maxCoeff() > 0.52 && th1.minCoeff() < -0.52);
        QVERIFY(th2.cwiseAbs().maxCoeff() > 0.26);
        // ... with the elbow counter-swinging ...
        QVERIFY(correlation(th1, th2) < -0.5);
        // ... that grows: the last second swings wider than the second one.
        QVERIFY(th1.tail(40).cwiseAbs().maxCoeff() >
                3.0 * th1.segment(40, 40).cwiseAbs().maxCoeff());
        // ... within the limits, and not a bang-bang.
        QVERIFY(d.actions.cwiseAbs().maxCoeff() <= 10.0);
        QVERIFY(d.actions.cwiseAbs().maxCoeff() > 1.0);
        QVERIFY((d.actions.array().abs() >= 10.0).count() < d.length() / 10);
    }

    void demonstrator_isSeededAndReplaysOnTheNominalPlant() {
        const prisca::core::Demonstration d = AcrobotDemonstrator::record(5);
        const prisca::core::Demonstration same = AcrobotDemonstrator::record(5);
        const prisca::core::Demonstration other = AcrobotDemonstrator::record(6);
        QCOMPARE(d.states, same.states);
        QCOMPARE(d.actions, same.actions);
        const double jitter = (d.actions - other.actions).cwiseAbs().maxCoeff();
        const double apart = (d.states - other.states).cwiseAbs().maxCoeff();
        qInfo("demonstrations of seeds 5 and 6: torques differ by up to %.3f N m, states by %.3f",
              jitter, apart);
        QVERIFY(jitter > 0.05);
        QVERIFY(apart < 0.3);  // the same swing, another hand
        // The recorded actions played open loop on a nominal arm give the recorded states.
        Acrobot plant;
        Eigen::VectorXd s = plant.reset(5, Perturbation::none());
        for (int k = 0; k < d.length(); ++k) {
            QCOMPARE(s, Eigen::VectorXd(d.states.row(k).transpose()));
            s = plant.step(d.actions.row(k).transpose());
        }
    }
};

QTEST_APPLESS_MAIN(TestAcrobot)
#include "test_acrobot.moc"
