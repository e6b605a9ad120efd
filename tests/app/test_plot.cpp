// The plot library: where data lands in pixels, equal aspect, log axes, clipping, NaN breaks,
// bands, heatmaps, legend placement, nice ticks, and PNG/SVG files (rendered offscreen with a
// QGuiApplication for the fonts).
#include "app/plot/Figure.h"

#include <QDir>
#include <QFile>
#include <QGuiApplication>
#include <QPainter>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <limits>

using namespace prisca::app::plot;

namespace {

bool isRedish(QRgb c) {
    return qRed(c) > 180 && qGreen(c) < 120 && qBlue(c) < 120;
}

bool isBluish(QRgb c) {
    return qBlue(c) > 180 && qRed(c) < 120 && qGreen(c) < 120;
}

// A figure with one panel over [0, 1] x [0, 1] (or the given range).
Figure onePanel(const Axes& axes, QSize size = QSize(1200, 800)) {
    Figure figure;
    figure.size = size;
    figure.panels.push_back(axes);
    return figure;
}

Line horizontalLine(double y, double x0, double x1, QColor color = Qt::red) {
    Line line;
    line.color = color;
    line.width = 3.0;
    line.points = {{x0, y}, {x1, y}};
    return line;
}

// The mean row of the reddish pixels in one column, or -1 if there are none.
double redRow(const QImage& image, int column) {
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < image.height(); ++y) {
        if (isRedish(image.pixel(column, y))) {
            sum += y;
            ++count;
        }
    }
    return count > 0 ? sum / count : -1.0;
}

// Bounding box of the pixels matching a predicate.
template <typename Predicate>
QRect boundingBox(const QImage& image, Predicate matches) {
    QRect box;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            if (matches(image.pixel(x, y))) {
                box |= QRect(x, y, 1, 1);
            }
        }
    }
    return box;
}

}  // namespace

class TestPlot : public QObject {
    Q_OBJECT
  private slots:
    void line_landsOnTheMappedPixels() {
        Figure figure;
        Axes axes;
        axes.range = QRectF(0.0, 0.0, 1.0, 1.0);
        Line line;
        line.color = Qt::red;
        line.width = 3.0;
        line.points = {{0.0, 0.5}, {1.0, 0.5}};
        axes.lines.push_back(line);
        figure.panels.push_back(axes);
        const QImage image = renderFigure(figure);
        QCOMPARE(image.size(), QSize(1200, 800));
        const PanelGeometry panel = layoutFigure(figure).at(0);
        const QPointF middle = toPixel(panel, {0.5, 0.5});
        QVERIFY(isRedish(image.pixel(int(middle.x()), int(std::round(middle.y())))));
        // Far above and below the line: not red.
        QVERIFY(!isRedish(image.pixel(int(middle.x()), int(toPixel(panel, {0.5, 0.8}).y()))));
        QVERIFY(!isRedish(image.pixel(int(middle.x()), int(toPixel(panel, {0.5, 0.2}).y()))));
    }

    void nan_breaksALine() {
        Figure figure;
        Axes axes;
        axes.range = QRectF(0.0, 0.0, 3.0, 1.0);
        Line line;
        line.color = Qt::red;
        line.width = 3.0;
        line.points = {{0.0, 0.5}, {1.0, 0.5}, {std::nan(""), 0.5}, {2.0, 0.5}, {3.0, 0.5}};
        axes.lines.push_back(line);
        figure.panels.push_back(axes);
        const QImage image = renderFigure(figure);
        const PanelGeometry panel = layoutFigure(figure).at(0);
        const QPointF drawn = toPixel(panel, {0.5, 0.5});
        const QPointF gap = toPixel(panel, {1.5, 0.5});
        QVERIFY(isRedish(image.pixel(int(drawn.x()), int(std::round(drawn.y())))));
        QVERIFY(!isRedish(image.pixel(int(gap.x()), int(std::round(gap.y())))));
    }

