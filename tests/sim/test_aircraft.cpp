// Behaviour of the simulated planar aircraft and its scripted pilot (its wind: test_aircraft_wind).

#include "AircraftTestSupport.h"

class TestAircraft : public QObject {
    Q_OBJECT

  private slots:
    void describesStateActionsAndPose();
    void trimThrottleHoldsSpeedAndHeadingFor20Seconds();
    void throttleAboveTrimSpeedsUpAndBelowSlowsDown();
    void fullLeftRudderTurnsLeftOnAFewTensOfMetresRadius();
    void fullRightRudderMirrorsTheLeftTurn();
    void yawRateKickDecaysWithoutRudder();
    void sideslipDisturbanceDecaysWithoutRudder();
    void sameSeedGivesBitIdenticalTrajectories();
    void differentSeedsGiveDifferentTrajectories();
    void actionsAreClampedToTheirLimits();
    void nonFiniteActionCutsTheEngineAndCentresTheRudder();
    void stepRejectsAWrongSize();
    void resetToSetsThatStateWithoutWind();
    void resetToRejectsBadInput();
    void precisionDoesNotDependOnTheDistanceFromTheOrigin();
    void turnAgreesAcrossPhysicsRates();
    void demonstratorFliesAValidSTurn();
    void demonstratorIsSeededAndSmooth();
};

void TestAircraft::describesStateActionsAndPose() {
    PlanarAircraft aircraft;
    const sim::PlantInfo& info = aircraft.info();
    QCOMPARE(info.name, QStringLiteral("aircraft"));
    QCOMPARE(info.stateNames, QStringList({"x", "y", "psi", "u", "v", "r"}));
    QCOMPARE(info.stateUnits, QStringList({"m", "m", "rad", "m/s", "m/s", "rad/s"}));
    QCOMPARE(info.actionNames, QStringList({"throttle", "rudder"}));
    QCOMPARE(info.actionUnits, QStringList({"1", "1"}));
    QCOMPARE(info.actionLower, Eigen::VectorXd(Eigen::Vector2d(0.0, -1.0)));
    QCOMPARE(info.actionUpper, Eigen::VectorXd(Eigen::Vector2d(1.0, 1.0)));
    QCOMPARE(info.angleIndices, std::vector<int>{2});
    QVERIFY(info.pose.has_value());
    QCOMPARE(info.pose->x, 0);
    QCOMPARE(info.pose->y, 1);
    QCOMPARE(info.pose->heading, 2);
    QVERIFY(info.deviationModel().validate().isEmpty());
    const Eigen::VectorXd s = aircraft.reset(1, sim::Perturbation::none());
    QCOMPARE(s.size(), 6);
    QCOMPARE(s, cruiseState());
    QCOMPARE(aircraft.time(), 0.0);
    aircraft.step(Eigen::Vector2d(0.5, 0.0));
    QVERIFY(std::abs(aircraft.time() - aircraft.timing().controlPeriod) < 1e-12);
    QVERIFY(!aircraft.atRest());
}

void TestAircraft::trimThrottleHoldsSpeedAndHeadingFor20Seconds() {
    const double trim = trimThrottle();
    // Bisection on the simulated aircraft: the throttle at which 10 s of flight ends at 17 m/s.
    double low = 0.0;
    double high = 1.0;
    PlanarAircraft aircraft;
    for (int i = 0; i < 30; ++i) {
        const double mid = 0.5 * (low + high);
        aircraft.resetTo(cruiseState());
        const double speed = groundSpeed(fly(aircraft, 10.0, mid, 0.0).back());
        (speed > 17.0 ? high : low) = mid;
    }
    const double measured = 0.5 * (low + high);
    qInfo("trim throttle at 17 m/s: analytic %.4f, simulated %.4f", trim, measured);
    QVERIFY2(trim > 0.45 && trim < 0.55, "trim throttle should be about 0.5");
    QVERIFY2(std::abs(measured - trim) < 0.005, "simulation disagrees with the analytic trim");

    aircraft.resetTo(cruiseState());
    double worstSpeed = 0.0;
    double worstHeading = 0.0;
    double worstLateral = 0.0;
    const std::vector<Eigen::VectorXd> states = fly(aircraft, 20.0, trim, 0.0);
    for (const Eigen::VectorXd& s : states) {
        worstSpeed = std::max(worstSpeed, std::abs(groundSpeed(s) - 17.0));
        worstHeading = std::max(worstHeading, std::abs(s[2]));
        worstLateral = std::max(worstLateral, std::abs(s[1]));
    }
    qInfo("20 s at trim: worst speed error %.2e m/s, heading %.2e rad, lateral %.2e m, x %.3f m",
          worstSpeed, worstHeading, worstLateral, states.back()[0]);
    QVERIFY(worstSpeed < 0.05);
    QVERIFY(worstHeading < 1e-4);
    QVERIFY(worstLateral < 1e-3);
    QVERIFY(std::abs(states.back()[0] - 17.0 * 20.0) < 1.0);
}

