// The plot library as drawn by QtCharts: where data lands in pixels (against the chart's own
// plot area and mapping), log axes, equal aspect, NaN breaks, bands, heatmaps, the legend, the
// cut to the visible range (PNG and SVG) and decimation (the files: test_plot_files).

#include "PlotTestSupport.h"

class TestPlot : public QObject {
    Q_OBJECT
  private slots:
    void line_landsWhereTheChartMapsIt() {
        Axes axes;
        axes.range = QRectF(0.0, 0.0, 1.0, 1.0);
        axes.lines.push_back(horizontalLine(0.5, 0.0, 1.0));
        const Figure figure = onePanel(axes);
        const FigureScene scene(figure);
        const QImage image = renderFigure(figure);
        QCOMPARE(image.size(), QSize(1200, 800));
        QCOMPARE(render(scene, figure.size), image);  // the same drawing either way
        const QRectF area = scene.plotArea(0);
        QVERIFY(area.width() > 800 && area.height() > 500);  // most of the figure
        // Where the chart maps the middle, and independently: halfway up the plot area.
        const QPointF middle = scene.toPixel(0, {0.5, 0.5});
        QVERIFY(std::abs(middle.x() - area.center().x()) < 0.5);
        QVERIFY(std::abs(middle.y() - area.center().y()) < 0.5);
        const double row = redRow(image, qRound(middle.x()));
        QVERIFY2(std::abs(row - area.center().y()) <= 1.5,
                 qPrintable(QStringLiteral("row %1, expected %2").arg(row).arg(area.center().y())));
        QVERIFY(
            !isRedish(image.pixel(qRound(middle.x()), qRound(scene.toPixel(0, {0.5, 0.8}).y()))));
    }

    void nonFinitePoints_breakALineAndKeepOneLegendEntry() {
        Axes axes;
        axes.range = QRectF(0.0, 0.0, 4.0, 1.0);
        Line line = horizontalLine(0.5, 0.0, 4.0);
        line.label = QStringLiteral("broken");
        const double inf = std::numeric_limits<double>::infinity();
        line.points = {{0.0, 0.5}, {1.0, 0.5}, {kNaN, 0.5}, {2.0, 0.5},
                       {2.5, 0.5}, {3.0, inf}, {3.5, 0.5},  {4.0, 0.5}};
        axes.lines.push_back(line);
        const Figure figure = onePanel(axes);
        const FigureScene scene(figure);
        const QImage image = render(scene, figure.size);
        const auto redAt = [&](double x) {
            return redRow(image, qRound(scene.toPixel(0, {x, 0.5}).x())) > 0;
        };
        QVERIFY(redAt(0.5));
        QVERIFY(!redAt(1.5));  // across the NaN
        QVERIFY(redAt(2.25));
        QVERIFY(!redAt(3.0));  // around the infinity
        QVERIFY(redAt(3.75));
        QCOMPARE(legendNames(scene, 0), QStringList{QStringLiteral("broken")});
        QVERIFY(scene.chart(0)->series().size() >= 3);  // pieces
    }

    void logY_putsTenHalfwayBetweenOneAndOneHundred() {
        Axes axes;
        axes.logY = true;
        axes.range = QRectF(0.0, 1.0, 3.0, 99.0);  // y from 1 to 100
        Line line = horizontalLine(10.0, 0.0, 3.0);
        line.points = {{0.0, 10.0}, {1.0, 10.0}, {1.5, 0.0}, {2.0, 10.0}, {3.0, 10.0}};
        axes.lines.push_back(line);
        const Figure figure = onePanel(axes);
        const FigureScene scene(figure);
        QVERIFY(qobject_cast<QLogValueAxis*>(scene.chart(0)->axes(Qt::Vertical).at(0)));
        const QImage image = render(scene, figure.size);
        const QRectF area = scene.plotArea(0);
        const double row = redRow(image, qRound(scene.toPixel(0, {0.5, 10.0}).x()));
        QVERIFY2(std::abs(row - area.center().y()) <= 1.5,
                 qPrintable(QStringLiteral("row %1, expected %2").arg(row).arg(area.center().y())));
        // y = 0 has no place on a log axis: the line breaks there.
        QCOMPARE(redRow(image, qRound(scene.toPixel(0, {1.5, 10.0}).x())), -1.0);
    }

