#include "app/widgets/ArenaView.h"

#include "sim/plants/SlideCar.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace prisca::app {

namespace {

// The simulated car's own dimensions for drawing [m] (one definition: SlideCarParameters).
constexpr sim::SlideCarParameters kCar{};
constexpr double kCarLength = kCar.length;
constexpr double kCarWidth = kCar.width;
constexpr double kHalfWheelbase = kCar.wheelbase / 2;
constexpr double kMaxSteeringAngle = kCar.maxSteeringAngle;  // rad at full steering
constexpr double kSkidSpeed = 0.15;  // lateral speed above which a skid mark is left [m/s]
// The parking lot drawn around the demonstration's final pose [m].
constexpr double kLotLength = 0.55;
constexpr double kLotWidth = 0.32;
// Acrobot links [m].
constexpr double kLink = 1.0;
constexpr double kMinAircraftPixels = 28.0;  // the aircraft is drawn at least this long
constexpr int kMaxTrailPoints = 200000;

const QColor kDesiredColour(0x2c, 0xa0, 0x2c);
const QColor kActualColour(0xd6, 0x27, 0x28);

QPen cosmetic(const QColor& colour, double width, Qt::PenStyle style = Qt::SolidLine) {
    QPen pen(colour, width, style);
    pen.setCosmetic(true);
    return pen;
}

}  // namespace

ArenaView::ArenaView(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("arenaView"));
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(240, 180);
    setAutoFillBackground(false);
}

void ArenaView::setScene(const sim::PlantInfo& info,
                         std::shared_ptr<const core::Demonstration> demonstration) {
    info_ = info;
    const sim::PlantEntry* entry = sim::PlantCatalog::find(info.name);
    drawing_ = entry ? entry->drawing : sim::PlantEntry::Drawing::Vehicle;
    demonstration_ = std::move(demonstration);
    desired_.clear();
    // A demonstration that does not carry what the drawing reads (the pose's columns, the
    // arm's two angles, one row) is not drawn.
    if (demonstration_) {
        const Eigen::MatrixXd& s = demonstration_->states;
        const int needed =
            info_.pose ? 1 + std::max({info_.pose->x, info_.pose->y, info_.pose->heading}) : 2;
        if (s.rows() == 0 || s.cols() < needed || demonstration_->actions.rows() == 0) {
            demonstration_.reset();
        }
    }
    if (demonstration_) {
        const Eigen::MatrixXd& s = demonstration_->states;
        for (Eigen::Index k = 0; k < s.rows(); ++k) {
            if (info_.pose) {
                desired_.push_back({s(k, info_.pose->x), s(k, info_.pose->y)});
            } else if (s.cols() >= 2) {
                desired_.push_back(acrobotTip(s(k, 0), s(k, 1), nullptr));
            }
        }
        state_ = s.row(0).transpose();
        action_ = demonstration_->actions.row(0).transpose();
    }
    referenceIndex_ = 0;
    clearTrails();
    userMoved_ = false;
    fitScene();
}

void ArenaView::setTrail(const QVector<QPointF>& points) {
    trail_ = points;
    update();
}

void ArenaView::setFence(const QVector<QPointF>& corners) {
    fence_ = corners;
    update();
}

void ArenaView::clearTrails() {
    trail_.clear();
    lastTrail_.clear();
    skidMarks_.clear();
    trial_ = -1;
    wind_.reset();
    update();
}

void ArenaView::addSamples(const QVector<LiveSample>& samples) {
    for (const LiveSample& sample : samples) {
        if (sample.trial != trial_) {
            lastTrail_ = trail_;
            trail_.clear();
            skidMarks_.clear();
            trial_ = sample.trial;
        }
        const Eigen::VectorXd& s = sample.state;
        if (info_.pose) {
            trail_.push_back({s[info_.pose->x], s[info_.pose->y]});
            if (drawing_ == sim::PlantEntry::Drawing::Car && s.size() >= 5 &&
                std::abs(s[4]) > kSkidSpeed) {
                const double psi = s[info_.pose->heading];
                skidMarks_.push_back(
                    {s[0] - kHalfWheelbase * std::cos(psi), s[1] - kHalfWheelbase * std::sin(psi)});
            }
        } else if (s.size() >= 2) {
            trail_.push_back(acrobotTip(s[0], s[1], nullptr));
        }
        if (trail_.size() > kMaxTrailPoints) {
            trail_.remove(0, trail_.size() - kMaxTrailPoints);
        }
        state_ = s;
        action_ = sample.action;
        wind_ = sample.wind;
        referenceIndex_ = sample.referenceIndex;
    }
    if (!samples.isEmpty()) {
        followRobot();
        update();
    }
}

