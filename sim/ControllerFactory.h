#pragma once

#include "PlantProfile.h"
#include "core/Controller.h"

#include <QStringList>

#include <memory>

namespace prisca::sim {

/// Builds the controller of a method for a plant, all from the same profile (features,
/// limits, matching) so that methods differ only in what they are.
class ControllerFactory {
  public:
    /// Method names as the command line spells them:
    /// prisca pgsd pegasus pd pd-selected pd-h pd-lsd pd-h-lsd playback.
    static QStringList methods();
    /// True for a name in methods().
    static bool isMethod(const QString& method);

    /// The controller of `method`.
    /// @param fittedB  B = B_v (.) B~ (m x n) from the fit, used by PRISCA
    /// @param theta    policy parameters for "pegasus" (p x m; zero when null). "pd-selected"
    ///                 uses profile.pd, so pass a profile whose gains were selected.
    /// Throws std::invalid_argument for an unknown method or inconsistent shapes.
    static std::unique_ptr<core::Controller> create(
        const QString& method, const PlantProfile& profile,
        std::shared_ptr<const core::Demonstration> demonstration, const Eigen::MatrixXd& fittedB,
        const Eigen::MatrixXd* theta = nullptr);
};

}  // namespace prisca::sim
