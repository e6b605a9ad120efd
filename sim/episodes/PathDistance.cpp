#include "sim/episodes/PathDistance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace prisca::sim {

namespace {

// A box may be skipped only if its distance exceeds the best one by more than this many times
// the query's and the path's coordinate magnitude. Rounding moves a computed distance by a few
// ulps of those magnitudes (x - ax cancels), never by 1e-12 of them, so no segment that could
// win is skipped; and 1e-12 of a lab's metres costs no pruning.
constexpr double kMarginPerMagnitude = 1e-12;

// Depth-first stack: at most one pending sibling per level plus the node popped; halving an
// int's worth of elements down to leaves takes at most 31 levels.
constexpr int kMaxStack = 64;

// The x (or y) coordinates of a demonstration's positions.
std::vector<double> poseColumn(const PlantInfo& info, const core::Demonstration& demonstration,
                               bool x) {
    if (!info.pose) {
        throw std::invalid_argument("PathDistance: a planar vehicle needed");
    }
    const Eigen::VectorXd column = demonstration.states.col(x ? info.pose->x : info.pose->y);
    return {column.data(), column.data() + column.size()};
}

}  // namespace

double distanceToSegment(double ax, double ay, double bx, double by, double x, double y) {
    const double dx = bx - ax;
    const double dy = by - ay;
    const double length2 = dx * dx + dy * dy;
    const double s =
        length2 > 0.0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / length2, 0.0, 1.0) : 0.0;
    return std::hypot(x - ax - s * dx, y - ay - s * dy);
}

PathDistance::PathDistance(std::vector<double> xs, std::vector<double> ys)
    : xs_(std::move(xs)), ys_(std::move(ys)) {
    if (xs_.size() != ys_.size()) {
        throw std::invalid_argument("PathDistance: as many x as y coordinates needed");
    }
    // A vertex equal to the one before adds a segment of no length, whose distance is that
    // vertex's, which the next segment (or the last vertex) gives again: dropped, the minimum is
    // the same to the bit. Kept, a path that stands still for thousands of samples (a take's
    // still tail) had thousands of boxes at exactly the same distance from a query, none of
    // which could be skipped: scoring turned quadratic.
    size_t kept = 0;
    for (size_t j = 0; j < xs_.size(); ++j) {
        if (kept > 0 && xs_[j] == xs_[kept - 1] && ys_[j] == ys_[kept - 1]) {
            continue;
        }
        xs_[kept] = xs_[j];
        ys_[kept] = ys_[j];
        ++kept;
    }
    xs_.resize(kept);
    ys_.resize(kept);
    if (xs_.size() > static_cast<size_t>(std::numeric_limits<int>::max())) {
        throw std::invalid_argument("PathDistance: too many vertices");
    }
    const int T = size();
    for (int j = 0; j < T; ++j) {
        finite_ = finite_ && std::isfinite(xs_[j]) && std::isfinite(ys_[j]);
        magnitude_ = std::max({magnitude_, std::abs(xs_[j]), std::abs(ys_[j])});
    }
    if (T == 0 || !finite_) {
        return;
    }
    order_.resize(T);
    for (int j = 0; j < T; ++j) {
        order_[j] = j;
    }
    std::vector<double> centreX(T), centreY(T);
    for (int j = 0; j < T; ++j) {
        const Box b = elementBox(j);
        centreX[j] = 0.5 * b.minX + 0.5 * b.maxX;  // halves first: no overflow
        centreY[j] = 0.5 * b.minY + 0.5 * b.maxY;
    }
    nodes_.reserve(T / 2 + 1);  // a leaf holds kLeafSize / 2 elements or more
    build(0, T, centreX, centreY);
}

PathDistance::PathDistance(const PlantInfo& info, const core::Demonstration& demonstration)
    : PathDistance(poseColumn(info, demonstration, true), poseColumn(info, demonstration, false)) {}

PathDistance::Box PathDistance::elementBox(int j) const {
    const int next = std::min(j + 1, size() - 1);
    return {std::min(xs_[j], xs_[next]), std::min(ys_[j], ys_[next]), std::max(xs_[j], xs_[next]),
            std::max(ys_[j], ys_[next])};
}

