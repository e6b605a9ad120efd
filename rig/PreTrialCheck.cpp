#include "rig/PreTrialCheck.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace prisca::rig {

namespace {

// The check's sentences, in the window's language where a translator is installed.
class Text {
    Q_DECLARE_TR_FUNCTIONS(prisca::rig::PreTrialCheck)
  public:
    static QString metres(const cv::Point2d& p) {
        return QStringLiteral("(%1, %2) m").arg(p.x, 0, 'f', 2).arg(p.y, 0, 'f', 2);
    }
};

PreTrialItem item(const char* key, const QString& label, bool ok, const QString& detail,
                  bool blocking = true) {
    return {QString::fromLatin1(key), label, ok, blocking, detail};
}

// The demonstration's positions, the lot (its last) included.
std::vector<cv::Point2d> path(const PreTrialInputs& in) {
    std::vector<cv::Point2d> points;
    if (!in.demonstration || !in.plant || !in.plant->pose) {
        return points;
    }
    const core::Demonstration& demo = *in.demonstration;
    for (int k = 0; k < demo.length(); ++k) {
        points.emplace_back(demo.states(k, in.plant->pose->x), demo.states(k, in.plant->pose->y));
    }
    return points;
}

PreTrialItem latencyItem(const PreTrialInputs& in) {
    const QString label = Text::tr("Latency");
    if (in.loopLatency && in.loopLatencySource == LoopLatencySource::Measured) {
        return item("latency", label, true,
                    Text::tr("measured: %1 ms").arg(*in.loopLatency * 1000.0, 0, 'f', 1));
    }
    if (in.loopLatency && in.loopLatencySource == LoopLatencySource::Declared) {
        return item("latency", label, true,
                    Text::tr("declared: %1 ms").arg(*in.loopLatency * 1000.0, 0, 'f', 1));
    }
    if (in.virtualCamera && in.injectedCameraDelay <= 0.0) {
        return item("latency", label, true,
                    Text::tr("the virtual camera's, known (the profile's assumption)"));
    }
    return item("latency", label, false,
                Text::tr("The loop's latency is neither measured nor declared: measure it (the "
                         "car at rest in view) or declare the value measured elsewhere."));
}

PreTrialItem fenceItem(const PreTrialInputs& in, const std::vector<cv::Point2d>& points) {
    const QString label = Text::tr("Fence");
    if (in.fence.polygon.size() < 3) {
        return item(
            "fence", label, false,
            Text::tr(
                "No fence: a car that runs away is stopped only by E-STOP and the "
                "lost-track guard. Draw one (the Rig tab's set-up page; prisca-cli rig --fence)."),
            false);
    }
    int outside = 0;
    cv::Point2d first;
    for (const cv::Point2d& p : points) {
        if (!in.fence.contains(p)) {
            if (outside++ == 0) {
                first = p;
            }
        }
    }
    if (!points.empty() && !in.fence.contains(points.back())) {
        return item("fence", label, false,
                    Text::tr("The lot %1 is outside the fence: the trial would end in failsafe. "
                             "Move the fence or record the demonstration inside it.")
                        .arg(Text::metres(points.back())));
    }
    if (outside > 0) {
        return item("fence", label, false,
                    Text::tr("%1 of the demonstration's %2 points are outside the fence (the "
                             "first at %3): the trial would end in failsafe.")
                        .arg(outside)
                        .arg(points.size())
                        .arg(Text::metres(first)));
    }
    return item("fence", label, true, Text::tr("the path and the lot are inside it"));
}

PreTrialItem viewItem(const PreTrialInputs& in, const std::vector<cv::Point2d>& points) {
    const QString label = Text::tr("In view");
    if (in.frameSize.empty()) {
        return item(
            "view", label, false,
            Text::tr("No frame yet: the path cannot be checked against the camera's view."));
    }
    const double w = in.frameSize.width, h = in.frameSize.height;
    const auto seen = [&](const cv::Point2d& floor) {
        const cv::Point2d image = in.calibration.toImage(floor);
        if (!std::isfinite(image.x) || !std::isfinite(image.y)) {
            return false;
        }
        // Behind the camera's horizon a homography maps points into the image too: they must
        // come back to where they were.
        const cv::Point2d back = in.calibration.toFloor(image);
        return image.x >= kViewMarginPx && image.x <= w - kViewMarginPx &&
               image.y >= kViewMarginPx && image.y <= h - kViewMarginPx &&
               std::hypot(back.x - floor.x, back.y - floor.y) < 0.01;
    };
    int outside = 0;
    cv::Point2d first;
    for (const cv::Point2d& p : points) {
        if (!seen(p)) {
            if (outside++ == 0) {
                first = p;
            }
        }
    }
    if (!points.empty() && !seen(points.back())) {
        return item("view", label, false,
                    Text::tr("The lot %1 is outside the camera's view: the car would be lost "
                             "where it should park. Record the demonstration in view, or move the "
                             "camera and calibrate again.")
                        .arg(Text::metres(points.back())));
    }
    if (outside > 0) {
        return item("view", label, false,
                    Text::tr("%1 of the demonstration's %2 points are outside the camera's view "
                             "(the first at %3).")
                        .arg(outside)
                        .arg(points.size())
                        .arg(Text::metres(first)));
    }
    return item("view", label, true, Text::tr("the path and the lot are in view"));
}

}  // namespace

bool PreTrialCheck::ready() const {
    return std::all_of(items.begin(), items.end(),
                       [](const PreTrialItem& i) { return i.ok || !i.blocking; });
}

QString PreTrialCheck::missingLabels() const {
    QStringList labels;
    for (const PreTrialItem& i : items) {
        if (!i.ok && i.blocking) {
            labels << i.label;
        }
    }
    return labels.join(QStringLiteral(", "));
}

