// The floor calibration reader on arbitrary bytes: it never crashes, and what it accepts maps
// the image into a bounded floor and back.
#include "FuzzTarget.h"

#include "devices/FloorCalibration.h"

#include <cmath>

using namespace prisca::devices;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const QByteArray json(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    QString error;
    const auto calibration = FloorCalibration::fromJson(json, &error);
    if (!calibration) {
        FUZZ_CHECK(!error.isEmpty());
        return 0;
    }
    FUZZ_CHECK(calibration->homographyProblem().isEmpty());
    FUZZ_CHECK(calibration->rmsMetres >= 0.0);
    const cv::Point2d floor = calibration->toFloor({320.0, 240.0});
    FUZZ_CHECK(std::isfinite(floor.x) && std::isfinite(floor.y));
    FUZZ_CHECK(std::abs(floor.x) <= FloorCalibration::kMaxFloorMetres &&
               std::abs(floor.y) <= FloorCalibration::kMaxFloorMetres);
    // Written and read back, it is the same calibration.
    const auto back = FloorCalibration::fromJson(calibration->toJson(), &error);
    FUZZ_CHECK(back);
    for (int i = 0; i < 9; ++i) {
        FUZZ_CHECK(back->imageToFloor.val[i] == calibration->imageToFloor.val[i]);
    }
    return 0;
}
