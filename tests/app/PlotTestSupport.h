#pragma once

// What the plot tests share: figures to draw and pixels to read back.

#include "app/plot/DataClipping.h"
#include "app/plot/Figure.h"
#include "app/plot/FigureFile.h"
#include "app/plot/FigureScene.h"
#include "support/FileSizeLimit.h"

#include <QApplication>
#include <QChart>
#include <QDir>
#include <QFile>
#include <QLegend>
#include <QLegendMarker>
#include <QLogValueAxis>
#include <QPainter>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QValueAxis>
#include <QXYSeries>
#include <QtTest>

#include <cmath>
#include <limits>

#include <unistd.h>

using namespace prisca::app::plot;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

inline bool isRedish(QRgb c) {
    return qRed(c) > 180 && qGreen(c) < 120 && qBlue(c) < 120;
}

inline bool isBluish(QRgb c) {
    return qBlue(c) > 180 && qRed(c) < 120 && qGreen(c) < 120;
}

inline Figure onePanel(const Axes& axes, QSize size = QSize(1200, 800)) {
    Figure figure;
    figure.size = size;
    figure.panels.push_back(axes);
    return figure;
}

inline Line horizontalLine(double y, double x0, double x1, QColor color = Qt::red) {
    Line line;
    line.color = color;
    line.width = 3.0;
    line.points = {{x0, y}, {x1, y}};
    return line;
}

// The mean row of the reddish pixels in one column, or -1 if there are none.
inline double redRow(const QImage& image, int column) {
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

inline QImage render(const FigureScene& scene, QSize size) {
    QImage image(size, QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    scene.render(&painter);
    return image;
}

inline QImage renderSvg(const QString& path, QSize size) {
    QSvgRenderer renderer(path);
    QImage image(size, QImage::Format_ARGB32);
    image.fill(Qt::white);
    if (renderer.isValid()) {
        QPainter painter(&image);
        renderer.render(&painter, QRectF(QPointF(0, 0), QSizeF(size)));
    }
    return image;
}

// The data range a panel's axes show.
inline QRectF shownRange(const FigureScene& scene, int panel) {
    QChart* chart = scene.chart(panel);
    const auto* x = qobject_cast<QValueAxis*>(chart->axes(Qt::Horizontal).at(0));
    QAbstractAxis* yAxis = chart->axes(Qt::Vertical).at(0);
    double y0 = 0.0, y1 = 0.0;
    if (const auto* log = qobject_cast<QLogValueAxis*>(yAxis)) {
        y0 = log->min();
        y1 = log->max();
    } else {
        y0 = static_cast<QValueAxis*>(yAxis)->min();
        y1 = static_cast<QValueAxis*>(yAxis)->max();
    }
    return QRectF(QPointF(x->min(), y0), QPointF(x->max(), y1));
}

// The names of the legend entries shown.
inline QStringList legendNames(const FigureScene& scene, int panel) {
    QStringList names;
    QLegend* legend = scene.chart(panel)->legend();
    if (!legend->isVisible()) {
        return names;
    }
    for (QLegendMarker* marker : legend->markers()) {
        if (marker->isVisible()) {
            names << marker->label();
        }
    }
    return names;
}

}  // namespace
