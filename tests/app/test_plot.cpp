// The plot library: where data lands in pixels, equal aspect, NaN breaks, heatmap thresholds,
// nice ticks, and PNG/SVG files (rendered offscreen with a QGuiApplication for the fonts).
#include "app/plot/Figure.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <limits>

using namespace prisca::app::plot;

namespace {

bool isRedish(QRgb c) {
    return qRed(c) > 180 && qGreen(c) < 120 && qBlue(c) < 120;
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
};

QTEST_MAIN(TestPlot)
#include "test_plot.moc"