void TestAircraft::throttleAboveTrimSpeedsUpAndBelowSlowsDown() {
    PlanarAircraft aircraft;
    aircraft.resetTo(cruiseState());
    const double fast = groundSpeed(fly(aircraft, 5.0, trimThrottle() + 0.2, 0.0).back());
    aircraft.resetTo(cruiseState());
    const double slow = groundSpeed(fly(aircraft, 5.0, trimThrottle() - 0.2, 0.0).back());
    aircraft.resetTo(cruiseState());
    const double top = groundSpeed(fly(aircraft, 60.0, 1.0, 0.0).back());
    qInfo("after 5 s at trim +- 0.2: %.2f / %.2f m/s; full-throttle top speed %.2f m/s", fast, slow,
          top);
    QVERIFY(fast > 18.0);
    QVERIFY(slow < 16.0);
    QVERIFY(top > 20.0 && top < 25.0);
}

void TestAircraft::fullLeftRudderTurnsLeftOnAFewTensOfMetresRadius() {
    PlanarAircraft aircraft;
    aircraft.resetTo(cruiseState());
    const std::vector<Eigen::VectorXd> states = fly(aircraft, 20.0, trimThrottle(), 1.0);
    // Heading increases (counter-clockwise) at every step after the entry.
    for (std::size_t k = 20; k < states.size(); ++k) {
        QVERIFY2(states[k][2] > states[k - 1][2], "heading must keep increasing in a left turn");
    }
    // The track curves left: after a quarter turn the aircraft is well to the left of its start.
    const int quarter = 8 * 40;
    QVERIFY(states[quarter][1] > 10.0);
    const int settled = static_cast<int>(states.size()) - 400;  // the last 10 s
    const double radius = fittedRadius(states, settled);
    const Eigen::VectorXd& end = states.back();
    const double speedOverRate = groundSpeed(end) / end[5];
    qInfo(
        "full left rudder at trim throttle: radius %.1f m (fit), V/r %.1f m, speed %.2f m/s, "
        "yaw rate %.1f deg/s, sideslip %.1f deg",
        radius, speedOverRate, groundSpeed(end), end[5] / kDegree, aircraft.sideslip() / kDegree);
    QVERIFY2(radius > 25.0 && radius < 45.0, "documented: about 34 m");
    QVERIFY(std::abs(radius - speedOverRate) < 0.02 * radius);
    QVERIFY(aircraft.sideslip() < 0.0);  // the nose points inside the turn
}

void TestAircraft::fullRightRudderMirrorsTheLeftTurn() {
    PlanarAircraft aircraft;
    aircraft.resetTo(cruiseState());
    const Eigen::VectorXd left = fly(aircraft, 10.0, trimThrottle(), 1.0).back();
    aircraft.resetTo(cruiseState());
    const Eigen::VectorXd right = fly(aircraft, 10.0, trimThrottle(), -1.0).back();
    qInfo("10 s full left: (%.2f, %.2f, %.3f); full right: (%.2f, %.2f, %.3f)", left[0], left[1],
          left[2], right[0], right[1], right[2]);
    QVERIFY(right[2] < -1.0);
    QVERIFY(std::abs(left[0] - right[0]) < 1e-3);
    QVERIFY(std::abs(left[1] + right[1]) < 1e-3);
    QVERIFY(std::abs(left[2] + right[2]) < 1e-4);
}

void TestAircraft::yawRateKickDecaysWithoutRudder() {
    PlanarAircraft aircraft;
    aircraft.resetTo(cruiseState(0, 0, 0, 17.0, 0.0, 0.5));
    const std::vector<Eigen::VectorXd> states = fly(aircraft, 3.0, trimThrottle(), 0.0);
    double settleTime = -1.0;
    for (std::size_t k = 0; k < states.size(); ++k) {
        bool quiet = true;
        for (std::size_t i = k; i < states.size(); ++i) {
            quiet = quiet && std::abs(states[i][5]) < 0.005;
        }
        if (quiet) {
            settleTime = k * aircraft.timing().controlPeriod;
            break;
        }
    }
    const Eigen::VectorXd& end = states.back();
    qInfo(
        "0.5 rad/s yaw kick: |r| < 1%% of the kick after %.3f s; after 3 s r %.2e rad/s, "
        "v %.2e m/s, heading settled at %.2f deg",
        settleTime, end[5], end[4], end[2] / kDegree);
    QVERIFY(settleTime >= 0.0 && settleTime < 1.5);
    QVERIFY(std::abs(end[5]) < 1e-3);
    QVERIFY(std::abs(end[4]) < 0.01);
    QVERIFY(std::abs(states[states.size() - 2][2] - end[2]) < 1e-4);  // a new, steady heading
}