QString PreTrialCheck::missingDetails() const {
    QStringList details;
    for (const PreTrialItem& i : items) {
        if (!i.ok && i.blocking) {
            details << i.detail;
        }
    }
    return details.join(QLatin1Char(' '));
}

const PreTrialItem* PreTrialCheck::find(const QString& key) const {
    for (const PreTrialItem& i : items) {
        if (i.key == key) {
            return &i;
        }
    }
    return nullptr;
}

QString emergencyProblem(bool failsafeHeld) {
    return failsafeHeld ? Text::tr(
                              "The program was stopped and continued; the car went without "
                              "commands meanwhile, so the link holds failsafe: reset E-STOP to "
                              "release it.")
                        : Text::tr("E-STOP is latched: reset it before a trial.");
}

QString methodRigProblem(bool simulationOnly, bool trainsOffline, const QString& label) {
    if (simulationOnly) {
        return Text::tr(
            "The oracle plans on copies of a simulated plant; a real car has none. "
            "Run it in simulation, or choose another method.");
    }
    if (trainsOffline) {
        return Text::tr(
                   "%1 trains offline in simulation; run it there, or choose another "
                   "method.")
            .arg(label);
    }
    return {};
}

PreTrialCheck evaluatePreTrialCheck(const PreTrialInputs& in) {
    PreTrialCheck check;
    auto& items = check.items;
    items.push_back(in.cameraRunning ? item("camera", Text::tr("Camera"), true, Text::tr("running"))
                                     : item("camera", Text::tr("Camera"), false,
                                            Text::tr("Start the camera first.")));
    items.push_back(in.carSeen ? item("car", Text::tr("Car"), true,
                                      in.virtualCamera ? Text::tr("the virtual car, put at the "
                                                                  "start by each trial")
                                                       : Text::tr("in view"))
                               : item("car", Text::tr("Car"), false,
                                      Text::tr("The camera does not see the car: put it in view "
                                               "with its LEDs on.")));
    // A real camera needs its own calibration (the rig starts with the virtual rig's) and lens.
    if (in.virtualCamera) {
        items.push_back(
            item("calibration", Text::tr("Calibration"), true, Text::tr("the virtual camera's")));
    } else if (in.calibrationIsVirtualRigs) {
        items.push_back(item("calibration", Text::tr("Calibration"), false,
                             Text::tr("The floor calibration is the virtual rig's, not this "
                                      "camera's: calibrate this camera or open its calibration.")));
    } else if (const QString problem = in.calibration.accuracyProblem(); !problem.isEmpty()) {
        items.push_back(item("calibration", Text::tr("Calibration"), false, problem));
    } else {
        items.push_back(item("calibration", Text::tr("Calibration"), true,
                             Text::tr("%1 points, RMS %2 mm")
                                 .arg(in.calibration.points.size())
                                 .arg(in.calibration.rmsMetres * 1000.0, 0, 'f', 1)));
    }
    if (in.virtualCamera) {
        items.push_back(item("lens", Text::tr("Lens"), true, Text::tr("none needed (virtual)")));
    } else if (in.calibration.lens) {
        items.push_back(item("lens", Text::tr("Lens"), true,
                             Text::tr("fx %1 px, k1 %2")
                                 .arg(in.calibration.lens->matrix(0, 0), 0, 'f', 1)
                                 .arg(in.calibration.lens->distortion[0], 0, 'f', 3)));
    } else {
        items.push_back(item("lens", Text::tr("Lens"), false,
                             Text::tr("No lens: fit the camera's intrinsics from board views or "
                                      "open them (a wide lens bends the floor by centimetres at "
                                      "the edges).")));
    }
    if (!in.link.connected) {
        items.push_back(
            item("link", Text::tr("Link"), false, Text::tr("Connect the transmitter link first.")));
    } else if (!in.link.lastError.isEmpty()) {
        items.push_back(item("link", Text::tr("Link"), false,
                             Text::tr("The link reports an error: %1").arg(in.link.lastError)));
    } else {
        items.push_back(item("link", Text::tr("Link"), true, Text::tr("connected")));
    }
    items.push_back(latencyItem(in));
    items.push_back(
        in.emergencyLatched
            ? item("estop", Text::tr("E-STOP"), false, emergencyProblem(in.failsafeHeld))
            : item("estop", Text::tr("E-STOP"), true, Text::tr("ready")));
    // The task: a slide-car's demonstration (the rig's estimator gives its state) and a method
    // that can run on a real car.
    QString task;
    if (!in.demonstration || in.demonstration->length() == 0 || !in.plant || !in.plant->pose) {
        task = Text::tr("The rig needs a demonstration of a planar vehicle.");
    } else if (in.plant->name != QLatin1String("slidecar")) {
        task = Text::tr("The rig drives a slide-car: choose the slide-car as the target.");
    } else if (const QString method = methodRigProblem(in.methodSimulationOnly,
                                                       in.methodTrainsOffline, in.methodLabel);
               !method.isEmpty()) {
        task = method;
    } else if (in.methodPlansThroughModel && !in.modelIdentified) {
        task = Text::tr(
                   "%1 plans through the car's model, and none is identified yet: identify "
                   "the car first (the Model tab; prisca-cli identify, then --model).")
                   .arg(in.methodLabel);
    }
    items.push_back(task.isEmpty() ? item("task", Text::tr("Task"), true,
                                          Text::tr("%1 on the slide-car").arg(in.methodLabel))
                                   : item("task", Text::tr("Task"), false, task));
    const std::vector<cv::Point2d> points = path(in);
    items.push_back(fenceItem(in, points));
    items.push_back(viewItem(in, points));
    return check;
}

}  // namespace prisca::rig
