#include "Demonstration.h"

#include <cmath>

namespace prisca::core {

QString Demonstration::validate() const {
    const int T = length();
    if (T == 0) {
        return QStringLiteral("the demonstration has no samples");
    }
    if (!(dt >= kMinDt && dt <= kMaxDt)) {
        return QStringLiteral("dt must be from %1 to %2 s, got %3").arg(kMinDt).arg(kMaxDt).arg(dt);
    }
    if (time.size() != T || actions.rows() != T) {
        return QStringLiteral("time (%1), states (%2) and actions (%3) differ in length")
            .arg(time.size())
            .arg(T)
            .arg(actions.rows());
    }
    if (stateNames.size() != stateDimension() || stateUnits.size() != stateDimension()) {
        return QStringLiteral("%1 state columns but %2 names and %3 units")
            .arg(stateDimension())
            .arg(stateNames.size())
            .arg(stateUnits.size());
    }
    if (actionNames.size() != actionDimension() || actionUnits.size() != actionDimension()) {
        return QStringLiteral("%1 action columns but %2 names and %3 units")
            .arg(actionDimension())
            .arg(actionNames.size())
            .arg(actionUnits.size());
    }
    for (int k = 0; k < T; ++k) {
        if (!(std::abs(time[k]) <= kMaxAbsTime)) {
            return QStringLiteral("time at sample %1 is not a number within +-%2 s")
                .arg(k)
                .arg(kMaxAbsTime);
        }
        if (k > 0 && !(time[k] > time[k - 1])) {
            return QStringLiteral("time is not strictly increasing at sample %1 (%2 after %3)")
                .arg(k)
                .arg(time[k])
                .arg(time[k - 1]);
        }
        for (int c = 0; c < stateDimension(); ++c) {
            if (!(std::abs(states(k, c)) <= kMaxAbsValue)) {
                return QStringLiteral("state '%1' at sample %2 is not a number within +-%3")
                    .arg(stateNames.value(c))
                    .arg(k)
                    .arg(kMaxAbsValue);
            }
        }
        for (int c = 0; c < actionDimension(); ++c) {
            if (!(std::abs(actions(k, c)) <= kMaxAbsValue)) {
                return QStringLiteral("action '%1' at sample %2 is not a number within +-%3")
                    .arg(actionNames.value(c))
                    .arg(k)
                    .arg(kMaxAbsValue);
            }
        }
    }
    return {};
}

}  // namespace prisca::core