void TestAircraft::sideslipDisturbanceDecaysWithoutRudder() {
    PlanarAircraft aircraft;
    aircraft.resetTo(cruiseState(0, 0, 0, 17.0, 3.0, 0.0));
    const double initialSideslip = aircraft.sideslip();
    const std::vector<Eigen::VectorXd> states = fly(aircraft, 3.0, trimThrottle(), 0.0);
    qInfo("sideslip %.1f deg decays to %.3f deg in 3 s (yaw rate %.2e rad/s)",
          initialSideslip / kDegree, aircraft.sideslip() / kDegree, states.back()[5]);
    QVERIFY(initialSideslip > 5.0 * kDegree);
    QVERIFY(std::abs(aircraft.sideslip()) < 0.05 * kDegree);
    QVERIFY(std::abs(states.back()[5]) < 1e-3);
}

void TestAircraft::sameSeedGivesBitIdenticalTrajectories() {
    PlanarAircraft a;
    PlanarAircraft b;
    a.reset(99, sim::Perturbation::realistic());
    b.reset(99, sim::Perturbation::realistic());
    for (int k = 0; k < 800; ++k) {
        const Eigen::Vector2d action(0.6, 0.8 * std::sin(0.01 * k));
        const Eigen::VectorXd sa = a.step(action);
        const Eigen::VectorXd sb = b.step(action);
        QVERIFY2(sa == sb, qPrintable(QStringLiteral("diverged at step %1").arg(k)));
    }
    // Resetting the same object again replays the trial exactly.
    const Eigen::VectorXd end = a.state();
    a.reset(99, sim::Perturbation::realistic());
    Eigen::VectorXd replay;
    for (int k = 0; k < 800; ++k) {
        replay = a.step(Eigen::Vector2d(0.6, 0.8 * std::sin(0.01 * k)));
    }
    QVERIFY(replay == end);
}

void TestAircraft::differentSeedsGiveDifferentTrajectories() {
    PlanarAircraft a;
    PlanarAircraft b;
    a.reset(1, sim::Perturbation::realistic());
    b.reset(2, sim::Perturbation::realistic());
    double largest = 0.0;
    for (int k = 0; k < 800; ++k) {
        const Eigen::Vector2d action(trimThrottle(), 0.0);
        largest = std::max(largest, (a.step(action).head<2>() - b.step(action).head<2>()).norm());
    }
    qInfo("seeds 1 and 2 under the same actions part by up to %.1f m in 20 s", largest);
    QVERIFY(largest > 5.0);
    // Only the actuator noise differs: the noisy trajectory still departs from the clean one.
    sim::Perturbation noiseOnly;
    noiseOnly.actuatorNoise = 1.0;
    a.reset(1, noiseOnly);
    b.reset(1, sim::Perturbation::none());
    for (int k = 0; k < 400; ++k) {
        a.step(Eigen::Vector2d(trimThrottle(), 0.0));
        b.step(Eigen::Vector2d(trimThrottle(), 0.0));
    }
    const double noiseEffect = (a.state() - b.state()).head<3>().norm();
    qInfo("actuator noise alone: %.3f after 10 s", noiseEffect);
    QVERIFY(noiseEffect > 0.01);
}

void TestAircraft::actionsAreClampedToTheirLimits() {
    PlanarAircraft a;
    PlanarAircraft b;
    const std::pair<Eigen::Vector2d, Eigen::Vector2d> cases[] = {
        {Eigen::Vector2d(5.0, 7.0), Eigen::Vector2d(1.0, 1.0)},
        {Eigen::Vector2d(-2.0, -9.0), Eigen::Vector2d(0.0, -1.0)},
        {Eigen::Vector2d(1e9, -1e9), Eigen::Vector2d(1.0, -1.0)},
    };
    for (const auto& [outside, limit] : cases) {
        a.resetTo(cruiseState());
        b.resetTo(cruiseState());
        for (int k = 0; k < 80; ++k) {
            QCOMPARE(a.step(outside), b.step(limit));
        }
    }
    // And the limit itself is not clamped further: half rudder turns less than full rudder.
    a.resetTo(cruiseState());
    b.resetTo(cruiseState());
    QVERIFY(fly(a, 2.0, 0.5, 0.5).back()[2] < fly(b, 2.0, 0.5, 1.0).back()[2]);
}

