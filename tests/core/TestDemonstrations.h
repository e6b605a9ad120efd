#pragma once
// Shared by the core tests: a demonstration with generic names, to be filled in by the test.

#include "core/Demonstration.h"

namespace prisca::test {

/// T samples of n states "s0".."s{n-1}" and m actions "u0".."u{m-1}", all zero, t = k dt.
inline core::Demonstration namedDemonstration(int T, int n, int m, double dt,
                                              const QString& stateUnit = QStringLiteral("1")) {
    core::Demonstration d;
    d.dt = dt;
    for (int c = 0; c < n; ++c) {
        d.stateNames << QStringLiteral("s%1").arg(c);
        d.stateUnits << stateUnit;
    }
    for (int l = 0; l < m; ++l) {
        d.actionNames << QStringLiteral("u%1").arg(l);
        d.actionUnits << QStringLiteral("1");
    }
    d.time = Eigen::VectorXd::LinSpaced(T, 0.0, (T - 1) * dt);
    d.states.setZero(T, n);
    d.actions.setZero(T, m);
    return d;
}

}  // namespace prisca::test
