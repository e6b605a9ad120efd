#include "app/plot/ChartDecimation.h"

#include <algorithm>

namespace prisca::app::plot {

QVector<QPointF> decimateMinMax(const QVector<QPointF>& points, int buckets) {
    if (buckets <= 0 || points.size() <= 4 * buckets) {
        return points;
    }
    const double x0 = points.front().x();
    const double span = points.back().x() - x0;
    if (!(span > 0.0)) {
        return {points.front(), points.back()};
    }
    QVector<QPointF> out;
    out.reserve(4 * buckets + 4);
    int start = 0;
    while (start < points.size()) {
        const int bucket =
            std::min(buckets - 1, static_cast<int>((points[start].x() - x0) / span * buckets));
        int end = start + 1;
        while (end < points.size() &&
               std::min(buckets - 1, static_cast<int>((points[end].x() - x0) / span * buckets)) ==
                   bucket) {
            ++end;
        }
        int low = start, high = start;
        for (int i = start + 1; i < end; ++i) {
            if (points[i].y() < points[low].y())
                low = i;
            if (points[i].y() > points[high].y())
                high = i;
        }
        // In x order, without repeats: first, the extremes, last.
        int picks[4] = {start, std::min(low, high), std::max(low, high), end - 1};
        int previous = -1;
        for (int i : picks) {
            if (i != previous) {
                out.push_back(points[i]);
                previous = i;
            }
        }
        start = end;
    }
    return out;
}

}  // namespace prisca::app::plot
