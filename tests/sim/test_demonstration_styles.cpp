// The family of scripted demonstrations: each style is what its name says (rotation, side,
// keys or stick, standstill, blip, jitter, coasting, approach speed), differs from the others,
// and is deterministic for a seed.
#include "sim/DemonstrationStyles.h"
#include "sim/PlantCatalog.h"

#include <QtTest>

#include <cmath>

using namespace prisca;
using namespace prisca::sim;

namespace {

double degrees(double radians) {
    return radians * 180.0 / M_PI;
}

core::Demonstration car(const char* style, std::uint64_t seed = 1) {
    return DemonstrationStyles::record(QStringLiteral("slidecar"), QString::fromLatin1(style),
                                       seed);
}

double finalHeadingDeg(const core::Demonstration& d) {
    return degrees(d.states(d.length() - 1, 2));
}

double peakSpeed(const core::Demonstration& d) {
    return d.states.col(3).maxCoeff();
}

// Largest change of an action channel from one sample to the next.
double largestStep(const core::Demonstration& d, int channel) {
    double step = 0.0;
    for (int k = 1; k < d.length(); ++k)
        step = std::max(step, std::abs(d.actions(k, channel) - d.actions(k - 1, channel)));
    return step;
}

// Sum over the recording of |u_k - u_{k-1}| on a channel (how busy the hand is).
double travel(const core::Demonstration& d, int channel) {
    double sum = 0.0;
    for (int k = 1; k < d.length(); ++k)
        sum += std::abs(d.actions(k, channel) - d.actions(k - 1, channel));
    return sum;
}

// First sample at which |steering| passes half lock.
int steerIn(const core::Demonstration& d) {
    for (int k = 0; k < d.length(); ++k)
        if (std::abs(d.actions(k, 1)) > 0.5)
            return k;
    return -1;
}

}  // namespace

class TestDemonstrationStyles : public QObject {
    Q_OBJECT
  private slots:
    void catalog_listsEnoughDistinctStylesPerPlant() {
        for (const auto& [plant, least] :
             {std::pair{"slidecar", 6}, {"acrobot", 3}, {"aircraft", 3}}) {
            const auto styles = DemonstrationStyles::of(plant);
            QVERIFY2(static_cast<int>(styles.size()) >= least, plant);
            QStringList names;
            for (const DemonstrationStyle& s : styles) {
                QVERIFY(!s.description.isEmpty());
                QVERIFY(!s.name.contains(' ') && !s.name.contains(','));
                names << s.name;
            }
            QCOMPARE(names.removeDuplicates(), 0);
            QCOMPARE(DemonstrationStyles::classic(plant), names.front());
            // The classic style is the plant's scripted demonstration.
            const core::Demonstration classic =
                DemonstrationStyles::record(plant, names.front(), 4);
            const core::Demonstration scripted = PlantCatalog::demonstrate(plant, 4);
            QCOMPARE(classic.states, scripted.states);
            QCOMPARE(classic.actions, scripted.actions);
            QCOMPARE(classic.metadata.value("style"), names.front());
        }
        QVERIFY(DemonstrationStyles::of("nosuchplant").empty());
    }

    void record_unknownStyleNamesTheKnownOnes() {
        try {
            DemonstrationStyles::record("acrobot", "backflip", 1);
            QFAIL("no exception");
        } catch (const std::invalid_argument& e) {
            const QString message = QString::fromStdString(e.what());
            QVERIFY2(message.contains("backflip") && message.contains("swing-large"),
                     qPrintable(message));
        }
    }

    void record_isDeterministicForASeedAndVariesWithIt() {
        for (const QString& style : DemonstrationStyles::names("slidecar")) {
            const core::Demonstration a = car(qPrintable(style), 5);
            QCOMPARE(car(qPrintable(style), 5).actions, a.actions);
            const core::Demonstration b = car(qPrintable(style), 6);
            QVERIFY2(a.actions.rows() != b.actions.rows() || a.actions != b.actions,
                     qPrintable(style));
        }
    }

    void slideCar_rotationAndSideAreAsNamed() {
        for (std::uint64_t seed : {1, 2, 3}) {
            for (const QString& style : DemonstrationStyles::names("slidecar")) {
                const core::Demonstration d = car(qPrintable(style), seed);
                const double psi = finalHeadingDeg(d);
                const double side = style.endsWith("left") ? 1.0 : -1.0;
                QVERIFY2(style.endsWith("left") || style.endsWith("right"), qPrintable(style));
                const double turned = side * psi;
                if (style.contains("-90-")) {
                    QVERIFY2(turned > 60.0 && turned < 120.0,
                             qPrintable(QStringLiteral("%1: %2 deg").arg(style).arg(psi)));
                } else {
                    QVERIFY2(style.contains("-180-"), qPrintable(style));
                    QVERIFY2(turned > 150.0 && turned < 220.0,
                             qPrintable(QStringLiteral("%1: %2 deg").arg(style).arg(psi)));
                }
                // Parked: the car ends at rest with the sticks released.
                QVERIFY(std::abs(d.states(d.length() - 1, 3)) < 0.05);
                QVERIFY(d.actions.row(d.length() - 1).cwiseAbs().maxCoeff() < 1e-12);
            }
        }
    }

