#include "app/plot/DataClipping.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prisca::app::plot {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The view in axis coordinates: x, and y or log10(y).
struct AxisSpace {
    double x0, x1, y0, y1;
    bool logY;

    explicit AxisSpace(const DataView& view)
        : x0(view.xMin),
          x1(view.xMax),
          y0(view.logY ? std::log10(view.yMin) : view.yMin),
          y1(view.logY ? std::log10(view.yMax) : view.yMax),
          logY(view.logY) {}

    double toAxis(double y) const { return logY ? (y > 0.0 ? std::log10(y) : kNaN) : y; }
    double toData(double y) const { return logY ? std::pow(10.0, y) : y; }
    QPointF toAxis(QPointF p) const { return {p.x(), toAxis(p.y())}; }
    QPointF toData(QPointF p) const { return {p.x(), toData(p.y())}; }
};

bool finite(QPointF p) {
    return std::isfinite(p.x()) && std::isfinite(p.y());
}

QPointF lerp(QPointF a, QPointF b, double t) {
    return a + (b - a) * t;
}

// Liang-Barsky: the part [t0, t1] of the segment a-b inside the box; false if none.
bool clipSegment(QPointF a, QPointF b, const AxisSpace& box, double* t0, double* t1) {
    double lo = 0.0;
    double hi = 1.0;
    const auto edge = [&](double p, double q) {
        if (p == 0.0) {
            return q >= 0.0;
        }
        const double t = q / p;
        if (p < 0.0) {
            if (t > hi) {
                return false;
            }
            lo = std::max(lo, t);
        } else {
            if (t < lo) {
                return false;
            }
            hi = std::min(hi, t);
        }
        return true;
    };
    const double dx = b.x() - a.x();
    const double dy = b.y() - a.y();
    if (!edge(-dx, a.x() - box.x0) || !edge(dx, box.x1 - a.x()) || !edge(-dy, a.y() - box.y0) ||
        !edge(dy, box.y1 - a.y())) {
        return false;
    }
    *t0 = lo;
    *t1 = hi;
    return lo <= hi;
}

// Sutherland-Hodgman against one edge: keeps the side where inside() holds.
template <typename Inside, typename Cross>
QList<QPointF> clipEdge(const QList<QPointF>& polygon, Inside inside, Cross cross) {
    QList<QPointF> out;
    for (qsizetype i = 0; i < polygon.size(); ++i) {
        const QPointF current = polygon[i];
        const QPointF previous = polygon[(i + polygon.size() - 1) % polygon.size()];
        if (inside(current)) {
            if (!inside(previous)) {
                out.append(cross(previous, current));
            }
            out.append(current);
        } else if (inside(previous)) {
            out.append(cross(previous, current));
        }
    }
    return out;
}

// Where a-b crosses x = c (or y = c), as a point on the segment.
QPointF atX(QPointF a, QPointF b, double c) {
    return lerp(a, b, (c - a.x()) / (b.x() - a.x()));
}

QPointF atY(QPointF a, QPointF b, double c) {
    return lerp(a, b, (c - a.y()) / (b.y() - a.y()));
}

// A band sample in axis coordinates.
struct Sample {
    double x, upper, lower;
};

Sample lerp(const Sample& a, const Sample& b, double t) {
    return {a.x + (b.x - a.x) * t, a.upper + (b.upper - a.upper) * t,
            a.lower + (b.lower - a.lower) * t};
}

// Inserts a sample wherever a bound crosses one of the levels between two samples, so that
// clamping the bounds to the levels afterwards cuts the band exactly.
std::vector<Sample> withCrossings(const std::vector<Sample>& samples, double y0, double y1) {
    std::vector<Sample> out;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        out.push_back(samples[i]);
        if (i + 1 == samples.size()) {
            break;
        }
        const Sample& a = samples[i];
        const Sample& b = samples[i + 1];
        std::vector<double> ts;
        for (const double level : {y0, y1}) {
            for (const auto& [from, to] : {std::pair{a.upper, b.upper}, {a.lower, b.lower}}) {
                if ((from - level) * (to - level) < 0.0) {
                    ts.push_back((level - from) / (to - from));
                }
            }
        }
        std::sort(ts.begin(), ts.end());
        for (const double t : ts) {
            out.push_back(lerp(a, b, t));
        }
    }
    return out;
}