std::optional<QPointF> ArenaView::robotPosition() const {
    if (!info_.pose || state_.size() <= std::max(info_.pose->x, info_.pose->y)) {
        return std::nullopt;
    }
    return QPointF(state_[info_.pose->x], state_[info_.pose->y]);
}

void ArenaView::followRobot() {
    // The view follows a robot about to leave it, unless the operator placed the view.
    const auto car = robotPosition();
    if (userMoved_ || !car) {
        return;
    }
    const QPointF at = toScreen(*car);
    const double margin = 0.05 * std::min(width(), height());
    if (at.x() < margin || at.y() < margin || at.x() > width() - margin ||
        at.y() > height() - margin) {
        fitScene();
    }
}

void ArenaView::showState(const Eigen::VectorXd& state, const Eigen::VectorXd& action) {
    state_ = state;
    action_ = action;
    followRobot();
    update();
}

QRectF ArenaView::sceneBounds() const {
    if (!info_.pose) {
        return QRectF(QPointF(-2.3, -2.3), QPointF(2.3, 2.3));
    }
    if (desired_.isEmpty()) {
        return QRectF(-1, -1, 2, 2);
    }
    double x0 = desired_[0].x(), x1 = x0, y0 = desired_[0].y(), y1 = y0;
    for (const QPointF& p : desired_) {
        x0 = std::min(x0, p.x());
        x1 = std::max(x1, p.x());
        y0 = std::min(y0, p.y());
        y1 = std::max(y1, p.y());
    }
    // The robot and its trail too: a car that left the path is still in the picture.
    const auto include = [&](const QPointF& p) {
        if (std::isfinite(p.x()) && std::isfinite(p.y())) {
            x0 = std::min(x0, p.x());
            x1 = std::max(x1, p.x());
            y0 = std::min(y0, p.y());
            y1 = std::max(y1, p.y());
        }
    };
    for (const QPointF& p : trail_) {
        include(p);
    }
    if (const auto car = robotPosition()) {
        include(*car);
    }
    const double margin = 0.12 * std::max(x1 - x0, y1 - y0) + 0.3;
    return QRectF(QPointF(x0 - margin, y0 - margin), QPointF(x1 + margin, y1 + margin));
}

void ArenaView::fitScene() {
    // The scene fits the area the axis labels leave free (the y labels on the right, the x
    // labels along the bottom), so no label is drawn over the robot or its path.
    constexpr double kRightLabels = 60.0;   // [px]
    constexpr double kBottomLabels = 30.0;  // [px]
    const QRectF bounds = sceneBounds();
    const double w = std::max(kRightLabels + 1.0, static_cast<double>(width()));
    const double h = std::max(kBottomLabels + 1.0, static_cast<double>(height()));
    scale_ = std::min((w - kRightLabels) / bounds.width(), (h - kBottomLabels) / bounds.height());
    centre_ = bounds.center() + QPointF(0.5 * kRightLabels / scale_, -0.5 * kBottomLabels / scale_);
    update();
}

QPointF ArenaView::toScreen(const QPointF& world) const {
    return {width() / 2.0 + (world.x() - centre_.x()) * scale_,
            height() / 2.0 - (world.y() - centre_.y()) * scale_};
}

QPointF ArenaView::toWorld(const QPointF& screen) const {
    return {centre_.x() + (screen.x() - width() / 2.0) / scale_,
            centre_.y() - (screen.y() - height() / 2.0) / scale_};
}

