#pragma once

// PlantParameters' number formats, shared by its sources (PlantParameters.cpp: the keys, ranges
// and plants; PlantParametersFile.cpp: the plant file read and written).

#include <QString>

namespace prisca::sim::parameters {

inline QString number(double v) {
    return QString::number(v, 'g', 10);
}

inline QString withUnit(double v, const QString& unit) {
    return unit == QLatin1String("1") ? number(v) : number(v) + QLatin1Char(' ') + unit;
}

}  // namespace prisca::sim::parameters
