// Devices benchmarks (make bench): the IR-LED tracker on a 640 x 480 frame, over the full frame
// and once locked (region of interest).
#include "devices/LedTracker.h"
#include "devices/SyntheticCamera.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace prisca::devices;
using Clock = std::chrono::steady_clock;

int main() {
    const FloorCalibration camera = syntheticCeilingCamera();
    SyntheticCameraSettings settings;
    settings.noise = 4.0;
    settings.blur = 0.6;
    settings.reflections = 2;
    std::vector<cv::Mat> frames;
    for (int i = 0; i < 200; ++i) {
        const PlanarPose pose{0.5 + 0.01 * i, 0.2 * std::sin(i * 0.05), 0.02 * i};
        frames.push_back(renderLeds(pose, camera, settings, LedGeometry{}, i + 1));
    }
    for (const bool locked : {false, true}) {
        std::vector<double> ms;
        LedTracker tracker;
        int found = 0;
        for (int repeat = 0; repeat < 3; ++repeat) {
            for (const cv::Mat& frame : frames) {
                if (!locked) {
                    tracker.reset();
                }
                const auto start = Clock::now();
                const TrackResult r = tracker.track(frame, camera);
                ms.push_back(
                    std::chrono::duration<double, std::milli>(Clock::now() - start).count());
                found += r.pose ? 1 : 0;
            }
        }
        std::sort(ms.begin(), ms.end());
        std::printf(
            "IR-LED tracker, 640x480, %s: median %.3f ms, 95th percentile %.3f ms "
            "(%d of %zu frames with a pose)\n",
            locked ? "locked (region of interest)" : "full frame", ms[ms.size() / 2],
            ms[ms.size() * 95 / 100], found, ms.size());
    }
    return 0;
}