    void equalAspect_givesTheSamePixelScaleOnBothAxes() {
        Figure figure;
        Axes axes;
        axes.equalAspect = true;
        axes.range = QRectF(0.0, 0.0, 10.0, 1.0);
        figure.panels.push_back(axes);
        const PanelGeometry panel = layoutFigure(figure).at(0);
        const double xScale = panel.area.width() / (panel.xMax - panel.xMin);
        const double yScale = panel.area.height() / (panel.yMax - panel.yMin);
        QVERIFY2(std::abs(xScale - yScale) < 1e-6 * xScale,
                 qPrintable(QString("%1 vs %2").arg(xScale).arg(yScale)));
        QVERIFY(panel.xMin <= 0.0 && panel.xMax >= 10.0);  // widened, never cut
    }

    void band_fillsBetweenItsBounds() {
        Figure figure;
        Axes axes;
        axes.range = QRectF(0.0, 0.0, 1.0, 1.0);
        Band band;
        band.color = QColor(0, 0, 255, 200);
        band.x = {0.0, 1.0};
        band.lower = {0.4, 0.4};
        band.upper = {0.6, 0.6};
        axes.bands.push_back(band);
        figure.panels.push_back(axes);
        const QImage image = renderFigure(figure);
        const PanelGeometry panel = layoutFigure(figure).at(0);
        const QPointF inside = toPixel(panel, {0.5, 0.5});
        const QPointF outside = toPixel(panel, {0.5, 0.8});
        const QRgb in = image.pixel(int(inside.x()), int(inside.y()));
        const QRgb out = image.pixel(int(outside.x()), int(outside.y()));
        QVERIFY(qBlue(in) > qRed(in) + 60);
        QVERIFY(std::abs(qBlue(out) - qRed(out)) < 30);
    }

    void heatmapThreshold_colorsCellsBelowItWithTheHighColour() {
        Figure figure;
        Axes axes;
        Heatmap map;
        map.columns = 2;
        map.rows = 1;
        map.extent = QRectF(0.0, 0.0, 2.0, 1.0);
        map.values = {0.5, 2.0};
        map.low = Qt::white;
        map.high = QColor(100, 100, 100);
        map.threshold = 1.0;
        axes.heatmap = map;
        figure.panels.push_back(axes);
        const QImage image = renderFigure(figure);
        const PanelGeometry panel = layoutFigure(figure).at(0);
        const QPointF below = toPixel(panel, {0.5, 0.5});
        const QPointF above = toPixel(panel, {1.5, 0.5});
        QVERIFY(qGray(image.pixel(int(below.x()), int(below.y()))) < 130);
        QVERIFY(qGray(image.pixel(int(above.x()), int(above.y()))) > 230);
    }

    void niceTicks_areOneTwoFiveMultiples() {
        const std::vector<double> ticks = niceTicks(0.0, 0.93, 5);
        QVERIFY(ticks.size() >= 4 && ticks.size() <= 8);
        for (size_t i = 1; i < ticks.size(); ++i) {
            const double step = ticks[i] - ticks[i - 1];
            const double mantissa = step / std::pow(10.0, std::floor(std::log10(step)));
            QVERIFY2(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
                         std::abs(mantissa - 5) < 1e-9,
                     qPrintable(QString::number(step)));
        }
        QVERIFY(niceTicks(std::numeric_limits<double>::quiet_NaN(), 1.0, 5).empty());
        const std::vector<double> decades = logTicks(1e-4, 1e-1, 6);
        QCOMPARE(decades.front(), 1e-4);
        QCOMPARE(decades.back(), 1e-1);
    }