QPointF ArenaView::acrobotTip(double theta1, double theta2, QPointF* elbow) const {
    // theta1 from the downward vertical, theta2 relative to link 1, counter-clockwise.
    const QPointF e(kLink * std::sin(theta1), -kLink * std::cos(theta1));
    if (elbow) {
        *elbow = e;
    }
    return e + QPointF(kLink * std::sin(theta1 + theta2), -kLink * std::cos(theta1 + theta2));
}

void ArenaView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), QColor(0xfa, 0xfa, 0xf7));
    drawGrid(painter);
    if (drawing_ == sim::PlantEntry::Drawing::Arm) {
        drawAcrobot(painter);
    } else if (info_.pose) {
        drawPlanar(painter);
    }
    if (wind_) {
        drawWind(painter);
    }
    // Legend.
    painter.setPen(cosmetic(kDesiredColour, 2.5));
    painter.drawLine(QPointF(12, 16), QPointF(36, 16));
    painter.setPen(cosmetic(kActualColour, 1.5));
    painter.drawLine(QPointF(12, 34), QPointF(36, 34));
    painter.setPen(palette().color(QPalette::Text));
    painter.drawText(QPointF(42, 20), tr("desired"));
    painter.drawText(QPointF(42, 38), tr("actual"));
}

void ArenaView::drawGrid(QPainter& painter) const {
    static const double steps[] = {0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1,   2,
                                   5,    10,   20,   50,  100, 200, 500, 1000};
    double step = steps[std::size(steps) - 1];
    for (double s : steps) {
        if (s * scale_ >= 60.0) {
            step = s;
            break;
        }
    }
    const QPointF topLeft = toWorld(QPointF(0, 0));
    const QPointF bottomRight = toWorld(QPointF(width(), height()));
    // At most about 60 lines each way a paint, however far out the view is (a span of
    // thousands of steps, or values where adding a step no longer moves: a line counter, not a
    // running sum, ends each loop).
    constexpr int kMostLines = 60;
    const double span = std::max(bottomRight.x() - topLeft.x(), topLeft.y() - bottomRight.y());
    if (!std::isfinite(span) || !std::isfinite(topLeft.x()) || !std::isfinite(topLeft.y())) {
        return;
    }
    while (span / step > kMostLines) {
        step *= 10.0;
    }
    const QFontMetrics metrics(font());
    const auto label = [&](double value) {
        return step < 1.0 ? tr("%1 cm").arg(std::round(value * 100.0))
                          : tr("%1 m").arg(std::round(value), 0, 'g', 6);
    };
    const double firstX = std::ceil(topLeft.x() / step);
    for (int i = 0; i <= kMostLines + 1; ++i) {
        const double x = (firstX + i) * step;
        if (x > bottomRight.x()) {
            break;
        }
        const double sx = toScreen({x, 0}).x();
        const bool axis = std::abs(x) < step * 1e-6;
        painter.setPen(cosmetic(axis ? QColor(0xb0, 0xb0, 0xb0) : QColor(0xe2, 0xe2, 0xe2), 1));
        painter.drawLine(QPointF(sx, 0), QPointF(sx, height()));
        painter.setPen(QColor(0x80, 0x80, 0x80));
        painter.drawText(QPointF(sx + 3, height() - 4), label(x));
    }
    const double firstY = std::ceil(bottomRight.y() / step);
    for (int i = 0; i <= kMostLines + 1; ++i) {
        const double y = (firstY + i) * step;
        if (y > topLeft.y()) {
            break;
        }
        const double sy = toScreen({0, y}).y();
        const bool axis = std::abs(y) < step * 1e-6;
        painter.setPen(cosmetic(axis ? QColor(0xb0, 0xb0, 0xb0) : QColor(0xe2, 0xe2, 0xe2), 1));
        painter.drawLine(QPointF(0, sy), QPointF(width(), sy));
        painter.setPen(QColor(0x80, 0x80, 0x80));
        painter.drawText(QPointF(width() - metrics.horizontalAdvance(label(y)) - 4, sy - 3),
                         label(y));
    }
}