int PathDistance::build(int first, int end, const std::vector<double>& centreX,
                        const std::vector<double>& centreY) {
    const int index = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    nodes_[index].first = first;
    nodes_[index].count = end - first;
    if (end - first <= kLeafSize) {
        Box box = elementBox(order_[first]);
        for (int i = first + 1; i < end; ++i) {
            box = unite(box, elementBox(order_[i]));
        }
        nodes_[index].box = box;
        return index;
    }
    // Halve the elements at the median of their centres along the longer side of the centres'
    // extent: a leaf then holds segments that lie together, wherever they are along the path,
    // so a path that passes the same place again and again still has small, separate leaves.
    double minX = centreX[order_[first]], maxX = minX;
    double minY = centreY[order_[first]], maxY = minY;
    for (int i = first + 1; i < end; ++i) {
        minX = std::min(minX, centreX[order_[i]]);
        maxX = std::max(maxX, centreX[order_[i]]);
        minY = std::min(minY, centreY[order_[i]]);
        maxY = std::max(maxY, centreY[order_[i]]);
    }
    const std::vector<double>& key = maxX - minX >= maxY - minY ? centreX : centreY;
    const int middle = first + (end - first) / 2;
    std::nth_element(order_.begin() + first, order_.begin() + middle, order_.begin() + end,
                     [&](int a, int b) { return key[a] < key[b] || (key[a] == key[b] && a < b); });
    const int left = build(first, middle, centreX, centreY);  // the next node
    const int right = build(middle, end, centreX, centreY);
    nodes_[index].right = right;
    nodes_[index].box = unite(nodes_[left].box, nodes_[right].box);
    return index;
}

double PathDistance::element(int j, double x, double y) const {
    const int next = std::min(j + 1, size() - 1);
    return distanceToSegment(xs_[j], ys_[j], xs_[next], ys_[next], x, y);
}

PathDistance::Box PathDistance::unite(const Box& a, const Box& b) {
    return {std::min(a.minX, b.minX), std::min(a.minY, b.minY), std::max(a.maxX, b.maxX),
            std::max(a.maxY, b.maxY)};
}

double PathDistance::boxDistance(const Box& box, double x, double y) {
    const double dx = std::max({box.minX - x, 0.0, x - box.maxX});
    const double dy = std::max({box.minY - y, 0.0, y - box.maxY});
    return std::hypot(dx, dy);
}

double PathDistance::distance(double x, double y) const {
    if (std::isnan(x) || std::isnan(y)) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    double best = std::numeric_limits<double>::infinity();
    if (nodes_.empty()) {  // no vertex (+infinity), or a non-finite one: every element
        for (int j = 0; j < size(); ++j) {
            best = std::min(best, element(j, x, y));
        }
        return best;
    }
    // An infinite query, or magnitudes that overflow, make the margin infinite: nothing is
    // skipped and the search is the brute force's.
    const double margin = kMarginPerMagnitude * (std::abs(x) + std::abs(y) + magnitude_);
    struct Pending {
        int node;
        double bound;  // the node's box's distance from (x, y)
    };
    std::array<Pending, kMaxStack> stack;
    int top = 0;
    stack[top++] = {0, boxDistance(nodes_[0].box, x, y)};
    while (top > 0) {
        const Pending pending = stack[--top];
        if (pending.bound - margin > best) {
            continue;  // nothing in this box can come nearer than what was found
        }
        const Node& node = nodes_[pending.node];
        if (node.right < 0) {
            for (int i = node.first; i < node.first + node.count; ++i) {
                best = std::min(best, element(order_[i], x, y));
            }
            continue;
        }
        Pending near{pending.node + 1, boxDistance(nodes_[pending.node + 1].box, x, y)};
        Pending far{node.right, boxDistance(nodes_[node.right].box, x, y)};
        if (far.bound < near.bound) {
            std::swap(near, far);
        }
        stack[top++] = far;  // popped after the nearer one has tightened best
        stack[top++] = near;
    }
    return best;
}

}  // namespace prisca::sim
