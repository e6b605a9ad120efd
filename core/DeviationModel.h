#pragma once

#include <Eigen/Core>

#include <QString>

#include <optional>
#include <vector>

namespace prisca::core {

/// pi, the one definition every layer uses.
inline constexpr double kPi = 3.14159265358979323846;

/// Wraps an angle to (-pi, pi] [rad]: the one angle wrap of the project.
double wrapAngle(double angle);

/// Indices of a planar pose (x, y, heading) in a state vector.
struct PlanarPoseIndices {
    int x = 0;        ///< world x [m]
    int y = 1;        ///< world y [m]
    int heading = 2;  ///< heading of the body x axis [rad], counter-clockwise from world x
};

/// Indices of a planar vehicle's body-frame velocities in a state vector.
struct BodyVelocityIndices {
    int forward = 3;  ///< along the body x axis [m/s]
    int lateral = 4;  ///< along the body y axis (left) [m/s]
    int yawRate = 5;  ///< heading rate [rad/s]
};

/// How the tracking error e = s (-) s* is formed from a state and its reference.
///
/// Plain components subtract. Angle components subtract and wrap to (-pi, pi]. For planar
/// vehicles the pose (x, y, heading) is expressed in the frame of the desired pose
/// (docs/architecture.md "Body-frame deviation"): the x slot holds the longitudinal error, the y
/// slot the lateral error (positive = left of the desired pose), the heading slot the wrapped
/// heading error. Velocities already in the body frame subtract plainly.
struct DeviationModel {
    int dimension = 0;                      ///< state dimension n
    std::vector<int> angleIndices;          ///< components wrapped to (-pi, pi]
    std::optional<PlanarPoseIndices> pose;  ///< if set, pose error in the desired frame
    /// If set (with pose), the state also holds the body-frame velocities, and the error's own
    /// kinematics are known (kinematics()).
    std::optional<BodyVelocityIndices> bodyVelocity;

    /// e = s (-) reference; both of size n. Writes into out (size n), no allocation.
    void deviation(const Eigen::Ref<const Eigen::VectorXd>& state,
                   const Eigen::Ref<const Eigen::VectorXd>& reference,
                   Eigen::Ref<Eigen::VectorXd> out) const;
    /// Convenience overload returning e.
    Eigen::VectorXd deviation(const Eigen::Ref<const Eigen::VectorXd>& state,
                              const Eigen::Ref<const Eigen::VectorXd>& reference) const;

    /// What the error does by itself, linearised at a reference state: de/dt ~= A e for the
    /// parts fixed by geometry alone. For a planar vehicle with body velocities, the pose error
    /// in the desired frame moves as
    ///     de_x = e_vx - v*_y e_psi + r* e_y,  de_y = e_vy + v*_x e_psi - r* e_x,  de_psi = e_r;
    /// every other entry is 0 (the velocities' own dynamics are the plant's, not geometry).
    /// Writes A (n x n) into out; all zero without pose and body velocities. No allocation.
    void kinematics(const Eigen::Ref<const Eigen::VectorXd>& reference,
                    Eigen::Ref<Eigen::MatrixXd> out) const;

    /// Plain vector difference for every component (no angles, no pose).
    static DeviationModel euclidean(int dimension);
    /// Planar vehicle with pose (x, y, heading) at the given indices.
    static DeviationModel planarVehicle(int dimension, PlanarPoseIndices pose = {});

    /// Empty when consistent; else a description of the first bad index.
    QString validate() const;
};

}  // namespace prisca::core
