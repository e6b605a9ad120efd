// A recording process for test_recording_crash to kill: records the window's way (driving a
// simulated slide-car, app::RecordingWorker) or the rig's (the virtual car seen by the camera,
// rig::RigSession) into the path given, and prints "elapsed <seconds>" every 20 ms: how much of
// the take the recorder has been handed (the window's: wall time since it started, which its
// steps keep up with; the rig's: its newest frame's time since the take's first frame with a
// pose), so the test knows what was recorded when it sent SIGKILL.
//
//     record_child window|rig <path>
#include "app/workers/RecordingWorker.h"
#include "rig/RigSession.h"
#include "sim/PlantCatalog.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTimer>

#include <cstdio>
#include <memory>

using namespace prisca;

namespace {

void startReporting(QCoreApplication& app, const std::function<double()>& driveAndTell) {
    std::printf("recording\n");
    std::fflush(stdout);
    auto* timer = new QTimer(&app);
    QObject::connect(timer, &QTimer::timeout, &app, [driveAndTell] {
        const double elapsed = driveAndTell();
        if (elapsed >= 0.0) {
            std::printf("elapsed %.4f\n", elapsed);
            std::fflush(stdout);
        }
    });
    timer->start(20);
}

}  // namespace

int main(int argc, char* argv[]) {
    QCoreApplication app(argc, argv);
    if (argc != 3) {
        std::fprintf(stderr, "usage: record_child window|rig <path>\n");
        return 2;
    }
    const QString mode = QString::fromLocal8Bit(argv[1]);
    const QString path = QString::fromLocal8Bit(argv[2]);
    const sim::PlantInfo car = sim::PlantCatalog::describe(QStringLiteral("slidecar"));
    if (mode == QLatin1String("window")) {
        auto* worker = new app::RecordingWorker(&app);
        QObject::connect(worker, &app::RecordingWorker::failed, &app, [](const QString& why) {
            std::fprintf(stderr, "%s\n", qPrintable(why));
            QCoreApplication::exit(1);
        });
        worker->start(QStringLiteral("slidecar"), path);
        auto* clock = new QElapsedTimer;
        clock->start();
        startReporting(app, [worker, clock] {
            worker->setInput(Eigen::Vector2d(0.6, 0.2));
            return clock->nsecsElapsed() * 1e-9;
        });
        return QCoreApplication::exec();
    }
    if (mode != QLatin1String("rig")) {
        std::fprintf(stderr, "unknown mode\n");
        return 2;
    }
    auto* rig = new rig::RigSession(&app);
    rig::CameraRequest camera;
    camera.virtualFps = 40.0;
    QString error;
    if (!rig->startCamera(camera, &error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    // The link to the virtual car, then the recording once the car is seen and connected.
    auto* wait = new QTimer(&app);
    bool linked = false;
    QObject::connect(wait, &QTimer::timeout, &app, [&, rig, wait] {
        if (!rig->lastPose()) {
            return;
        }
        if (!linked) {
            devices::LinkSettings link;
            link.port = rig->virtualPort();
            link.failsafe = rig->channels().failsafe();
            link.sendOnCommand = true;
            rig->connectLink(link);
            linked = true;
            return;
        }
        if (!rig->linkStatus().connected) {
            return;
        }
        wait->stop();
        QString why;
        if (!rig->startRecording(car, path, &why)) {
            std::fprintf(stderr, "%s\n", qPrintable(why));
            QCoreApplication::exit(1);
            return;
        }
        startReporting(app, [rig] {
            rig->setDriveCommand(Eigen::Vector2d(0.15, 1.0));  // circles in view
            return rig->recordedSeconds();
        });
    });
    wait->start(10);
    return QCoreApplication::exec();
}
