#pragma once

#include "core/DeviationModel.h"

#include <Eigen/Core>

#include <QString>
#include <QStringList>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace prisca::sim {

/// The clocks of a simulation. No wall clock is ever read inside sim.
struct SimulationTiming {
    double controlPeriod = 0.025;  ///< one control step [s] (40 Hz)
    int physicsSubsteps = 10;      ///< physics steps per control period, >= 1 (400 Hz)

    /// The physics step [s].
    double physicsStep() const { return controlPeriod / physicsSubsteps; }
};

/// How far a trial departs from the nominal plant. Each field scales the plant's own
/// "realistic lab" level (documented by each plant): 0 is the nominal plant, 1 the realistic
/// level, 2 twice that. Everything drawn from it comes from the trial seed.
struct Perturbation {
    /// How the parameter variation is spread over a run's trials.
    enum class Model {
        /// Every trial draws its own variation, mean zero: nothing persists from trial to trial.
        Trial,
        /// A lab session (one day at the rig): the mismatch between the nominal and the real
        /// plant (steering trim, throttle gain, floor friction, ...) is drawn once for the day,
        /// a drift (the battery sagging) moves it trial by trial, and each trial adds a little
        /// variation of its own. The initial offsets and actuator noise stay per trial. Each
        /// plant documents its magnitudes.
        Session
    };
    double initialState = 0.0;   ///< initial pose / state offsets
    double parameters = 0.0;     ///< parameter variation (friction, gains, trim, wind, ...)
    double actuatorNoise = 0.0;  ///< per-step noise on the applied action
    Model model = Model::Trial;
    std::uint64_t day = 0;  ///< Session: the day's seed (a run's seed), drawing its mismatch
    int trialIndex = 0;     ///< Session: the trial's place in the day, 0 first (the drift)

    static Perturbation none() { return {}; }
    static Perturbation realistic() { return {1.0, 1.0, 1.0}; }
    /// What a demonstration recorded on a session day's plant meets: the day's mismatch at
    /// `parameters` level before its first trial, no offset, no actuator noise.
    static Perturbation dayOf(std::uint64_t day, double parameters = 1.0) {
        Perturbation p;
        p.parameters = parameters;
        p.model = Model::Session;
        p.day = day;
        return p;
    }
    bool session() const { return model == Model::Session; }
};

/// "session" or "trial", as the command line and files spell the models.
QString perturbationModelName(Perturbation::Model model);
/// The model of a name; nullopt for another name.
std::optional<Perturbation::Model> perturbationModelFromName(const QString& name);

/// The day's draws of a Session perturbation: unit normals from the day's own stream, the same
/// sequence for every trial of the day (and a plant's draws from it in a fixed order).
class SessionDay {
  public:
    explicit SessionDay(const Perturbation& perturbation);
    /// The next unit-normal draw of the day.
    double normal();
    /// The fraction a quantity has fallen by at this trial when it falls by `perTrial` (per
    /// trial, >= 0) from the day's first trial on: perTrial * trialIndex, at most 0.5.
    double drift(double perTrial) const;

  private:
    std::uint64_t state_;
    int trialIndex_;
};

/// What a plant is: names and units of its state and action, limits, and how its tracking
/// error is formed. Plain data.
struct PlantInfo {
    QString name;                                 ///< its PlantCatalog name, e.g. "slidecar"
    QString description;                          ///< one line for the operator
    QStringList stateNames;                       ///< n names
    QStringList stateUnits;                       ///< n units
    QStringList actionNames;                      ///< m names
    QStringList actionUnits;                      ///< m units
    Eigen::VectorXd actionLower;                  ///< m lower limits
    Eigen::VectorXd actionUpper;                  ///< m upper limits
    std::vector<int> angleIndices;                ///< state components that are angles
    std::optional<core::PlanarPoseIndices> pose;  ///< planar vehicles: x, y, heading
    std::optional<core::BodyVelocityIndices> bodyVelocity;  ///< and their body velocities
    /// Car-like steering: the steering turns the heading at the signed forward speed (so the
    /// other way in reverse), unlike a differential drive, whose turn rate is its own command.
    bool steersThroughTravel = false;

    int stateDimension() const { return static_cast<int>(stateNames.size()); }
    int actionDimension() const { return static_cast<int>(actionNames.size()); }
    /// The tracking-error model of this plant (body frame for vehicles, wrapped angles).
    core::DeviationModel deviationModel() const;

