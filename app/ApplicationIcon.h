#pragma once

#include <QIcon>

namespace prisca::app {

/// The PRISCA Lab icon (a demonstrated path ending in its target) from the embedded resources:
/// the SVG when Qt's SVG plugin is installed, else the PNG renders of it.
QIcon applicationIcon();

}  // namespace prisca::app
