// The floor calibration's fit on arbitrary clicked points: it never crashes; a refusal says why
// in one line; an accepted calibration maps every point's image to a bounded floor position and
// back, its residuals and RMS are finite, and it saves to a file that loads back.
//
// Input: point records, one after the other, until the bytes run out (at most 64 points; a
// record cut short reads zeros). A record is an op byte, then its operands:
//   op % 8 = 0..3  a new point: image u, v [px] and floor x, y [m], each a value (below)
//            4     a copy of an earlier point (index byte)
//            5     on the line through two earlier points, in the image and on the floor alike
//                  (index bytes i, j; t = signed byte / 16: p_i + t (p_j - p_i))
//            6     an earlier point's image (index byte) with a new floor x, y
//            7     a new image u, v with its floor on the line through two earlier floors (i, j, t)
// (4 to 7 with no earlier point make a new point.) A value is a kind byte, then:
//   kind % 4 = 0, 1  a little-endian int16 / 16 for px, / 1000 for m (a grid of exact values)
//              2     a byte indexing kSpecial (NaN, infinities, 1e300, the smallest, ...)
//              3     8 bytes of a raw double
#include "FuzzTarget.h"

#include "devices/FloorCalibration.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

using namespace prisca::devices;

namespace {

constexpr std::size_t kMaxPoints = 64;

const double kSpecial[] = {std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity(),
                           1e300,
                           -1e300,
                           std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::min(),
                           std::numeric_limits<double>::denorm_min(),
                           0.0,
                           -0.0,
                           1e-300,
                           1e-9,
                           1e15,
                           1e6,
                           FloorCalibration::kMaxFloorMetres,
                           std::nextafter(FloorCalibration::kMaxFloorMetres, 2e3),
                           640.0,
                           480.0};

class Reader {
  public:
    Reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    bool done() const { return at_ >= size_; }
    std::uint8_t byte() { return at_ < size_ ? data_[at_++] : 0; }
    double value(double unit) {
        const std::uint8_t kind = byte();
        switch (kind % 4) {
            case 2:
                return kSpecial[byte() % (sizeof(kSpecial) / sizeof(kSpecial[0]))];
            case 3: {
                std::uint8_t raw[8];
                for (std::uint8_t& b : raw) {
                    b = byte();
                }
                double d;
                std::memcpy(&d, raw, sizeof d);
                return d;
            }
            default: {
                const std::uint16_t low = byte();
                const auto v = static_cast<std::int16_t>(low | (std::uint16_t(byte()) << 8));
                return v / unit;
            }
        }
    }
    cv::Point2d image() {
        const double u = value(16.0);
        return {u, value(16.0)};
    }
    cv::Point2d floor() {
        const double x = value(1000.0);
        return {x, value(1000.0)};
    }

  private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t at_ = 0;
};

std::vector<CalibrationPoint> decode(const std::uint8_t* data, std::size_t size) {
    Reader in(data, size);
    std::vector<CalibrationPoint> points;
    while (!in.done() && points.size() < kMaxPoints) {
        const int op = in.byte() % 8;
        const auto earlier = [&] { return points[in.byte() % points.size()]; };
        const auto along = [&](const cv::Point2d& a, const cv::Point2d& b) {
            const double t = static_cast<std::int8_t>(in.byte()) / 16.0;
            return a + t * (b - a);
        };
        CalibrationPoint p;
        if (op < 4 || points.empty()) {
            p.image = in.image();
            p.floor = in.floor();
        } else if (op == 4) {
            p = earlier();
        } else if (op == 5) {
            const CalibrationPoint a = earlier(), b = earlier();
            const double t = static_cast<std::int8_t>(in.byte()) / 16.0;
            p.image = a.image + t * (b.image - a.image);
            p.floor = a.floor + t * (b.floor - a.floor);  // the same t: a collinear pair
        } else if (op == 6) {
            p.image = earlier().image;
            p.floor = in.floor();
        } else {
            p.image = in.image();
            const CalibrationPoint a = earlier(), b = earlier();
            p.floor = along(a.floor, b.floor);
        }
        points.push_back(p);
    }
    return points;
}

// A message for the operator: not empty, one line, no control character.
void checkMessage(const QString& message) {
    FUZZ_CHECK(!message.isEmpty());
    for (const QChar c : message) {
        const char16_t u = c.unicode();
        FUZZ_CHECK(!(u < 0x20 || u == 0x7f || (u >= 0x80 && u < 0xa0)));
    }
}

bool finite(const cv::Point2d& p) {
    return std::isfinite(p.x) && std::isfinite(p.y);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::vector<CalibrationPoint> points = decode(data, size);
    QString error;
    const auto calibration = FloorCalibration::fit(points, &error);
    if (!calibration) {
        checkMessage(error);
        return 0;
    }
    FUZZ_CHECK(points.size() >= 4);
    FUZZ_CHECK(calibration->homographyProblem().isEmpty());
    FUZZ_CHECK(calibration->points.size() == points.size());
    FUZZ_CHECK(std::isfinite(calibration->rmsMetres) && calibration->rmsMetres >= 0.0);
    const std::vector<double> residuals = calibration->residuals();
    FUZZ_CHECK(residuals.size() == points.size());
    double largest = 0.0;
    for (double r : residuals) {
        FUZZ_CHECK(std::isfinite(r) && r >= 0.0);
        largest = std::max(largest, r);
    }
    // The root mean square of the residuals is at most their largest.
    FUZZ_CHECK(calibration->rmsMetres <= largest * (1.0 + 1e-12));

    // The image's size: the VGA frame the calibration is judged on, or the points' extent.
    double extent = 640.0;
    for (const CalibrationPoint& p : points) {
        extent = std::max({extent, std::abs(p.image.x), std::abs(p.image.y)});
    }
    // Within the floor's bound up to rounding: the bound is checked with the homography scaled
    // to its largest entry 1, toFloor() uses it as stored (1000 m can come out 1 ulp over).
    const double bound = FloorCalibration::kMaxFloorMetres * (1.0 + 1e-12);
    for (const CalibrationPoint& p : points) {
        const cv::Point2d floor = calibration->toFloor(p.image);
        FUZZ_CHECK(finite(floor));
        FUZZ_CHECK(std::abs(floor.x) <= bound && std::abs(floor.y) <= bound);
        // Back to the image to within 1e-6 of its size (under 0.001 px on a VGA frame). In exact
        // arithmetic the round trip is the identity; in doubles it loses about cond(H) x 1e-16
        // of the size. A ceiling camera's homography (px -> m: scales 1e-4..1 m/px, a floor
        // within +-1 km) has cond(H) well under 1e8, so 1e-6 leaves a margin of 100 or more;
        // only a homography no camera over a floor has misses it.
        const cv::Point2d back = calibration->toImage(floor);
        FUZZ_CHECK(finite(back));
        FUZZ_CHECK(cv::norm(back - p.image) <= 1e-6 * extent);
    }

    // It saves and loads back as the same calibration.
    const auto loaded = FloorCalibration::fromJson(calibration->toJson(), &error);
    FUZZ_CHECK(loaded);
    for (int i = 0; i < 9; ++i) {
        FUZZ_CHECK(loaded->imageToFloor.val[i] == calibration->imageToFloor.val[i]);
    }
    FUZZ_CHECK(loaded->rmsMetres == calibration->rmsMetres);
    return 0;
}