void ArenaView::drawPlanar(QPainter& painter) const {
    const auto polyline = [&](const QVector<QPointF>& points) {
        QPolygonF screen;
        screen.reserve(points.size());
        for (const QPointF& p : points) {
            screen << toScreen(p);
        }
        painter.drawPolyline(screen);
    };
    const bool car = drawing_ == sim::PlantEntry::Drawing::Car;
    // The parking lot: the demonstration's final pose.
    if (car && demonstration_ && demonstration_->length() > 0) {
        const Eigen::VectorXd lot = demonstration_->states.row(demonstration_->length() - 1);
        painter.save();
        painter.translate(toScreen({lot[info_.pose->x], lot[info_.pose->y]}));
        painter.scale(scale_, -scale_);
        painter.rotate(lot[info_.pose->heading] * 180.0 / M_PI);
        painter.setPen(cosmetic(QColor(0x1f, 0x77, 0xb4), 2, Qt::DashLine));
        painter.setBrush(QColor(0x1f, 0x77, 0xb4, 24));
        painter.drawRect(QRectF(-kLotLength / 2, -kLotWidth / 2, kLotLength, kLotWidth));
        painter.restore();
    }
    if (fence_.size() >= 3) {
        // The fence: where a trial on the rig ends in failsafe.
        painter.setBrush(Qt::NoBrush);
        painter.setPen(cosmetic(QColor(0xd3, 0x2f, 0x2f), 2, Qt::DashDotLine));
        QVector<QPointF> closed = fence_;
        closed << fence_.front();
        polyline(closed);
    }
    painter.setBrush(Qt::NoBrush);
    painter.setPen(cosmetic(kDesiredColour, 2.5));
    polyline(desired_);
    if (!lastTrail_.isEmpty()) {
        painter.setPen(cosmetic(
            QColor(kActualColour.red(), kActualColour.green(), kActualColour.blue(), 70), 1.2));
        polyline(lastTrail_);
    }
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0x40, 0x40, 0x40, 90));
    for (const QPointF& p : skidMarks_) {
        painter.drawEllipse(toScreen(p), 1.6, 1.6);
    }
    painter.setBrush(Qt::NoBrush);
    painter.setPen(cosmetic(kActualColour, 1.5));
    polyline(trail_);
    // The reference the controller matched.
    if (demonstration_ && referenceIndex_ >= 0 && referenceIndex_ < desired_.size()) {
        painter.setPen(cosmetic(kDesiredColour, 1.5));
        painter.setBrush(Qt::white);
        painter.drawEllipse(toScreen(desired_[referenceIndex_]), 4, 4);
    }
    if (state_.size() == info_.stateDimension()) {
        if (car) {
            const double steering = action_.size() >= 2 ? action_[1] : 0.0;
            drawCar(painter, state_, steering);
        } else if (drawing_ == sim::PlantEntry::Drawing::Aircraft) {
            drawAircraft(painter, state_);
        } else {
            drawMarker(painter, state_);
        }
    }
}

void ArenaView::drawMarker(QPainter& painter, const Eigen::VectorXd& s) const {
    // Any other planar vehicle: an arrow at its pose, a fixed size on screen.
    painter.save();
    painter.translate(toScreen({s[info_.pose->x], s[info_.pose->y]}));
    painter.rotate(-s[info_.pose->heading] * 180.0 / M_PI);
    QPolygonF arrow;
    arrow << QPointF(12, 0) << QPointF(-8, 7) << QPointF(-4, 0) << QPointF(-8, -7);
    painter.setPen(cosmetic(QColor(0x20, 0x20, 0x20), 1));
    painter.setBrush(QColor(0x2c, 0xa0, 0x2c));
    painter.drawPolygon(arrow);
    painter.restore();
}