void TestAircraft::nonFiniteActionCutsTheEngineAndCentresTheRudder() {
    PlanarAircraft a;
    PlanarAircraft b;
    a.resetTo(cruiseState());
    b.resetTo(cruiseState());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 40; ++k) {
        const Eigen::VectorXd sa = a.step(Eigen::Vector2d(k % 2 ? nan : inf, k % 2 ? -inf : nan));
        QVERIFY(sa.allFinite());
        QCOMPARE(sa, b.step(Eigen::Vector2d(0.0, 0.0)));
    }
}

void TestAircraft::stepRejectsAWrongSize() {
    PlanarAircraft aircraft;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, aircraft.step(Eigen::VectorXd(1)));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, aircraft.step(Eigen::VectorXd::Zero(3)));
}

void TestAircraft::resetToSetsThatStateWithoutWind() {
    PlanarAircraft aircraft;
    aircraft.reset(5, sim::Perturbation::realistic());
    const Eigen::VectorXd wanted = cruiseState(12.5, -40.25, 2.0, 15.5, -1.25, 0.3);
    const Eigen::VectorXd got = aircraft.resetTo(wanted);
    qInfo("resetTo round trip error %.2e", (got - wanted).cwiseAbs().maxCoeff());
    QCOMPARE(got.head<3>(), wanted.head<3>());  // the pose is carried in double: exact
    QVERIFY((got - wanted).cwiseAbs().maxCoeff() < 1e-5);
    QCOMPARE(aircraft.state(), got);
    QCOMPARE(aircraft.time(), 0.0);
    QVERIFY(aircraft.windField().calm());
    QCOMPARE(aircraft.thrustScale(), 1.0);
    QCOMPARE(aircraft.dragScale(), 1.0);
    // Nominal and noise-free: equal to a fresh aircraft put in the same state.
    PlanarAircraft fresh;
    fresh.resetTo(wanted);
    for (int k = 0; k < 100; ++k) {
        QCOMPARE(aircraft.step(Eigen::Vector2d(0.7, -0.2)), fresh.step(Eigen::Vector2d(0.7, -0.2)));
    }
}

void TestAircraft::resetToRejectsBadInput() {
    PlanarAircraft aircraft;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, aircraft.resetTo(Eigen::VectorXd::Zero(5)));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, aircraft.resetTo(Eigen::VectorXd::Zero(7)));
    Eigen::VectorXd bad = cruiseState();
    bad[3] = std::numeric_limits<double>::quiet_NaN();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, aircraft.resetTo(bad));
    bad = cruiseState();
    bad[0] = std::numeric_limits<double>::infinity();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, aircraft.resetTo(bad));
    // A rejected state leaves the aircraft as it was.
    QCOMPARE(aircraft.state(), cruiseState());
}

void TestAircraft::precisionDoesNotDependOnTheDistanceFromTheOrigin() {
    // Box2D works in float; 10 km out a float position would be good to only 1 mm.
    PlanarAircraft near;
    PlanarAircraft far;
    near.resetTo(cruiseState(0.0, 0.0, 1.0));
    far.resetTo(cruiseState(1e4, -1e4, 1.0 + 20.0 * kPi));
    const Eigen::VectorXd a = fly(near, 20.0, 0.6, 0.4).back();
    const Eigen::VectorXd b = fly(far, 20.0, 0.6, 0.4).back();
    const double positionError = std::hypot(b[0] - 1e4 - a[0], b[1] + 1e4 - a[1]);
    const double headingError = std::abs(b[2] - 20.0 * kPi - a[2]);
    qInfo("10 km out after 20 s: position differs by %.2e m, heading by %.2e rad", positionError,
          headingError);
    QVERIFY(positionError < 1e-6);
    QVERIFY(headingError < 1e-9);

    // Ten minutes of trimmed straight flight from the origin, out to 10 km: the distance flown
    // must stay 17 m/s x 600 s (float positions out there would round every 400 Hz step by up
    // to half a millimetre).
    PlanarAircraft longFlight;
    longFlight.resetTo(cruiseState(0.0, 0.0, 1.0));
    const Eigen::VectorXd end = fly(longFlight, 600.0, trimThrottle(), 0.0).back();
    const double distanceError = std::hypot(end[0], end[1]) - 17.0 * 600.0;
    const double trackError = std::abs(std::atan2(end[1], end[0]) - 1.0);
    qInfo("600 s straight: distance flown off by %.2e m, track by %.2e rad", distanceError,
          trackError);
    QVERIFY(std::abs(distanceError) < 1e-3);
    QVERIFY(trackError < 1e-6);
}