    void save_writesPngAndSvgAndRefusesBadPaths() {
        QTemporaryDir dir;
        Figure figure;
        figure.size = QSize(400, 300);
        Axes axes;
        Line line;
        line.points = {{0, 0}, {1, 1}};
        axes.lines.push_back(line);
        figure.panels.push_back(axes);
        QString error;
        QVERIFY2(saveFigure(figure, dir.filePath("a.png"), &error), qPrintable(error));
        QCOMPARE(QImage(dir.filePath("a.png")).size(), QSize(400, 300));
        QVERIFY2(saveFigure(figure, dir.filePath("a.svg"), &error), qPrintable(error));
        QFile svg(dir.filePath("a.svg"));
        QVERIFY(svg.open(QIODevice::ReadOnly));
        const QByteArray text = svg.readAll();
        QVERIFY(text.contains("<svg"));
        QVERIFY(!saveFigure(figure, dir.filePath("a.bmp"), &error));
        QVERIFY(error.contains("a.bmp"));
        QVERIFY(!saveFigure(figure, dir.filePath("no/such/dir/a.png"), &error));
        QVERIFY(error.contains("no/such/dir"));
    }

    void application_isAGuiApplicationWithoutWidgets() {
        // QTEST_MAIN makes a QGuiApplication only because prisca_plot brings QtGui and nothing
        // brings QtWidgets: fonts need the former, the command line must not need the latter.
        QVERIFY(qobject_cast<QGuiApplication*>(QCoreApplication::instance()) != nullptr);
        QVERIFY(!QCoreApplication::instance()->inherits("QApplication"));
    }

    void line_landsOnTheRowHalfwayUpThePlotArea() {
        Axes axes;
        axes.range = QRectF(0.0, 0.0, 1.0, 1.0);
        axes.lines.push_back(horizontalLine(0.5, 0.0, 1.0));
        const Figure figure = onePanel(axes);
        const QImage image = renderFigure(figure);
        const QRectF area = layoutFigure(figure).at(0).area;
        // Measured against the plot area alone, not through the library's own mapping.
        const double row = redRow(image, qRound(area.center().x()));
        QVERIFY2(std::abs(row - area.center().y()) <= 1.5,
                 qPrintable(QStringLiteral("row %1, expected %2").arg(row).arg(area.center().y())));
    }

    void logY_putsTenHalfwayBetweenOneAndOneHundred() {
        Axes axes;
        axes.logY = true;
        axes.range = QRectF(0.0, 1.0, 1.0, 99.0);  // y from 1 to 100
        axes.lines.push_back(horizontalLine(10.0, 0.0, 1.0));
        const Figure figure = onePanel(axes);
        const QImage image = renderFigure(figure);
        const PanelGeometry panel = layoutFigure(figure).at(0);
        QVERIFY(panel.logY);
        const double row = redRow(image, qRound(panel.area.center().x()));
        QVERIFY2(std::abs(row - panel.area.center().y()) <= 1.5,
                 qPrintable(
                     QStringLiteral("row %1, expected %2").arg(row).arg(panel.area.center().y())));
        QVERIFY(std::isnan(toPixel(panel, {0.5, 0.0}).y()));  // y <= 0 has no place
    }

    void logY_breaksALineAtNonPositiveValues() {
        Axes axes;
        axes.logY = true;
        axes.range = QRectF(0.0, 1.0, 3.0, 99.0);
        Line line = horizontalLine(10.0, 0.0, 3.0);
        line.points = {{0.0, 10.0}, {1.0, 10.0}, {1.5, 0.0}, {2.0, 10.0}, {3.0, 10.0}};
        axes.lines.push_back(line);
        const Figure figure = onePanel(axes);
        const QImage image = renderFigure(figure);
        const PanelGeometry panel = layoutFigure(figure).at(0);
        QVERIFY(redRow(image, qRound(toPixel(panel, {0.5, 10.0}).x())) > 0);
        QCOMPARE(redRow(image, qRound(toPixel(panel, {1.5, 10.0}).x())), -1.0);
    }

