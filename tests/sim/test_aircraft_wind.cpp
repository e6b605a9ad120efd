// The planar aircraft in wind: a crosswind drifting its track and turning its nose, gusts with
// their configured statistics whatever the step, seeded, refused when ill-formed, and the
// realistic perturbation bringing wind.

#include "AircraftTestSupport.h"

class TestAircraftWind : public QObject {
    Q_OBJECT

  private slots:
    void crosswindDriftsTheGroundTrack();
    void suddenCrosswindTurnsTheNoseIntoTheWind();
    void gustsHaveConfiguredRmsAndCorrelationTime();
    void gustStatisticsDoNotDependOnTheStepSize();
    void windIsDeterministicForASeed();
    void windRejectsBadParameters();
    void realisticPerturbationBringsWindAndNoneIsCalm();
};

void TestAircraftWind::crosswindDriftsTheGroundTrack() {
    // Trimmed in a 3 m/s wind towards +y (from the right): 17 m/s through the air along the
    // nose, so the ground velocity carries the wind too.
    sim::GustyWindParameters crosswind;
    crosswind.meanSpeed = 3.0;
    crosswind.meanDirection = kPi / 2.0;
    PlanarAircraft aircraft;
    aircraft.resetTo(cruiseState(0, 0, 0, 17.0, 3.0, 0.0));
    aircraft.setWind(crosswind, 7);
    QVERIFY((aircraft.wind() - Eigen::Vector2d(0.0, 3.0)).norm() < 1e-12);
    const Eigen::VectorXd windy = fly(aircraft, 20.0, trimThrottle(), 0.0).back();
    aircraft.resetTo(cruiseState());
    const Eigen::VectorXd calm = fly(aircraft, 20.0, trimThrottle(), 0.0).back();
    qInfo("20 s straight: drift %.2f m with a 3 m/s crosswind, %.2e m without; heading %.3f deg",
          windy[1], calm[1], windy[2] / kDegree);
    QVERIFY(std::abs(windy[1] - 60.0) < 1.0);
    QVERIFY(std::abs(calm[1]) < 1e-3);
    QVERIFY(std::abs(windy[2]) < 0.1 * kDegree);
}

void TestAircraftWind::suddenCrosswindTurnsTheNoseIntoTheWind() {
    // Flying straight over the ground when a 3 m/s wind towards +y sets in: the relative wind
    // comes from the right and the weathercock turns the nose right, into it. The side force also
    // drags the aircraft along with the air meanwhile, so the nose stops short of the initial
    // relative wind's direction, and the ground track then drifts downwind.
    sim::GustyWindParameters crosswind;
    crosswind.meanSpeed = 3.0;
    crosswind.meanDirection = kPi / 2.0;
    PlanarAircraft aircraft;
    aircraft.resetTo(cruiseState());
    aircraft.setWind(crosswind, 7);
    const std::vector<Eigen::VectorXd> states = fly(aircraft, 10.0, trimThrottle(), 0.0);
    const Eigen::VectorXd& end = states.back();
    const Eigen::VectorXd& before = states[states.size() - 41];  // one second earlier
    const double relativeWind = -std::atan2(3.0, 17.0);
    const double driftRate = end[1] - before[1];
    qInfo(
        "sudden 3 m/s crosswind: heading settles at %.2f deg (initial relative wind %.2f deg), "
        "sideslip %.3f deg, track drifts %.2f m/s to the left",
        end[2] / kDegree, relativeWind / kDegree, aircraft.sideslip() / kDegree, driftRate);
    QVERIFY(end[2] < -3.0 * kDegree && end[2] > relativeWind - 0.5 * kDegree);
    QVERIFY(std::abs(end[2] - before[2]) < 0.01 * kDegree);
    QVERIFY(std::abs(aircraft.sideslip()) < 0.05 * kDegree);
    QVERIFY(driftRate > 0.5);
}

void TestAircraftWind::gustsHaveConfiguredRmsAndCorrelationTime() {
    sim::GustyWindParameters p;
    p.meanSpeed = 2.0;
    p.meanDirection = 0.7;
    p.gustRms = 1.5;
    p.gustTimeConstant = 2.0;
    const GustStatistics g = measureGusts(p, 0.05, 40000.0, 11);
    for (int a = 0; a < 2; ++a) {
        qInfo(
            "gust axis %d: rms %.3f m/s (configured 1.5), autocorrelation at tau %.3f "
            "(exp(-1) = 0.368), correlation time %.2f s (configured 2)",
            a, g.rms[a], g.correlationAtTau[a], g.correlationTime[a]);
        QVERIFY(std::abs(g.rms[a] - 1.5) < 0.05 * 1.5);
        QVERIFY(std::abs(g.correlationAtTau[a] - std::exp(-1.0)) < 0.04);
        QVERIFY(std::abs(g.correlationTime[a] - 2.0) < 0.2);
    }
    qInfo("cross-correlation of the axes %.4f", g.crossCorrelation);
    QVERIFY(std::abs(g.crossCorrelation) < 0.05);
    sim::GustyWind wind(p, 3);
    QVERIFY((wind.mean() - 2.0 * Eigen::Vector2d(std::cos(0.7), std::sin(0.7))).norm() < 1e-12);
    QVERIFY((wind.velocity() - wind.mean() - wind.gust()).norm() < 1e-12);
}

