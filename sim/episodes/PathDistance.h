#pragma once

#include "core/Demonstration.h"
#include "sim/plants/Plant.h"

#include <vector>

namespace prisca::sim {

/// Distance from (x, y) to the segment from (ax, ay) to (bx, by), a point where the two are
/// equal. The one formula behind distanceToPath and PathDistance, so both give the same bits.
double distanceToSegment(double ax, double ay, double bx, double by, double x, double y);

/// The distance from points to one polyline, indexed once so that a query near the polyline
/// costs about the logarithm of its length, not its length: scoring a trial against a
/// demonstration of T samples takes O(T log T), not O(T^2).
///
/// The index is a hierarchy of bounding boxes over the polyline's segments, split at the median
/// along the longer side (kLeafSize segments per leaf), built in O(T log T) time and O(T) memory
/// whatever the path's shape: segments that lie together share a leaf wherever they are along
/// the path, so a long demonstration that passes the same place again and again, or a query far
/// from the path (a trial that left it), still costs a few boxes per level. A query descends
/// nearer box first and skips a box only once its distance exceeds the best distance found by
/// more than a rounding margin, so the result is exactly the brute force's: the minimum over
/// every segment (and the last vertex) of distanceToSegment.
///
/// Edge cases, as the brute force (distanceToPath): no vertex gives +infinity; one vertex, or
/// all vertices equal, gives the distance to that point; a NaN x or y gives NaN. A segment whose
/// formula gives NaN (coordinates near the largest double, where its squares overflow) counts
/// for nothing, as in the brute force. A polyline with a non-finite vertex is searched
/// exhaustively (its boxes would mean nothing).
///
/// Immutable once built; any thread may query a const PathDistance.
class PathDistance {
  public:
    /// Segments per leaf of the hierarchy at most: a leaf is scanned as the brute force would.
    static constexpr int kLeafSize = 8;

    /// @param xs, ys  the polyline's vertices in order (equal sizes; empty or one vertex allowed)
    PathDistance(std::vector<double> xs, std::vector<double> ys);
    /// The polyline through a demonstration's positions. Requires a planar vehicle (info.pose).
    PathDistance(const PlantInfo& info, const core::Demonstration& demonstration);

    /// Distance from (x, y) to the polyline [the vertices' unit].
    double distance(double x, double y) const;
    /// Vertices of the polyline, each repeated in a row counted once.
    int size() const { return static_cast<int>(xs_.size()); }

  private:
    struct Box {
        double minX, minY, maxX, maxY;
    };
    struct Node {
        Box box;
        int first = 0;  // its elements are order_[first .. first + count)
        int count = 0;
        int right = -1;  // the right child's index (the left child is the next node); -1: a leaf
    };
    // Element j is the segment from vertex j to vertex j + 1; the last element is the last
    // vertex alone (the brute force's last term).
    double element(int j, double x, double y) const;
    Box elementBox(int j) const;
    // Builds the node over order_[first .. end) and those below it; returns its index.
    int build(int first, int end, const std::vector<double>& centreX,
              const std::vector<double>& centreY);
    static Box unite(const Box& a, const Box& b);
    static double boxDistance(const Box& box, double x, double y);

    std::vector<double> xs_, ys_;
    std::vector<int> order_;   // the elements, grouped by node
    std::vector<Node> nodes_;  // depth first; nodes_[0] is the root (none if not finite_)
    double magnitude_ = 0.0;   // the largest |coordinate| of any vertex
    bool finite_ = true;       // every vertex finite (else queries are exhaustive)
};

}  // namespace prisca::sim
