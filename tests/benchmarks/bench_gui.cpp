// GUI benchmark (make bench): the live charts holding 100,000 points of a 40 Hz stream. Each
// frame adds one 40 ms batch (2 samples), redraws the decimated series and paints the panel,
// as the application does; the frame time must stay well under the 40 ms batch period for the
// window to stay fluid.
#include "app/panels/LiveChartsPanel.h"
#include "sim/PlantCatalog.h"

#include <QApplication>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace prisca;
using Clock = std::chrono::steady_clock;

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication application(argc, argv);
    const sim::PlantInfo info = sim::PlantCatalog::describe(QStringLiteral("slidecar"));
    app::LiveChartsPanel panel;
    panel.resize(900, 320);
    panel.setPlant(info, 6);
    panel.show();

    const auto sample = [&](int k) {
        app::LiveSample s;
        s.step = k;
        s.runTime = k * 0.025;
        s.state = Eigen::VectorXd::Zero(6);
        s.action = Eigen::Vector2d(std::sin(k * 0.01), std::cos(k * 0.013));
        s.referenceAction = Eigen::Vector2d(std::sin(k * 0.01 + 0.1), std::cos(k * 0.013 + 0.1));
        s.theta = Eigen::VectorXd::Constant(6, std::sin(k * 0.001));
        s.trackedError = 0.1 + 0.05 * std::sin(k * 0.05) + ((k % 997) == 0 ? 1.0 : 0.0);
        return s;
    };
    QVector<app::LiveSample> batch;
    for (int k = 0; k < 100000; ++k) {
        batch.push_back(sample(k));
        if (batch.size() == 1000) {
            panel.addSamples(batch);
            batch.clear();
        }
    }
    std::vector<double> frames;
    for (int frame = 0; frame < 60; ++frame) {
        const auto start = Clock::now();
        panel.addSamples({sample(100000 + 2 * frame), sample(100001 + 2 * frame)});
        panel.redraw();
        const QPixmap painted = panel.grab();  // the paint the window would do
        frames.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        if (painted.isNull()) {
            std::printf("bench_gui: nothing painted\n");
            return 1;
        }
    }
    std::sort(frames.begin(), frames.end());
    std::printf(
        "live charts, %d points buffered, %d drawn: frame (batch + redraw + paint) median "
        "%.1f ms, 95th percentile %.1f ms, worst (the first paint) %.1f ms; batch period "
        "40 ms\n",
        panel.bufferedPoints(), panel.drawnPoints(), frames[frames.size() / 2],
        frames[frames.size() * 95 / 100], frames.back());
    return 0;
}