    void logY_widensToWholeDecades() {
        Axes axes;
        axes.logY = true;
        Line line;
        line.points = {{0.0, 0.02}, {1.0, 0.3}};
        axes.lines.push_back(line);
        const FigureScene scene(onePanel(axes));
        const QRectF range = shownRange(scene, 0);
        QCOMPARE(range.top(), 0.01);
        QCOMPARE(range.bottom(), 1.0);
    }

    void equalAspect_givesEqualPixelsPerUnitOnBothAxes() {
        for (const QSize size : {QSize(1200, 500), QSize(500, 1200)}) {
            Axes axes;
            axes.equalAspect = true;
            axes.range = QRectF(0.0, 0.0, 10.0, 1.0);
            Shape square;
            square.points = {{4.0, 0.0}, {5.0, 0.0}, {5.0, 1.0}, {4.0, 1.0}};
            square.pen = Qt::blue;
            square.brush = Qt::blue;
            axes.shapes.push_back(square);
            const Figure figure = onePanel(axes, size);
            const FigureScene scene(figure);
            const QRectF area = scene.plotArea(0);
            const QRectF range = shownRange(scene, 0);
            const double xScale = area.width() / range.width();
            const double yScale = area.height() / range.height();
            QVERIFY2(std::abs(xScale - yScale) < 1e-6 * xScale,
                     qPrintable(QStringLiteral("%1 vs %2 px per unit").arg(xScale).arg(yScale)));
            QVERIFY(range.left() <= 0.0 && range.right() >= 10.0);  // widened, never cut
            QVERIFY(range.top() <= 0.0 && range.bottom() >= 1.0);
            // And on the pixels: the unit square is drawn square.
            const QRect blue = boundingBox(render(scene, size), isBluish);
            QVERIFY(blue.width() > 20);
            QVERIFY2(std::abs(blue.width() - blue.height()) <= 2,
                     qPrintable(QStringLiteral("%1 x %2 px").arg(blue.width()).arg(blue.height())));
        }
    }

    void band_isTranslucentAndBreaksAtNaN() {
        Axes axes;
        axes.range = QRectF(0.0, 0.0, 3.0, 1.0);
        Band band;
        band.color = Qt::blue;  // opaque: drawn at a quarter opacity
        band.x = {0.0, 1.0, 1.5, 2.0, 3.0};
        band.lower = {0.4, 0.4, kNaN, 0.4, 0.4};
        band.upper = {0.6, 0.6, 0.6, 0.6, 0.6};
        axes.bands.push_back(band);
        const Figure figure = onePanel(axes);
        const FigureScene scene(figure);
        const QImage image = render(scene, figure.size);
        const auto at = [&](double x, double y) {
            const QPointF p = scene.toPixel(0, {x, y});
            return image.pixel(qRound(p.x()), qRound(p.y()));
        };
        const QRgb inside = at(0.7, 0.45);  // off the grid lines
        QVERIFY2(qBlue(inside) > 240 && qRed(inside) > 150 && qRed(inside) < 230,
                 qPrintable(QColor(inside).name()));         // blue over white at about 25 %
        QCOMPARE(QColor(at(1.3, 0.45)), QColor(Qt::white));  // the NaN sample's gap
        QCOMPARE(QColor(at(2.7, 0.45)), QColor(inside));
        QCOMPARE(QColor(at(2.7, 0.85)), QColor(Qt::white));
    }