void TestAircraftWind::gustStatisticsDoNotDependOnTheStepSize() {
    sim::GustyWindParameters p;
    p.gustRms = 1.0;
    p.gustTimeConstant = 1.0;
    // A coarse step of half the time constant: an Euler step would get the variance wrong.
    for (double dt : {0.0025, 0.5}) {
        const GustStatistics g = measureGusts(p, dt, dt < 0.01 ? 4000.0 : 40000.0, 5);
        qInfo("dt %.4f s: rms %.3f / %.3f m/s, correlation time %.2f / %.2f s", dt, g.rms[0],
              g.rms[1], g.correlationTime[0], g.correlationTime[1]);
        for (int a = 0; a < 2; ++a) {
            QVERIFY(std::abs(g.rms[a] - 1.0) < 0.07);
            QVERIFY(std::abs(g.correlationTime[a] - 1.0) < 0.12);
        }
    }
}

void TestAircraftWind::windIsDeterministicForASeed() {
    sim::GustyWindParameters p;
    p.meanSpeed = 1.0;
    p.gustRms = 1.0;
    sim::GustyWind a(p, 42);
    sim::GustyWind b(p, 42);
    sim::GustyWind c(p, 43);
    double difference = 0.0;
    for (int i = 0; i < 1000; ++i) {
        QCOMPARE(a.velocity(), b.velocity());
        difference = std::max(difference, (a.velocity() - c.velocity()).norm());
        a.advance(0.01);
        b.advance(0.01);
        c.advance(0.01);
    }
    QVERIFY(difference > 0.1);
    QVERIFY(std::abs(a.time() - 10.0) < 1e-9);
    a.reset(42);
    sim::GustyWind fresh(p, 42);
    QCOMPARE(a.velocity(), fresh.velocity());
    QCOMPARE(a.time(), 0.0);
}

void TestAircraftWind::windRejectsBadParameters() {
    sim::GustyWindParameters negative;
    negative.gustRms = -1.0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, sim::GustyWind(negative, 1));
    sim::GustyWindParameters noTime;
    noTime.gustTimeConstant = 0.0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, sim::GustyWind(noTime, 1));
    sim::GustyWindParameters nan;
    nan.meanSpeed = std::numeric_limits<double>::quiet_NaN();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, sim::GustyWind(nan, 1));
    sim::GustyWind wind;
    QVERIFY(wind.calm());
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, wind.advance(-0.1));
}

void TestAircraftWind::realisticPerturbationBringsWindAndNoneIsCalm() {
    PlanarAircraft aircraft;
    double largestWind = 0.0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        aircraft.reset(seed, sim::Perturbation::realistic());
        const sim::GustyWindParameters& w = aircraft.windField().parameters();
        QCOMPARE(w.meanSpeed, 2.0);
        QCOMPARE(w.gustRms, 1.0);
        QVERIFY(aircraft.thrustScale() >= 0.95 && aircraft.thrustScale() <= 1.05);
        QVERIFY(aircraft.dragScale() >= 0.95 && aircraft.dragScale() <= 1.05);
        // Trimmed in the air mass: the start airspeed is the nominal 17 +- a few m/s, no sideslip.
        QVERIFY(std::abs(aircraft.airspeed() - 17.0) < 4.0);
        QVERIFY(std::abs(aircraft.sideslip()) < 1e-6);
        for (int k = 0; k < 40; ++k) {
            aircraft.step(Eigen::Vector2d(trimThrottle(), 0.0));
            largestWind = std::max(largestWind, aircraft.wind().norm());
        }
    }
    qInfo("largest wind seen over 20 realistic trials: %.2f m/s", largestWind);
    QVERIFY(largestWind > 2.0);

    aircraft.reset(3, sim::Perturbation::none());
    QVERIFY(aircraft.windField().calm());
    QCOMPARE(aircraft.thrustScale(), 1.0);
    QCOMPARE(aircraft.dragScale(), 1.0);
    for (int k = 0; k < 200; ++k) {
        aircraft.step(Eigen::Vector2d(trimThrottle(), 0.3));
        QCOMPARE(aircraft.wind(), Eigen::Vector2d(Eigen::Vector2d::Zero()));
    }
}

QTEST_APPLESS_MAIN(TestAircraftWind)
#include "test_aircraft_wind.moc"
