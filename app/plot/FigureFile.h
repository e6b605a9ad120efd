#pragma once

// A figure to a file or an image: drawn by FigureScene, the file replaced atomically.

#include "app/plot/Figure.h"

#include <QImage>
#include <QString>

namespace prisca::app::plot {

/// Renders to path; the format comes from the extension (.png or .svg, any case). The file is
/// replaced atomically. False and *error (naming the path) on an unknown extension, an empty
/// figure size, no QApplication or a file that cannot be written. error may be null.
bool saveFigure(const Figure& figure, const QString& path, QString* error);

/// Renders into an ARGB32 image of figure.size (null for an empty or absurd size, > 16384 px,
/// or without a QApplication).
QImage renderFigure(const Figure& figure);

}  // namespace prisca::app::plot