    void translucentLine_hasAnEvenColourAcrossItsVertices() {
        Axes axes;
        axes.range = QRectF(0.0, 0.0, 1.0, 1.0);
        Line line;
        line.color = QColor(255, 0, 0, 128);
        line.width = 6.0;
        for (int i = 0; i <= 40; ++i) {
            line.points.emplace_back(i / 40.0, 0.53);  // off the grid lines
        }
        axes.lines.push_back(line);
        const Figure figure = onePanel(axes);
        const QImage image = renderFigure(figure);
        const PanelGeometry panel = layoutFigure(figure).at(0);
        Axes bare = axes;
        bare.lines.clear();
        const QImage background = renderFigure(onePanel(bare));
        const int row = qRound(toPixel(panel, {0.5, 0.53}).y());
        int lightest = 255;
        int darkest = 0;
        for (int x = qRound(toPixel(panel, {0.1, 0.0}).x()); x < toPixel(panel, {0.9, 0.0}).x();
             ++x) {
            if (background.pixel(x, row) != qRgb(255, 255, 255)) {
                continue;  // a grid line shows through
            }
            const int green = qGreen(image.pixel(x, row));  // 255 on white, less where redder
            lightest = std::min(lightest, green);
            darkest = std::max(darkest, green);
        }
        QVERIFY2(darkest - lightest <= 3 && std::abs(lightest - 127) <= 8,
                 qPrintable(QStringLiteral("green from %1 to %2").arg(lightest).arg(darkest)));
    }

    void data_isClippedToThePlotArea() {
        Axes axes;
        axes.range = QRectF(0.0, 0.0, 1.0, 1.0);
        axes.lines.push_back(horizontalLine(0.5, -5.0, 5.0));
        const Figure figure = onePanel(axes);
        const QImage image = renderFigure(figure);
        const QRectF area = layoutFigure(figure).at(0).area;
        const QRect red = boundingBox(image, isRedish);
        QVERIFY(!red.isEmpty());
        QVERIFY2(red.left() >= area.left() - 1 && red.right() <= area.right() + 1,
                 qPrintable(QStringLiteral("red from %1 to %2, area from %3 to %4")
                                .arg(red.left())
                                .arg(red.right())
                                .arg(area.left())
                                .arg(area.right())));
        QVERIFY(red.right() >= area.right() - 2);  // but drawn right up to the edge
    }

    void svg_isClippedToThePlotAreaToo() {
        // QSvgGenerator ignores the painter's clip, so the geometry itself must stop at the edge.
        QTemporaryDir dir;
        Axes axes;
        axes.range = QRectF(0.0, 0.0, 1.0, 1.0);
        axes.lines.push_back(horizontalLine(0.5, -5.0, 5.0));
        Band band;
        band.color = QColor(255, 0, 0, 255);
        band.x = {-5.0, 5.0};
        band.lower = {0.1, 0.1};
        band.upper = {0.2, 0.2};
        axes.bands.push_back(band);
        const Figure figure = onePanel(axes, QSize(600, 400));
        const QString path = dir.filePath(QStringLiteral("clipped.svg"));
        QString error;
        QVERIFY2(saveFigure(figure, path, &error), qPrintable(error));
        QSvgRenderer renderer(path);
        QVERIFY(renderer.isValid());
        QImage image(figure.size, QImage::Format_ARGB32);
        image.fill(Qt::white);
        {
            QPainter painter(&image);
            renderer.render(&painter, QRectF(QPointF(0, 0), QSizeF(figure.size)));
        }
        const QRectF area = layoutFigure(figure).at(0).area;
        const auto reddish = [](QRgb c) {  // the line or the band tint, not grey text
            return qRed(c) - qGreen(c) > 40 && qRed(c) - qBlue(c) > 40;
        };
        const QRect red = boundingBox(image, reddish);
        QVERIFY(!red.isEmpty());
        QVERIFY2(red.left() >= area.left() - 1 && red.right() <= area.right() + 1,
                 qPrintable(QStringLiteral("red from %1 to %2, area from %3 to %4")
                                .arg(red.left())
                                .arg(red.right())
                                .arg(area.left())
                                .arg(area.right())));
    }

