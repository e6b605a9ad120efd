#pragma once

#include <QLatin1String>
#include <QWidget>

namespace prisca::app {

/// A new widget of `parent` with the object name the tests, the settings and the style find it
/// by: `startCamera_(named<QPushButton>(this, "startCamera"))`.
template <typename Widget>
Widget* named(QWidget* parent, const char* name) {
    auto* widget = new Widget(parent);
    widget->setObjectName(QLatin1String(name));
    return widget;
}

}  // namespace prisca::app
