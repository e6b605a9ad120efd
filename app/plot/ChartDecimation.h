#pragma once

#include <QPointF>
#include <QVector>

namespace prisca::app::plot {

/// Reduces a series sorted by x to at most about 4 points per bucket (the first, lowest,
/// highest and last point of each of `buckets` equal slices of its x range, in x order), so a
/// chart drawn from it shows every spike of the full series at a fraction of the points.
/// Series with at most 4 * buckets points are returned unchanged.
QVector<QPointF> decimateMinMax(const QVector<QPointF>& points, int buckets);

}  // namespace prisca::app::plot