    void equalAspect_drawsASquareAsASquare() {
        Axes axes;
        axes.equalAspect = true;
        Shape square;
        square.points = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
        square.pen = Qt::blue;
        square.brush = Qt::blue;
        axes.shapes.push_back(square);
        Text far;  // stretches the data range along x only
        far.at = QPointF(4.0, 0.5);
        axes.texts.push_back(far);
        for (const QSize size : {QSize(1200, 500), QSize(500, 1200)}) {
            const QImage image = renderFigure(onePanel(axes, size));
            const QRect blue = boundingBox(image, isBluish);
            QVERIFY(blue.width() > 20);
            QVERIFY2(std::abs(blue.width() - blue.height()) <= 2,
                     qPrintable(QStringLiteral("%1 x %2 px in a %3 x %4 figure")
                                    .arg(blue.width())
                                    .arg(blue.height())
                                    .arg(size.width())
                                    .arg(size.height())));
        }
    }

    void band_isTranslucentAndBreaksAtNaN() {
        Axes axes;
        axes.range = QRectF(0.0, 0.0, 3.0, 1.0);
        Band band;
        band.color = Qt::blue;  // opaque: drawn at a quarter opacity
        band.x = {0.0, 1.0, 1.5, 2.0, 3.0};
        band.lower = {0.4, 0.4, std::nan(""), 0.4, 0.4};
        band.upper = {0.6, 0.6, 0.6, 0.6, 0.6};
        axes.bands.push_back(band);
        const Figure figure = onePanel(axes);
        const QImage image = renderFigure(figure);
        const PanelGeometry panel = layoutFigure(figure).at(0);
        const auto at = [&](double x, double y) {
            const QPointF p = toPixel(panel, {x, y});
            return image.pixel(qRound(p.x()), qRound(p.y()));
        };
        const QRgb inside = at(0.7, 0.45);  // off the grid lines
        QVERIFY2(qBlue(inside) > 240 && qRed(inside) > 150 && qRed(inside) < 230,
                 qPrintable(QColor(inside).name()));         // blue over white at about 25 %
        QCOMPARE(QColor(at(1.3, 0.45)), QColor(Qt::white));  // the NaN sample's gap
        QCOMPARE(QColor(at(2.7, 0.45)), QColor(inside));
        QCOMPARE(QColor(at(2.7, 0.85)), QColor(Qt::white));
    }

    void heatmap_scalesFromLowToHighColour() {
        Axes axes;
        Heatmap map;
        map.columns = 3;
        map.rows = 2;
        map.extent = QRectF(0.0, 0.0, 3.0, 2.0);
        map.values = {0.0,  5.0,  10.0,  // row 0, at the bottom
                      10.0, 10.0, std::nan("")};
        map.low = Qt::blue;
        map.high = Qt::red;
        axes.heatmap = map;
        const Figure figure = onePanel(axes);
        const QImage image = renderFigure(figure);
        const PanelGeometry panel = layoutFigure(figure).at(0);
        QCOMPARE(panel.xMin, 0.0);  // a heatmap alone fills the panel
        QCOMPARE(panel.yMax, 2.0);
        const auto at = [&](double x, double y) {
            const QPointF p = toPixel(panel, {x, y});
            return QColor(image.pixel(qRound(p.x()), qRound(p.y())));
        };
        QCOMPARE(at(0.5, 0.5), QColor(Qt::blue));
        QCOMPARE(at(2.5, 0.5), QColor(Qt::red));
        QCOMPARE(at(0.5, 1.5), QColor(Qt::red));
        const QColor middle = at(1.5, 0.5);
        QVERIFY2(std::abs(middle.red() - 128) <= 2 && std::abs(middle.blue() - 128) <= 2,
                 qPrintable(middle.name()));
        QCOMPARE(at(2.5, 1.5), QColor(Qt::white));  // NaN: blank
    }

