#pragma once

#include "core/Demonstration.h"
#include "sim/plants/Plant.h"

#include <vector>

namespace prisca::sim {

/// Collects a demonstration sample by sample: row k holds the state s_k observed at t_k and the
/// action u_k applied from t_k on (docs/architecture.md "Demonstration" CSV). Used by the scripted
/// demonstrators and by recording in the application.
class DemonstrationRecorder {
  public:
    /// @param info  names, units and the plant name of the demonstration
    /// @param dt    control period [s]
    DemonstrationRecorder(const PlantInfo& info, double dt);

    /// Appends one sample (sizes n and m).
    void record(const Eigen::VectorXd& state, const Eigen::VectorXd& action);
    /// Number of samples so far.
    int size() const { return static_cast<int>(states_.size()); }
    /// The demonstration so far (t_k = k dt).
    core::Demonstration demonstration() const;

  private:
    PlantInfo info_;
    double dt_;
    std::vector<Eigen::VectorXd> states_;
    std::vector<Eigen::VectorXd> actions_;
};

}  // namespace prisca::sim
