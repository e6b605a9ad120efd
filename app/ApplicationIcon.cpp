#include "app/ApplicationIcon.h"

#include <QImageReader>

namespace prisca::app {

QIcon applicationIcon() {
    QIcon icon;
    // Reading SVG needs the optional QtSvg plugin; without it the icon falls back to the PNGs.
    if (QImageReader::supportedImageFormats().contains("svg")) {
        icon.addFile(QStringLiteral(":/icons/prisca.svg"));
    }
    for (const int size : {16, 32, 48, 64, 128, 256}) {
        icon.addFile(QStringLiteral(":/icons/prisca-%1.png").arg(size), QSize(size, size));
    }
    return icon;
}

}  // namespace prisca::app