    void heatmapThreshold_usesBothColoursOnAGrid() {
        Axes axes;
        Heatmap map;
        map.columns = 2;
        map.rows = 2;
        map.extent = QRectF(10.0, 100.0, 2.0, 20.0);
        map.values = {0.5, 3.0,   // bottom row
                      2.0, 0.1};  // top row
        map.low = QColor(250, 250, 250);
        map.high = QColor(150, 150, 150);
        map.threshold = 1.0;
        axes.heatmap = map;
        const Figure figure = onePanel(axes);
        const QImage image = renderFigure(figure);
        const PanelGeometry panel = layoutFigure(figure).at(0);
        const auto at = [&](double x, double y) {
            const QPointF p = toPixel(panel, {x, y});
            return QColor(image.pixel(qRound(p.x()), qRound(p.y())));
        };
        QCOMPARE(at(10.5, 105.0), map.high);  // 0.5 < 1: "satisfied"
        QCOMPARE(at(11.5, 105.0), map.low);
        QCOMPARE(at(10.5, 115.0), map.low);
        QCOMPARE(at(11.5, 115.0), map.high);
    }

    void legend_avoidsTheCornerTheDataFill() {
        Axes axes;
        axes.range = QRectF(0.0, 0.0, 1.0, 1.0);
        Band band;  // fills the upper right quadrant, where a legend goes by default
        band.label = QStringLiteral("upper right");
        band.color = QColor(0, 0, 255, 120);
        band.x = {0.5, 1.0};
        band.lower = {0.5, 0.5};
        band.upper = {1.0, 1.0};
        axes.bands.push_back(band);
        Axes without = axes;
        without.legend = false;
        const QImage with = renderFigure(onePanel(axes));
        const QImage plain = renderFigure(onePanel(without));
        const PanelGeometry panel = layoutFigure(onePanel(axes)).at(0);
        const QPointF centre = toPixel(panel, {0.5, 0.5});
        QRect changed;
        for (int y = 0; y < with.height(); ++y) {
            for (int x = 0; x < with.width(); ++x) {
                if (with.pixel(x, y) != plain.pixel(x, y)) {
                    changed |= QRect(x, y, 1, 1);
                }
            }
        }
        QVERIFY(!changed.isEmpty());  // a legend was drawn
        QVERIFY2(changed.right() < centre.x() || changed.top() > centre.y(),
                 qPrintable(QStringLiteral("legend at %1,%2 %3x%4")
                                .arg(changed.x())
                                .arg(changed.y())
                                .arg(changed.width())
                                .arg(changed.height())));
    }

    void emptyPanel_drawsAxesAndItsNote() {
        Axes axes;
        axes.xLabel = QStringLiteral("x [m]");
        Axes silent = axes;
        silent.emptyNote.clear();
        const PanelGeometry panel = layoutFigure(onePanel(axes)).at(0);
        QCOMPARE(panel.xMin, 0.0);
        QCOMPARE(panel.xMax, 1.0);
        const QImage noted = renderFigure(onePanel(axes));
        const QImage blank = renderFigure(onePanel(silent));
        const QRect middle =
            QRectF(panel.area.center() - QPointF(60, 15), QSizeF(120, 30)).toRect();
        QVERIFY(noted.copy(middle) != blank.copy(middle));
        QVERIFY(noted.pixel(qRound(panel.area.left()) - 1, qRound(panel.area.center().y())) !=
                qRgb(255, 255, 255));  // the frame
    }