void ArenaView::drawCar(QPainter& painter, const Eigen::VectorXd& s, double steering) const {
    painter.save();
    painter.translate(toScreen({s[info_.pose->x], s[info_.pose->y]}));
    painter.scale(scale_, -scale_);
    painter.rotate(s[info_.pose->heading] * 180.0 / M_PI);
    painter.setPen(cosmetic(QColor(0x20, 0x20, 0x20), 1));
    painter.setBrush(QColor(0x33, 0x33, 0x33));
    const double wheelLength = 0.07, wheelWidth = 0.035;
    const double track = kCarWidth / 2 - 0.005;
    for (double ax : {kHalfWheelbase, -kHalfWheelbase}) {
        for (double side : {track, -track}) {
            painter.save();
            painter.translate(ax, side);
            if (ax > 0) {
                painter.rotate(std::clamp(steering, -1.0, 1.0) * kMaxSteeringAngle * 180.0 / M_PI);
            }
            painter.drawRect(QRectF(-wheelLength / 2, -wheelWidth / 2, wheelLength, wheelWidth));
            painter.restore();
        }
    }
    painter.setBrush(QColor(0xff, 0x8c, 0x1a, 220));
    painter.drawRoundedRect(
        QRectF(-kCarLength / 2, -kCarWidth / 2 + 0.02, kCarLength, kCarWidth - 0.04), 0.03, 0.03);
    // Windscreen marks the front.
    painter.setBrush(QColor(0x30, 0x50, 0x70));
    painter.drawRect(QRectF(0.04, -0.05, 0.06, 0.10));
    painter.restore();
}

void ArenaView::drawAircraft(QPainter& painter, const Eigen::VectorXd& s) const {
    painter.save();
    painter.translate(toScreen({s[info_.pose->x], s[info_.pose->y]}));
    // Real size (about 1.2 m long) is a dot at mission scale: never smaller than a few pixels.
    const double pixels = std::max(kMinAircraftPixels, 1.2 * scale_);
    painter.scale(pixels, -pixels);
    painter.rotate(s[info_.pose->heading] * 180.0 / M_PI);
    QPainterPath plane;
    plane.moveTo(0.55, 0);  // nose
    plane.lineTo(0.1, 0.06);
    plane.lineTo(0.05, 0.75);  // left wing tip
    plane.lineTo(-0.1, 0.75);
    plane.lineTo(-0.1, 0.06);
    plane.lineTo(-0.4, 0.05);
    plane.lineTo(-0.5, 0.25);  // tail
    plane.lineTo(-0.55, 0.25);
    plane.lineTo(-0.5, 0);
    plane.lineTo(-0.55, -0.25);
    plane.lineTo(-0.5, -0.25);
    plane.lineTo(-0.4, -0.05);
    plane.lineTo(-0.1, -0.06);
    plane.lineTo(-0.1, -0.75);
    plane.lineTo(0.05, -0.75);
    plane.lineTo(0.1, -0.06);
    plane.closeSubpath();
    painter.setPen(cosmetic(QColor(0x20, 0x20, 0x20), 1));
    painter.setBrush(QColor(0x5a, 0x7d, 0xb5));
    painter.drawPath(plane);
    painter.restore();
}

void ArenaView::drawAcrobot(QPainter& painter) const {
    const QPointF pivot = toScreen({0, 0});
    const auto drawArm = [&](double t1, double t2, const QColor& colour, double width) {
        QPointF elbow;
        const QPointF tip = acrobotTip(t1, t2, &elbow);
        painter.setPen(cosmetic(colour, width));
        painter.drawLine(pivot, toScreen(elbow));
        painter.drawLine(toScreen(elbow), toScreen(tip));
        painter.setBrush(colour);
        painter.drawEllipse(toScreen(elbow), width * 0.6, width * 0.6);
        painter.drawEllipse(toScreen(tip), width * 0.5, width * 0.5);
    };
    // The desired tip path, the actual one, the desired pose (ghost) and the arm.
    painter.setBrush(Qt::NoBrush);
    painter.setPen(cosmetic(kDesiredColour, 2));
    painter.drawPolyline(QPolygonF([&] {
        QPolygonF p;
        for (const QPointF& q : desired_)
            p << toScreen(q);
        return p;
    }()));
    painter.setPen(cosmetic(kActualColour, 1.2));
    painter.drawPolyline(QPolygonF([&] {
        QPolygonF p;
        for (const QPointF& q : trail_)
            p << toScreen(q);
        return p;
    }()));
    if (demonstration_ && referenceIndex_ >= 0 && referenceIndex_ < demonstration_->length()) {
        const Eigen::VectorXd ref = demonstration_->states.row(referenceIndex_);
        drawArm(ref[0], ref[1], QColor(0x2c, 0xa0, 0x2c, 110), 10);
    }
    if (state_.size() >= 2) {
        drawArm(state_[0], state_[1], QColor(0x33, 0x33, 0x33), 8);
    }
    painter.setPen(cosmetic(QColor(0x20, 0x20, 0x20), 1));
    painter.setBrush(QColor(0x90, 0x90, 0x90));
    painter.drawEllipse(pivot, 7, 7);
    // The ground line below the pivot.
    painter.setPen(cosmetic(QColor(0x80, 0x80, 0x80), 2));
    painter.drawLine(toScreen({-2.2, -2.15}), toScreen({2.2, -2.15}));
}