    void slideCar_keyboardRampsStickDoesNot() {
        // Keys move a control by at most 2/s up or 3/s back: 0.05 and 0.075 a 40 Hz step.
        for (const char* style : {"keyboard-180-right", "keyboard-90-right"}) {
            const core::Demonstration d = car(style);
            QVERIFY2(largestStep(d, 1) <= 0.075 + 1e-9, style);
            QVERIFY2(largestStep(d, 0) <= 0.075 + 1e-9, style);
            QVERIFY(d.actions.col(1).cwiseAbs().maxCoeff() > 0.99);  // full lock reached
        }
        // A stick reaches full lock in 0.08 s: steps far above a key's ramp.
        QVERIFY(largestStep(car("stick-180-left"), 1) > 0.2);
    }

    void slideCar_standstillWaitsBeforeTheLaunch() {
        const core::Demonstration d = car("standstill-180-left");
        const int still = static_cast<int>(0.8 / d.dt);
        for (int k = 0; k < still; ++k) {
            QCOMPARE(d.actions(k, 0), 0.0);
            QCOMPARE(d.states(k, 3), 0.0);
        }
        QVERIFY(steerIn(d) > steerIn(car("stick-180-left")) + still);
    }

    void slideCar_approachSpeedsAreOrdered() {
        const double fast = peakSpeed(car("fast-180-right"));
        const double classic = peakSpeed(car("stick-180-left"));
        const double slow = peakSpeed(car("slow-90-left"));
        QVERIFY2(fast > classic + 0.2 && classic > slow + 0.5,
                 qPrintable(QStringLiteral("%1 %2 %3").arg(fast).arg(classic).arg(slow)));
    }

    void slideCar_blipJitterAndCoastShowInTheActions() {
        // Blip: throttle back on after the steer-in, in the slide.
        const core::Demonstration blip = car("blip-180-left");
        const int in = steerIn(blip);
        QVERIFY(blip.actions.col(0).segment(in + 4, 12).maxCoeff() > 0.3);
        QVERIFY(car("stick-180-left").actions.col(0).segment(in + 4, 12).maxCoeff() < 0.05);
        // Jitter: a busy hand on both sticks.
        const core::Demonstration jitter = car("jitter-180-right");
        const core::Demonstration classic = car("stick-180-left");
        QVERIFY(travel(jitter, 0) > 3.0 * travel(classic, 0));
        QVERIFY(travel(jitter, 1) > 3.0 * travel(classic, 1));
        // Coasting: the throttle is off for at least 0.3 s before the steer-in.
        const core::Demonstration coast = car("coast-90-right");
        const int coastIn = steerIn(coast);
        const int coasting = static_cast<int>(0.3 / coast.dt);
        QVERIFY(coast.actions.col(0).segment(coastIn - coasting, coasting).maxCoeff() < 0.01);
        QVERIFY(coast.states(coastIn, 3) < coast.states.col(3).maxCoeff() - 0.2);  // slowed
    }

    void acrobot_swingsDifferInAmplitudeAndPeriod() {
        auto amplitude = [](const char* style) {
            const core::Demonstration d = DemonstrationStyles::record("acrobot", style, 1);
            return d.states.col(0).cwiseAbs().maxCoeff();
        };
        QVERIFY(amplitude("swing-small") < 0.7 * amplitude("swing-medium"));
        QVERIFY(amplitude("swing-large") > 1.3 * amplitude("swing-medium"));
        auto crossings = [](const char* style) {
            const core::Demonstration d = DemonstrationStyles::record("acrobot", style, 1);
            int n = 0;
            for (int k = 1; k < d.length(); ++k)
                n += (d.states(k - 1, 2) < 0.0) != (d.states(k, 2) < 0.0);
            return n;
        };
        QVERIFY(crossings("swing-fast") > crossings("swing-medium"));
    }

    void aircraft_patternsTurnAsNamed() {
        auto headings = [](const char* style) {
            const core::Demonstration d = DemonstrationStyles::record("aircraft", style, 1);
            return std::tuple{degrees(d.states.col(2).maxCoeff()),
                              degrees(d.states.col(2).minCoeff()),
                              degrees(d.states(d.length() - 1, 2))};
        };
        const auto [sMax, sMin, sEnd] = headings("s-turn");
        QVERIFY(sMax > 160.0 && sMax < 200.0 && std::abs(sEnd) < 15.0);
        const auto [cMax, cMin, cEnd] = headings("circle");
        QVERIFY(cEnd > 340.0 && cEnd < 380.0 && cMin > -15.0);
        const auto [eMax, eMin, eEnd] = headings("figure-eight");
        QVERIFY(eMax > 340.0 && std::abs(eEnd) < 15.0);
        const auto [wMax, wMin, wEnd] = headings("s-turn-wide");
        QVERIFY(wMax > 160.0 && std::abs(wEnd) < 15.0);
        // The wide S-turn is flown with less rudder: a larger turn radius.
        const core::Demonstration wide = DemonstrationStyles::record("aircraft", "s-turn-wide", 1);
        const core::Demonstration s = DemonstrationStyles::record("aircraft", "s-turn", 1);
        QVERIFY(wide.states.col(1).maxCoeff() > 1.3 * s.states.col(1).maxCoeff());
        Q_UNUSED(sMin);
        Q_UNUSED(wMin);
    }
};

QTEST_APPLESS_MAIN(TestDemonstrationStyles)
#include "test_demonstration_styles.moc"
