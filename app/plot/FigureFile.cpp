#include "app/plot/FigureFile.h"

#include "app/plot/FigureScene.h"
#include "core/FileIo.h"

#include <QApplication>
#include <QBuffer>
#include <QFileInfo>
#include <QPainter>
#include <QSvgGenerator>

namespace prisca::app::plot {

namespace {

// An SVG keeps four points per pixel column of a long line, so a reader may zoom in four times.
constexpr int kSvgColumnsPerPixel = 4;

bool fail(QString* error, const QString& message) {
    if (error) {
        *error = message;
    }
    return false;
}

}  // namespace

QImage renderFigure(const Figure& figure) {
    const FigureScene scene(figure);
    if (!scene.isValid()) {
        return {};
    }
    QImage image(figure.size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter painter(&image);
    scene.render(&painter);
    painter.end();
    return image.convertToFormat(QImage::Format_ARGB32);
}

bool saveFigure(const Figure& figure, const QString& path, QString* error) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != QLatin1String("png") && suffix != QLatin1String("svg")) {
        return fail(
            error,
            QStringLiteral("%1: unknown plot format \"%2\" (use .png or .svg)").arg(path, suffix));
    }
    if (!drawableFigureSize(figure.size)) {
        return fail(error, QStringLiteral("%1: bad figure size %2 x %3")
                               .arg(path)
                               .arg(figure.size.width())
                               .arg(figure.size.height()));
    }
    if (!qobject_cast<QApplication*>(QCoreApplication::instance())) {
        // QtCharts draws with widgets (e.g. on the offscreen platform).
        return fail(error, QStringLiteral("%1: rendering a plot needs a QApplication").arg(path));
    }
    // Encoded in memory, then written by the one atomic writer, which checks that every byte
    // reached the disk: a device's short write (a full disk) is not an error to QTextStream or
    // QImageWriter, and QSaveFile::commit() does not report a failed final flush.
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    if (suffix == QLatin1String("png")) {
        if (!renderFigure(figure).save(&buffer, "PNG")) {
            return fail(error, QStringLiteral("%1: cannot encode PNG").arg(path));
        }
    } else {
        const FigureScene scene(figure, kSvgColumnsPerPixel);
        QSvgGenerator generator;
        generator.setOutputDevice(&buffer);
        generator.setSize(figure.size);
        generator.setViewBox(QRect(QPoint(0, 0), figure.size));
        generator.setResolution(96);  // so width and height in mm come out as CSS pixels
        generator.setTitle(figure.title);
        generator.setDescription(QStringLiteral("PRISCA Lab figure"));
        QPainter painter;
        if (!painter.begin(&generator)) {
            return fail(error, QStringLiteral("%1: cannot start the SVG").arg(path));
        }
        painter.fillRect(QRectF(QPointF(0, 0), QSizeF(figure.size)), Qt::white);
        scene.render(&painter);
        painter.end();
    }
    buffer.close();
    core::FileError fileError;
    if (!core::writeFileAtomically(path, bytes, &fileError)) {
        return fail(error, fileError.toString());
    }
    return true;
}

}  // namespace prisca::app::plot
