// Writes what a wide-lens ceiling camera would give a lab setting up its rig, from the
// synthetic wide-lens camera (devices::syntheticWideLensCamera, k1 = -0.3):
//   DIR/views/viewNN.png   chessboard views (9 x 6 inner corners, 40 mm squares)
//   DIR/views.avi          the same views as a camera would stream them (2 s each, 10 fps)
//   DIR/floor.csv          floor markers: u, v [px] (to a quarter pixel), x, y [m]
//   DIR/truth.json         the camera's true floor calibration (with its lens)
// Usage: make_lens_views DIR [VIEWS]
#include "devices/SyntheticCamera.h"

#include <QDir>
#include <QFile>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <cstdio>

using namespace prisca::devices;

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: make_lens_views DIR [VIEWS]\n");
        return 2;
    }
    const QString dir = QString::fromLocal8Bit(argv[1]);
    const int count = argc > 2 ? std::atoi(argv[2]) : 14;
    QDir().mkpath(dir + "/views");
    const FloorCalibration truth = syntheticWideLensCamera(-0.3);
    const BoardViewRenderer renderer(*truth.lens);
    const BoardSpec board;
    cv::VideoWriter video((dir + "/views.avi").toStdString(), cv::CAP_OPENCV_MJPEG,
                          cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 10.0, cv::Size(640, 480),
                          true);
    video.set(cv::VIDEOWRITER_PROP_QUALITY, 95);
    const auto poses = renderer.poses(board, count, 11);
    for (size_t i = 0; i < poses.size(); ++i) {
        const cv::Mat view = renderer.render(board, poses[i].first, poses[i].second, 2.0, i + 1);
        char name[64];
        std::snprintf(name, sizeof name, "/views/view%02zu.png", i);
        cv::imwrite((dir + name).toStdString(), view);
        cv::Mat bgr;
        cv::cvtColor(view, bgr, cv::COLOR_GRAY2BGR);
        for (int k = 0; k < 20; ++k) {
            video.write(bgr);
        }
    }
    video.release();
    const QByteArray csv = floorMarkersCsv(syntheticFloorMarkers(truth, 6, 5, 0.25, 5));
    QFile f(dir + "/floor.csv");
    f.open(QIODevice::WriteOnly);
    f.write(csv);
    f.close();
    QString error;
    truth.save(dir + "/truth.json", &error);
    std::printf("%zu views in %s/views and %s/views.avi; floor.csv; truth.json\n", poses.size(),
                argv[1], argv[1]);
    return 0;
}
