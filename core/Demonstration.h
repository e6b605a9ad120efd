#pragma once

#include <QMap>
#include <QString>
#include <QStringList>

#include <Eigen/Core>

namespace prisca::core {

/// One recorded manoeuvre: states and actions sampled at a fixed period.
/// Plain data; copy freely across threads.
struct Demonstration {
    /// What the format can mean (docs/architecture.md "Demonstration" CSV): a sampling period from
    /// 0.1 ms to 10 s, times within +-10^6 s (11.6 days), and every state or action within +-10^6
    /// of its unit (a million metres, radians, newton-metres, ...). Beyond these a number is a
    /// corrupt file, not a manoeuvre, and only overflows the fit of B_v.
    static constexpr double kMinDt = 1e-4;
    static constexpr double kMaxDt = 10.0;
    static constexpr double kMaxAbsTime = 1e6;
    static constexpr double kMaxAbsValue = 1e6;

    QString plant;                    ///< plant identifier, e.g. "slidecar"; empty when unknown
    double dt = 0.025;                ///< sampling (control) period [s]
    QStringList stateNames;           ///< n names, e.g. "x"
    QStringList stateUnits;           ///< n units, e.g. "m" ("1" for dimensionless)
    QStringList actionNames;          ///< m names, e.g. "throttle"
    QStringList actionUnits;          ///< m units
    Eigen::VectorXd time;             ///< T sample times [s], strictly increasing
    Eigen::MatrixXd states;           ///< T x n; row k is the state s*_k
    Eigen::MatrixXd actions;          ///< T x m; row k is the action u*_k applied at time t_k
    QMap<QString, QString> metadata;  ///< further "# key: value" lines, kept verbatim

    /// Number of samples T.
    int length() const { return static_cast<int>(states.rows()); }
    /// State dimension n.
    int stateDimension() const { return static_cast<int>(states.cols()); }
    /// Action dimension m (the paper's L channels).
    int actionDimension() const { return static_cast<int>(actions.cols()); }

    /// Checks shapes, names, finiteness, the bounds above and strictly increasing time.
    /// Returns an empty string when consistent, else a one-line description of the first problem.
    QString validate() const;
};

}  // namespace prisca::core