    void niceTicks_areExactDecimals() {
        QCOMPARE(niceTicks(0.0, 1.0, 5), (std::vector<double>{0.0, 0.2, 0.4, 0.6, 0.8, 1.0}));
        QCOMPARE(niceTicks(1.0, 0.0, 5), niceTicks(0.0, 1.0, 5));
        QCOMPARE(niceTicks(0.1, 0.3, 5), (std::vector<double>{0.1, 0.15, 0.2, 0.25, 0.3}));
        QCOMPARE(niceTicks(0.0, 1000.0, 4),
                 (std::vector<double>{0.0, 200.0, 400.0, 600.0, 800.0, 1000.0}));
        const std::vector<double> across = niceTicks(-3.7, 12.2, 6);
        QVERIFY(std::find(across.begin(), across.end(), 0.0) != across.end());
        QVERIFY(across.front() >= -3.7 && across.back() <= 12.2);
        QCOMPARE(niceTicks(2.5, 2.5, 5), std::vector<double>{2.5});
        QVERIFY(niceTicks(0.0, std::numeric_limits<double>::infinity(), 5).empty());
        QVERIFY(niceTicks(1.0, 1.0 + 1e-12, 5).size() >= 2);  // tiny spans still get two
    }

    void logTicks_arePowersOfTenOrOneTwoFive() {
        QCOMPARE(logTicks(1.0, 1000.0, 6), (std::vector<double>{1.0, 10.0, 100.0, 1000.0}));
        // Thirteen decades, about five ticks: every third power, on multiples of three.
        QCOMPARE(logTicks(1e-6, 1e6, 5), (std::vector<double>{1e-6, 1e-3, 1.0, 1e3, 1e6}));
        // Little more than two decades: 1, 2 and 5 times powers of ten.
        QCOMPARE(logTicks(0.015, 3.0, 10),
                 (std::vector<double>{0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0}));
        QVERIFY(logTicks(0.0, 10.0, 5).empty());
        QVERIFY(logTicks(-1.0, 10.0, 5).empty());
    }

    void save_writesAWellFormedSvg() {
        QTemporaryDir dir;
        Axes axes;
        axes.lines.push_back(horizontalLine(0.5, 0.0, 1.0));
        Figure figure = onePanel(axes, QSize(400, 300));
        figure.title = QStringLiteral("A figure");
        QString error;
        const QString path = dir.filePath(QStringLiteral("figure.SVG"));  // extension in any case
        QVERIFY2(saveFigure(figure, path, &error), qPrintable(error));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        QVERIFY(text.startsWith("<?xml"));
        QVERIFY(text.contains("<svg"));
        QVERIFY(text.contains("viewBox=\"0 0 400 300\""));
        QVERIFY(text.contains("A figure"));
        QSvgRenderer renderer(path);
        QVERIFY(renderer.isValid());
        // Only the file itself: the atomic write leaves no temporary behind.
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{"figure.SVG"});
    }

    void save_replacesAnExistingPngAndRefusesABadSize() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("a.png"));
        QFile old(path);
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("not a png");
        old.close();
        Figure figure = onePanel(Axes{}, QSize(320, 240));
        QString error;
        QVERIFY2(saveFigure(figure, path, &error), qPrintable(error));
        QCOMPARE(QImage(path).size(), QSize(320, 240));
        figure.size = QSize(0, 240);
        QVERIFY(renderFigure(figure).isNull());
        QVERIFY(!saveFigure(figure, path, &error));
        QVERIFY(error.contains(path));
        QCOMPARE(QImage(path).size(), QSize(320, 240));  // the old file is untouched
    }

    void render_handlesAHundredThousandPointsQuickly() {
        Axes axes;
        Line walk;
        walk.points.reserve(100000);
        double y = 0.0;
        for (int i = 0; i < 100000; ++i) {
            y += std::sin(i * 0.37) * 0.5;  // deterministic wiggle
            walk.points.emplace_back(i, y);
        }
        axes.lines.push_back(walk);
        // Speed belongs in benchmarks; here only that a dense line renders at all.
        const QImage image = renderFigure(onePanel(axes));
        QVERIFY(!image.isNull());
    }
};

QTEST_MAIN(TestPlot)
#include "test_plot.moc"