void TestAircraft::turnAgreesAcrossPhysicsRates() {
    sim::SimulationTiming fine;
    fine.physicsSubsteps = 40;  // 1600 Hz
    PlanarAircraft standard;
    PlanarAircraft reference({}, fine);
    standard.resetTo(cruiseState());
    reference.resetTo(cruiseState());
    const Eigen::VectorXd a = fly(standard, 10.0, 0.8, 1.0).back();
    const Eigen::VectorXd b = fly(reference, 10.0, 0.8, 1.0).back();
    const double error = (a.head<2>() - b.head<2>()).norm();
    qInfo("10 s turn at 400 Hz vs 1600 Hz physics: %.3f m apart, heading %.2e rad", error,
          std::abs(a[2] - b[2]));
    QVERIFY(error < 0.5);
    QVERIFY(std::abs(a[2] - b[2]) < 0.01);
}

void TestAircraft::demonstratorFliesAValidSTurn() {
    const core::Demonstration d = sim::AircraftDemonstrator::record(1);
    QVERIFY2(d.validate().isEmpty(), qPrintable(d.validate()));
    QCOMPARE(d.plant, QStringLiteral("aircraft"));
    QCOMPARE(d.stateDimension(), 6);
    QCOMPARE(d.actionDimension(), 2);
    QCOMPARE(d.dt, 0.025);
    const double duration = d.length() * d.dt;
    double minHeading = 1e9, maxHeading = -1e9, minSpeed = 1e9, maxSpeed = 0.0;
    for (int k = 0; k < d.length(); ++k) {
        minHeading = std::min(minHeading, d.states(k, 2));
        maxHeading = std::max(maxHeading, d.states(k, 2));
        const double speed = std::hypot(d.states(k, 3), d.states(k, 4));
        minSpeed = std::min(minSpeed, speed);
        maxSpeed = std::max(maxSpeed, speed);
        QVERIFY(d.actions(k, 0) >= 0.0 && d.actions(k, 0) <= 1.0);
        QVERIFY(d.actions(k, 1) >= -1.0 && d.actions(k, 1) <= 1.0);
    }
    const double finalHeading = d.states(d.length() - 1, 2);
    const double maxRudder = d.actions.col(1).maxCoeff();
    const double minRudder = d.actions.col(1).minCoeff();
    qInfo(
        "demonstration: %d samples, %.2f s, heading %.1f..%.1f deg (final %.1f), speed "
        "%.2f..%.2f m/s, rudder %.2f..%.2f, end at (%.1f, %.1f) m",
        d.length(), duration, minHeading / kDegree, maxHeading / kDegree, finalHeading / kDegree,
        minSpeed, maxSpeed, minRudder, maxRudder, d.states(d.length() - 1, 0),
        d.states(d.length() - 1, 1));
    QVERIFY(duration >= 20.0 && duration <= 30.0);
    QVERIFY(maxHeading - minHeading > 150.0 * kDegree);
    QVERIFY(std::abs(finalHeading) < 15.0 * kDegree);  // back on the first heading: an S-turn
    QVERIFY(minSpeed > 14.0 && maxSpeed < 21.0);
    QVERIFY(maxRudder > 0.4 && minRudder < -0.4);  // a left and a right turn
}

void TestAircraft::demonstratorIsSeededAndSmooth() {
    const core::Demonstration a = sim::AircraftDemonstrator::record(7);
    const core::Demonstration b = sim::AircraftDemonstrator::record(7);
    const core::Demonstration c = sim::AircraftDemonstrator::record(8);
    QCOMPARE(a.states, b.states);
    QCOMPARE(a.actions, b.actions);
    const int n = std::min(a.length(), c.length());
    const double difference = (a.actions.topRows(n) - c.actions.topRows(n)).cwiseAbs().maxCoeff();
    double largestStep = 0.0;
    for (int k = 1; k < a.length(); ++k) {
        largestStep =
            std::max(largestStep, (a.actions.row(k) - a.actions.row(k - 1)).cwiseAbs().maxCoeff());
    }
    qInfo("seeds 7 and 8 differ by up to %.3f in an action; largest per-step action change %.3f",
          difference, largestStep);
    QVERIFY(difference > 0.01);
    QVERIFY(largestStep < 0.1);  // a hand, not a bang-bang switch
}

QTEST_APPLESS_MAIN(TestAircraft)
#include "test_aircraft.moc"