    void png_isCutAtThePlotArea() {
        Axes axes;
        axes.range = QRectF(0.0, 0.0, 1.0, 1.0);
        axes.lines.push_back(horizontalLine(0.5, -5.0, 5.0));
        const Figure figure = onePanel(axes);
        const FigureScene scene(figure);
        const QRectF area = scene.plotArea(0);
        const QRect red = boundingBox(render(scene, figure.size), isRedish);
        QVERIFY(!red.isEmpty());
        QVERIFY2(red.left() >= area.left() - 1 && red.right() <= area.right() + 1,
                 qPrintable(QStringLiteral("red from %1 to %2, area from %3 to %4")
                                .arg(red.left())
                                .arg(red.right())
                                .arg(area.left())
                                .arg(area.right())));
        QVERIFY(red.left() <= area.left() + 2 && red.right() >= area.right() - 2);  // edge to edge
    }

    void svg_isCutAtThePlotAreaToo() {
        // The SVG writer ignores the painter's clip: the series themselves must stop at the edge.
        QTemporaryDir dir;
        Axes axes;
        axes.range = QRectF(0.0, 0.0, 1.0, 1.0);
        axes.lines.push_back(horizontalLine(0.5, -5.0, 5.0));
        Band band;
        band.color = QColor(255, 0, 0, 255);
        band.x = {-5.0, 5.0};
        band.lower = {0.1, -3.0};
        band.upper = {0.2, 3.0};
        axes.bands.push_back(band);
        Shape lot;
        lot.points = {{0.8, 0.8}, {3.0, 0.8}, {3.0, 3.0}, {0.8, 3.0}};
        lot.pen = Qt::red;
        lot.brush = QColor(255, 0, 0, 100);
        axes.shapes.push_back(lot);
        const Figure figure = onePanel(axes, QSize(600, 400));
        const QString path = dir.filePath(QStringLiteral("clipped.svg"));
        QString error;
        QVERIFY2(saveFigure(figure, path, &error), qPrintable(error));
        const QImage image = renderSvg(path, figure.size);
        const QRectF area = FigureScene(figure).plotArea(0);
        const auto reddish = [](QRgb c) {  // the line, band or lot, not grey text
            return qRed(c) - qGreen(c) > 40 && qRed(c) - qBlue(c) > 40;
        };
        const QRect red = boundingBox(image, reddish);
        QVERIFY(!red.isEmpty());
        QVERIFY2(area.adjusted(-1.5, -1.5, 1.5, 1.5).contains(QRectF(red)),
                 qPrintable(QStringLiteral("red %1,%2 %3x%4, area %5,%6 %7x%8")
                                .arg(red.x())
                                .arg(red.y())
                                .arg(red.width())
                                .arg(red.height())
                                .arg(area.x())
                                .arg(area.y())
                                .arg(area.width())
                                .arg(area.height())));
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
        const FigureScene scene(figure);
        const QImage image = render(scene, figure.size);
        Axes bare = axes;
        bare.lines.clear();
        const QImage background = renderFigure(onePanel(bare));
        const int row = qRound(scene.toPixel(0, {0.5, 0.53}).y());
        int lightest = 255;
        int darkest = 0;
        for (int x = qRound(scene.toPixel(0, {0.1, 0.0}).x()); x < scene.toPixel(0, {0.9, 0.0}).x();
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

    void heatmap_scalesFromLowToHighColourAndFillsThePanel() {
        Axes axes;
        Heatmap map;
        map.columns = 3;
        map.rows = 2;
        map.extent = QRectF(0.0, 0.0, 3.0, 2.0);
        map.values = {0.0,  5.0,  10.0,  // row 0, at the bottom
                      10.0, 10.0, kNaN};
        map.low = Qt::blue;
        map.high = Qt::red;
        axes.heatmap = map;
        const Figure figure = onePanel(axes);
        const FigureScene scene(figure);
        QCOMPARE(shownRange(scene, 0), QRectF(0.0, 0.0, 3.0, 2.0));  // a heatmap alone fills it
        const QImage image = render(scene, figure.size);
        const auto at = [&](double x, double y) {
            const QPointF p = scene.toPixel(0, {x, y});
            return QColor(image.pixel(qRound(p.x()), qRound(p.y())));
        };
        QCOMPARE(at(0.5, 0.5), QColor(Qt::blue));
        QCOMPARE(at(2.5, 0.5), QColor(Qt::red));
        QCOMPARE(at(0.5, 1.5), QColor(Qt::red));
        const QColor middle = at(1.5, 0.5);
        QVERIFY2(std::abs(middle.red() - 128) <= 2 && std::abs(middle.blue() - 128) <= 2,
                 qPrintable(middle.name()));
        QCOMPARE(at(2.3, 1.3), QColor(Qt::white));  // NaN: blank (off the grid lines)
    }

    void heatmapThreshold_usesBothColoursAndNamesThemInTheKey() {
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
        map.valueLabel = QStringLiteral("Var(D)");
        axes.heatmap = map;
        const Figure figure = onePanel(axes);
        const FigureScene scene(figure);
        const QImage image = render(scene, figure.size);
        const auto at = [&](double x, double y) {
            const QPointF p = scene.toPixel(0, {x, y});
            return QColor(image.pixel(qRound(p.x()), qRound(p.y())));
        };
        QCOMPARE(at(10.5, 105.0), map.high);  // 0.5 < 1: "satisfied"
        QCOMPARE(at(11.5, 105.0), map.low);
        QCOMPARE(at(10.5, 115.0), map.low);
        QCOMPARE(at(11.5, 115.0), map.high);
        // Names are rich text in QtCharts: "<" must arrive as a character.
        QCOMPARE(legendNames(scene, 0),
                 (QStringList{QStringLiteral("Var(D) &lt; 1"), QStringLiteral("Var(D) \u2265 1")}));
    }

    void legend_sitsBelowThePlotAreaWithOneEntryPerLabel() {
        Axes axes;
        axes.range = QRectF(0.0, 0.0, 1.0, 1.0);
        Line mean = horizontalLine(0.5, 0.0, 1.0, Qt::blue);
        mean.label = QStringLiteral("mean");
        Band band;
        band.label = mean.label;  // shares the line's entry
        band.x = {0.0, 1.0};
        band.lower = {0.4, 0.4};
        band.upper = {0.9, 0.9};
        Band other = band;
        other.label = QStringLiteral("other");
        Line silent = horizontalLine(0.2, 0.0, 1.0);  // no label: no entry
        axes.lines = {mean, silent};
        axes.bands = {band, other};
        const FigureScene scene(onePanel(axes));
        QCOMPARE(legendNames(scene, 0), (QStringList{"mean", "other"}));
        const QRectF legend = scene.chart(0)->legend()->sceneBoundingRect();
        QVERIFY(legend.top() >= scene.plotArea(0).bottom());  // never over the data

        axes.legend = false;
        QVERIFY(legendNames(FigureScene(onePanel(axes)), 0).isEmpty());
    }

    void panelsInAColumn_shareTheirLeftEdge() {
        Figure figure;
        figure.columns = 1;
        Axes narrow;
        narrow.lines.push_back(horizontalLine(0.5, 0.0, 1.0));
        Axes wide = narrow;
        wide.lines[0].points = {{0.0, -123456.0}, {1.0, 123456.0}};  // long tick labels
        wide.yLabel = QStringLiteral("y [m]");
        figure.panels = {narrow, wide};
        const FigureScene scene(figure);
        QVERIFY2(std::abs(scene.plotArea(0).left() - scene.plotArea(1).left()) <= 1.0,
                 qPrintable(QStringLiteral("%1 vs %2")
                                .arg(scene.plotArea(0).left())
                                .arg(scene.plotArea(1).left())));
        QVERIFY(scene.plotArea(0).bottom() < scene.plotArea(1).top());
    }

    void emptyPanel_showsItsNote() {
        Axes axes;
        axes.xLabel = QStringLiteral("x [m]");
        Axes silent = axes;
        silent.emptyNote.clear();
        const FigureScene scene(onePanel(axes));
        QCOMPARE(shownRange(scene, 0), QRectF(0.0, 0.0, 1.0, 1.0));
        const QImage noted = render(scene, QSize(1200, 800));
        const QImage blank = renderFigure(onePanel(silent));
        const QRect middle =
            QRectF(scene.plotArea(0).center() - QPointF(60, 15), QSizeF(120, 30)).toRect();
        QVERIFY(noted.copy(middle) != blank.copy(middle));
    }

    void text_isPlacedAtItsAnchor() {
        Axes axes;
        axes.range = QRectF(0.0, 0.0, 1.0, 1.0);
        Text note;
        note.at = QPointF(0.25, 0.75);
        note.text = QStringLiteral("MMMM");
        note.color = Qt::red;
        axes.texts.push_back(note);
        Text outside = note;
        outside.at = QPointF(2.0, 0.5);  // cut like the data
        axes.texts.push_back(outside);
        const Figure figure = onePanel(axes);
        const FigureScene scene(figure);
        const QRect red = boundingBox(render(scene, figure.size), isRedish);
        const QPointF anchor = scene.toPixel(0, note.at);
        QVERIFY(!red.isEmpty());
        QVERIFY(red.left() > anchor.x() && red.left() < anchor.x() + 15);  // just right of it
        QVERIFY(red.top() < anchor.y() && red.bottom() > anchor.y());      // centred on it
        QVERIFY(red.right() < scene.plotArea(0).center().x());
    }

    void denseLine_isDecimatedKeepingItsExtremes() {
        Axes axes;
        Line walk;
        walk.points.reserve(100000);
        for (int i = 0; i < 100000; ++i) {
            walk.points.emplace_back(i, std::sin(i * 0.37));
        }
        walk.points[54321].setY(25.0);
        walk.points[77777].setY(-30.0);
        axes.lines.push_back(walk);
        const Figure figure = onePanel(axes);
        const FigureScene scene(figure);
        qsizetype drawn = 0;
        double high = -1e9, low = 1e9;
        for (QAbstractSeries* series : scene.chart(0)->series()) {
            for (const QPointF& p : static_cast<QXYSeries*>(series)->points()) {
                high = std::max(high, p.y());
                low = std::min(low, p.y());
                ++drawn;
            }
        }
        QVERIFY2(drawn <= 4 * qCeil(scene.plotArea(0).width()) + 4,
                 qPrintable(QString::number(drawn)));
        QCOMPARE(high, 25.0);
        QCOMPARE(low, -30.0);
        QVERIFY(!renderFigure(figure).isNull());
    }

    void clipping_cutsSegmentsAtTheEdges() {
        const DataView view{0.0, 1.0, 0.0, 1.0, false};
        const auto pieces = clipPolyline({{-1.0, 0.5}, {0.5, 0.5}, {0.5, 2.0}, {0.8, 0.2}}, view);
        QCOMPARE(pieces.size(), std::size_t(2));
        QCOMPARE(pieces[0], (QList<QPointF>{{0.0, 0.5}, {0.5, 0.5}, {0.5, 1.0}}));
        QCOMPARE(pieces[1].front().y(), 1.0);
        QCOMPARE(pieces[1].back(), QPointF(0.8, 0.2));
        // On a log axis the cut is made where the drawn (straight in log y) segment crosses.
        const DataView log{0.0, 1.0, 1.0, 100.0, true};
        const auto logPiece = clipPolyline({{0.0, 10.0}, {1.0, 10000.0}}, log).at(0);
        QCOMPARE(logPiece.back().x(), 1.0 / 3.0);
        QVERIFY(std::abs(logPiece.back().y() - 100.0) < 1e-9);
        // A band crossing the top edge: clamped there, with a sample where it crosses.
        Band band;
        band.x = {0.0, 1.0};
        band.lower = {0.0, 0.0};
        band.upper = {0.5, 1.5};
        const std::vector<BandPiece> cut = clipBand(band, view);
        QCOMPARE(cut.size(), std::size_t(1));
        QCOMPARE(cut[0].upper, (QList<QPointF>{{0.0, 0.5}, {0.5, 1.0}, {1.0, 1.0}}));
        QVERIFY(clipPolygon({{2.0, 2.0}, {3.0, 2.0}, {3.0, 3.0}}, view).isEmpty());
    }
};

QTEST_MAIN(TestPlot)
#include "test_plot.moc"
