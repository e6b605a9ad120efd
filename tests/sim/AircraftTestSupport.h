#pragma once

// What the aircraft tests share: flights to run and their statistics.

#include "sim/demonstrations/AircraftDemonstrator.h"
#include "sim/plants/GustyWind.h"
#include "sim/plants/PlanarAircraft.h"

#include <Eigen/Dense>

#include <QtTest>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

using namespace prisca;
using sim::PlanarAircraft;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;

inline Eigen::VectorXd cruiseState(double x = 0.0, double y = 0.0, double psi = 0.0,
                                   double u = 17.0, double v = 0.0, double r = 0.0) {
    Eigen::VectorXd s(6);
    s << x, y, psi, u, v, r;
    return s;
}

inline double trimThrottle() {
    return PlanarAircraft::trimThrottle(sim::PlanarAircraftParameters{}, 17.0);
}

// Flies the aircraft for the given time with a constant action; returns every state, the start
// included.
inline std::vector<Eigen::VectorXd> fly(PlanarAircraft& aircraft, double seconds, double throttle,
                                        double rudder) {
    std::vector<Eigen::VectorXd> states{aircraft.state()};
    const int steps = static_cast<int>(std::lround(seconds / aircraft.timing().controlPeriod));
    for (int k = 0; k < steps; ++k) {
        states.push_back(aircraft.step(Eigen::Vector2d(throttle, rudder)));
    }
    return states;
}

inline double groundSpeed(const Eigen::VectorXd& s) {
    return std::hypot(s[3], s[4]);
}

// Least-squares circle through the points (Kasa fit): returns the radius [m].
inline double fittedRadius(const std::vector<Eigen::VectorXd>& states, int first) {
    const int n = static_cast<int>(states.size()) - first;
    Eigen::MatrixXd A(n, 3);
    Eigen::VectorXd b(n);
    for (int i = 0; i < n; ++i) {
        const double x = states[first + i][0];
        const double y = states[first + i][1];
        A.row(i) << 2.0 * x, 2.0 * y, 1.0;
        b[i] = x * x + y * y;
    }
    const Eigen::Vector3d c = A.colPivHouseholderQr().solve(b);
    return std::sqrt(c[2] + c[0] * c[0] + c[1] * c[1]);
}

// Sample autocorrelation of a series at a lag (in samples).
inline double autocorrelation(const std::vector<double>& xs, int lag) {
    const int n = static_cast<int>(xs.size());
    double mean = 0.0;
    for (double x : xs) {
        mean += x;
    }
    mean /= n;
    double variance = 0.0;
    double covariance = 0.0;
    for (int i = 0; i < n; ++i) {
        variance += (xs[i] - mean) * (xs[i] - mean);
        if (i + lag < n) {
            covariance += (xs[i] - mean) * (xs[i + lag] - mean);
        }
    }
    return covariance / variance;
}

struct GustStatistics {
    double rms[2];
    double correlationAtTau[2];
    double correlationTime[2];  // from the autocorrelation at a 1 s lag [s]
    double crossCorrelation;
};

inline GustStatistics measureGusts(const sim::GustyWindParameters& parameters, double dt,
                                   double duration, std::uint64_t seed) {
    sim::GustyWind wind(parameters, seed);
    const int n = static_cast<int>(duration / dt);
    std::vector<double> gx(n), gy(n);
    for (int i = 0; i < n; ++i) {
        gx[i] = wind.gust().x();
        gy[i] = wind.gust().y();
        wind.advance(dt);
    }
    GustStatistics g{};
    double cross = 0.0;
    for (int i = 0; i < n; ++i) {
        cross += gx[i] * gy[i];
    }
    const int lagTau = static_cast<int>(std::lround(parameters.gustTimeConstant / dt));
    const int lagSecond = static_cast<int>(std::lround(1.0 / dt));
    const std::vector<double>* series[2] = {&gx, &gy};
    double sumSquares[2] = {0.0, 0.0};
    for (int a = 0; a < 2; ++a) {
        for (double x : *series[a]) {
            sumSquares[a] += x * x;
        }
        g.rms[a] = std::sqrt(sumSquares[a] / n);
        g.correlationAtTau[a] = autocorrelation(*series[a], lagTau);
        g.correlationTime[a] = -(lagSecond * dt) / std::log(autocorrelation(*series[a], lagSecond));
    }
    g.crossCorrelation = cross / std::sqrt(sumSquares[0] * sumSquares[1]);
    return g;
}

}  // namespace