void ArenaView::drawWind(QPainter& painter) const {
    // A compass-style arrow: where the air is going, and how fast.
    const QPointF centre(60.0, 110.0);  // under the legend, clear of the grid labels
    const double speed = wind_->norm();
    painter.setPen(cosmetic(QColor(0x90, 0x90, 0x90), 1));
    painter.setBrush(QColor(255, 255, 255, 200));
    painter.drawEllipse(centre, 40, 40);
    if (speed > 1e-3) {
        // Screen y points down: flip the world's y.
        const QPointF direction(wind_->x() / speed, -wind_->y() / speed);
        const QPointF tip = centre + 30.0 * direction;
        const QPointF tail = centre - 30.0 * direction;
        const QPointF normal(-direction.y(), direction.x());
        painter.setPen(cosmetic(QColor(0x1f, 0x77, 0xb4), 3));
        painter.drawLine(tail, tip);
        painter.setBrush(QColor(0x1f, 0x77, 0xb4));
        painter.drawPolygon(QPolygonF{tip, tip - 10.0 * direction + 6.0 * normal,
                                      tip - 10.0 * direction - 6.0 * normal});
    }
    painter.setPen(palette().color(QPalette::Text));
    painter.drawText(QRectF(centre.x() - 60, centre.y() + 42, 120, 18), Qt::AlignCenter,
                     tr("wind %1 m/s").arg(speed, 0, 'f', 1));
}

void ArenaView::wheelEvent(QWheelEvent* event) {
    const QPointF anchor = toWorld(event->position());
    const double factor = std::pow(1.0015, event->angleDelta().y());
    scale_ = std::clamp(scale_ * factor, 0.05, 20000.0);
    // Keep the world point under the cursor where it was.
    const QPointF after = toWorld(event->position());
    centre_ += anchor - after;
    userMoved_ = true;
    update();
    event->accept();
}

void ArenaView::mousePressEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton) {
        dragging_ = true;
        dragStart_ = event->position();
        dragCentre_ = centre_;
        setCursor(Qt::ClosedHandCursor);
    }
}

void ArenaView::mouseMoveEvent(QMouseEvent* event) {
    if (dragging_) {
        const QPointF delta = event->position() - dragStart_;
        centre_ = dragCentre_ + QPointF(-delta.x() / scale_, delta.y() / scale_);
        userMoved_ = true;
        update();
    }
}

void ArenaView::mouseReleaseEvent(QMouseEvent*) {
    dragging_ = false;
    unsetCursor();
}

void ArenaView::mouseDoubleClickEvent(QMouseEvent*) {
    userMoved_ = false;
    fitScene();
}

void ArenaView::keyPressEvent(QKeyEvent* event) {
    switch (event->key()) {
        case Qt::Key_Home:
            userMoved_ = false;
            fitScene();
            return;
        case Qt::Key_Plus:
        case Qt::Key_Equal:
            scale_ *= 1.25;
            userMoved_ = true;
            update();
            return;
        case Qt::Key_Minus:
            scale_ /= 1.25;
            userMoved_ = true;
            update();
            return;
        default:
            QWidget::keyPressEvent(event);
    }
}

void ArenaView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    if (!userMoved_) {
        fitScene();
    }
}

}  // namespace prisca::app