// Cuts samples (x ascending) to [x0, x1], interpolating at the edges.
std::vector<Sample> cutToX(const std::vector<Sample>& samples, double x0, double x1) {
    std::vector<Sample> out;
    const auto inside = [&](double x) { return x >= x0 && x <= x1; };
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const Sample& a = samples[i];
        if (inside(a.x)) {
            out.push_back(a);
        }
        if (i + 1 == samples.size()) {
            break;
        }
        const Sample& b = samples[i + 1];
        for (const double edge : {x0, x1}) {
            if ((a.x - edge) * (b.x - edge) < 0.0) {
                out.push_back(lerp(a, b, (edge - a.x) / (b.x - a.x)));
            }
        }
    }
    return out;
}

}  // namespace

bool DataView::contains(QPointF point) const {
    return finite(point) && point.x() >= xMin && point.x() <= xMax && point.y() >= yMin &&
           point.y() <= yMax;
}

std::vector<QList<QPointF>> clipPolyline(const std::vector<QPointF>& points, const DataView& view) {
    const AxisSpace box(view);
    std::vector<QList<QPointF>> pieces;
    QList<QPointF> piece;
    const auto finish = [&] {
        if (piece.size() >= 2) {
            pieces.push_back(piece);
        }
        piece.clear();
    };
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const QPointF a = box.toAxis(points[i]);
        const QPointF b = box.toAxis(points[i + 1]);
        double t0 = 0.0;
        double t1 = 1.0;
        if (!finite(a) || !finite(b) || !clipSegment(a, b, box, &t0, &t1)) {
            finish();
            continue;
        }
        if (piece.isEmpty() || t0 > 0.0) {
            finish();
            piece.append(box.toData(lerp(a, b, t0)));
        }
        piece.append(box.toData(lerp(a, b, t1)));
        if (t1 < 1.0) {
            finish();
        }
    }
    finish();
    return pieces;
}

QList<QPointF> clipPolygon(const std::vector<QPointF>& points, const DataView& view) {
    const AxisSpace box(view);
    QList<QPointF> polygon;
    for (const QPointF& p : points) {
        const QPointF a = box.toAxis(p);
        if (finite(a)) {
            polygon.append(a);
        }
    }
    polygon = clipEdge(
        polygon, [&](QPointF p) { return p.x() >= box.x0; },
        [&](QPointF a, QPointF b) { return atX(a, b, box.x0); });
    polygon = clipEdge(
        polygon, [&](QPointF p) { return p.x() <= box.x1; },
        [&](QPointF a, QPointF b) { return atX(a, b, box.x1); });
    polygon = clipEdge(
        polygon, [&](QPointF p) { return p.y() >= box.y0; },
        [&](QPointF a, QPointF b) { return atY(a, b, box.y0); });
    polygon = clipEdge(
        polygon, [&](QPointF p) { return p.y() <= box.y1; },
        [&](QPointF a, QPointF b) { return atY(a, b, box.y1); });
    if (polygon.size() < 3) {
        return {};
    }
    for (QPointF& p : polygon) {
        p = box.toData(p);
    }
    return polygon;
}

std::vector<BandPiece> clipBand(const Band& band, const DataView& view) {
    const AxisSpace box(view);
    const std::size_t n = std::min({band.x.size(), band.lower.size(), band.upper.size()});
    // Below the bottom edge: where a lower bound <= 0 goes on a log axis.
    const double below = box.y0 - (box.y1 - box.y0);
    std::vector<BandPiece> pieces;
    std::size_t i = 0;
    while (i < n) {
        std::vector<Sample> run;
        for (; i < n; ++i) {
            const double upper = box.toAxis(band.upper[i]);
            double lower = box.toAxis(band.lower[i]);
            if (view.logY && std::isfinite(band.lower[i]) && band.lower[i] <= 0.0) {
                lower = below;
            }
            if (!std::isfinite(band.x[i]) || !std::isfinite(upper) || !std::isfinite(lower)) {
                ++i;
                break;
            }
            run.push_back({band.x[i], upper, lower});
        }
        run = withCrossings(cutToX(run, box.x0, box.x1), box.y0, box.y1);
        if (run.size() < 2) {
            continue;
        }
        BandPiece piece;
        for (const Sample& s : run) {
            piece.upper.append({s.x, box.toData(std::clamp(s.upper, box.y0, box.y1))});
            piece.lower.append({s.x, box.toData(std::clamp(s.lower, box.y0, box.y1))});
        }
        pieces.push_back(piece);
    }
    return pieces;
}

}  // namespace prisca::app::plot