    /// The largest magnitude a state component may start from, by its unit: 10 km and 10^4 rad
    /// for positions and angles, 1000 m/s and 1000 rad/s for rates. Far beyond any lab, and
    /// well inside what the physics engine's single-precision bodies hold.
    double stateBound(int component) const;
    /// Empty when the state has n components, each finite and within stateBound; else what is
    /// wrong, naming the component, its value and its range ("psi = 1e+300 rad is outside
    /// [-10000, 10000] rad"). Every plant's resetTo() checks its state with it.
    QString stateProblem(const Eigen::VectorXd& state) const;
};

/// One simulated robot (OMPL-style narrow interface). Built on Box2D; SI units inside.
/// A Plant is single-threaded: one instance per trial. It never draws and never emits signals.
class Plant {
  public:
    virtual ~Plant() = default;

    virtual const PlantInfo& info() const = 0;
    virtual const SimulationTiming& timing() const = 0;

    /// Starts a new trial from the plant's nominal start, with perturbations, initial offsets and
    /// noise streams drawn from the seed. Returns the state.
    virtual Eigen::VectorXd reset(std::uint64_t seed, const Perturbation& perturbation) = 0;
    /// Starts from exactly this state (size n) with nominal parameters and no noise.
    /// Throws std::invalid_argument for a wrong size or a non-finite value.
    virtual Eigen::VectorXd resetTo(const Eigen::VectorXd& state) = 0;
    /// Applies the action (size m; clamped to the limits, then perturbed as the trial says) for
    /// one control period. Returns the new state. Throws std::invalid_argument on a wrong size.
    virtual Eigen::VectorXd step(const Eigen::VectorXd& action) = 0;
    /// After resetTo: runs these commands (one per control period, oldest first) through the
    /// actuators alone (dead times, servo), not the body, so the commands of the last steps are
    /// still in flight as they would be on the plant (identification restarts the plant at
    /// recorded states). Plants without actuator dynamics ignore it.
    virtual void primeActuators(const std::vector<Eigen::VectorXd>& recentActions) {
        (void)recentActions;
    }
    /// What the plant carries between steps beyond its state and its actuators, which a
    /// restart at a recorded state cannot read from it (the slide-car: whether each axle's
    /// tyres slide, and the load the last step's acceleration moved between the axles): read
    /// from one run of a model to carry into a restart of another (identification's segments).
    /// Empty for plants without it; setHiddenState after resetTo, ignoring a wrong size.
    virtual std::vector<double> hiddenState() const { return {}; }
    virtual void setHiddenState(const std::vector<double>& hidden) { (void)hidden; }
    /// A model's estimate of the steering trim its car has (share of full lock), added to every
    /// steering command; kept over resetTo and copied by clone. False: the plant has no
    /// steering to trim.
    virtual bool setSteeringOffset(double offset) {
        (void)offset;
        return false;
    }

    /// An independent copy of this trial's plant as it is now: the same perturbed parameters,
    /// wind, commands in flight and state, for a planner that simulates ahead (the oracle).
    /// With actuatorNoise false the copy applies its actions exactly (the future noise of the
    /// trial is not something a planner can know); true keeps the noise and its stream.
    virtual std::unique_ptr<Plant> clone(bool actuatorNoise = false) const = 0;

    /// The current state (size n).
    virtual Eigen::VectorXd state() const = 0;
    /// Simulated time since the last reset [s].
    virtual double time() const = 0;
    /// True once the plant is at rest (vehicles: speed and yaw rate below small thresholds).
    virtual bool atRest() const { return false; }
    /// The air's velocity over the ground now [m/s], world frame, for plants that fly in wind
    /// (for display; the controller never sees it). Empty for the others.
    virtual std::optional<Eigen::Vector2d> windVelocity() const { return std::nullopt; }
};

/// A well-mixed 64-bit seed for stream `stream` of trial seed `seed` (splitmix64), so that
/// neighbouring seeds give unrelated random streams.
std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t stream);

/// A controller that is handed the trial's plant itself (the oracle, which plans on copies of it).
/// EpisodeStepper attaches the plant after resetting it for a trial and before resetting the
/// controller; a controller that is not PlantAware never sees the plant.
class PlantAware {
  public:
    virtual ~PlantAware() = default;
    /// The plant of the trial about to start (outlives the trial); nullptr detaches.
    virtual void attachPlant(const Plant* plant) = 0;
};

}  // namespace prisca::sim
