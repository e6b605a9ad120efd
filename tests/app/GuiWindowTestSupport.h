#pragma once

// What the whole-window tests share: the window in view, its docks, its visible texts.

#include "GuiTestSupport.h"

#include <QAbstractAxis>
#include <QChart>
#include <QChartView>
#include "app/MessageLog.h"
#include "app/panels/MessageLogPanel.h"
#include "app/widgets/CameraView.h"
#include "app/workers/ExperimentArchive.h"

#include <QClipboard>
#include <QDialog>
#include <QGroupBox>
#include <QHeaderView>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLoggingCategory>
#include <QMenu>
#include <QMenuBar>
#include <QScreen>
#include <QTextBrowser>
#include <QThread>

#include <opencv2/videoio.hpp>

using namespace prisca::app;
using namespace prisca::test;

namespace {

// True when all of `widget` is inside the window and inside every scrolled view around it: an
// operator sees it without scrolling.
inline bool wholeInView(QWidget* widget) {
    QWidget* window = widget->window();
    const QRect rect(widget->mapTo(window, QPoint(0, 0)), widget->size());
    if (!widget->isVisible() || !window->rect().contains(rect)) {
        return false;
    }
    for (QWidget* p = widget->parentWidget(); p && p != window; p = p->parentWidget()) {
        if (auto* area = qobject_cast<QAbstractScrollArea*>(p)) {
            QWidget* port = area->viewport();
            const QRect seen(port->mapTo(window, QPoint(0, 0)), port->size());
            if (!seen.contains(rect)) {
                return false;
            }
        }
    }
    return true;
}

inline QDockWidget* dockOf(Window& w, const char* name) {
    return w.find<QDockWidget>(name);
}

// Every text an operator can read in the window: labels, buttons, tabs, dock titles, combo
// items, table headers and cells, menus, keyed by where it is.
inline QMap<QString, QString> visibleTexts(QWidget* root) {
    QMap<QString, QString> texts;
    const auto key = [](QObject* o, const QString& what) {
        QString path;
        for (QObject* p = o; p; p = p->parent()) {
            path.prepend(QStringLiteral("/") +
                         (p->objectName().isEmpty()
                              ? QString::fromLatin1(p->metaObject()->className())
                              : p->objectName()));
        }
        return path + QLatin1Char(':') + what + QLatin1Char('@') +
               QString::number(reinterpret_cast<quintptr>(o), 16);
    };
    QList<QWidget*> widgets = root->findChildren<QWidget*>();
    widgets.prepend(root);
    for (QWidget* widget : widgets) {
        // The message log keeps each line as it was said (a record, not the interface).
        bool inLog = false;
        for (QWidget* p = widget; p; p = p->parentWidget()) {
            inLog = inLog || qobject_cast<MessageLogPanel*>(p) != nullptr;
        }
        if (inLog && !qobject_cast<MessageLogPanel*>(widget) &&
            !qobject_cast<QHeaderView*>(widget) && !qobject_cast<QPushButton*>(widget)) {
            continue;
        }
        if (auto* label = qobject_cast<QLabel*>(widget)) {
            texts.insert(key(label, QStringLiteral("text")), label->text());
        } else if (auto* button = qobject_cast<QAbstractButton*>(widget)) {
            texts.insert(key(button, QStringLiteral("text")), button->text());
        } else if (auto* tabs = qobject_cast<QTabWidget*>(widget)) {
            for (int i = 0; i < tabs->count(); ++i) {
                texts.insert(key(tabs, QStringLiteral("tab%1").arg(i)), tabs->tabText(i));
            }
        } else if (auto* dock = qobject_cast<QDockWidget*>(widget)) {
            texts.insert(key(dock, QStringLiteral("title")), dock->windowTitle());
        } else if (auto* combo = qobject_cast<QComboBox*>(widget)) {
            for (int i = 0; i < combo->count(); ++i) {
                texts.insert(key(combo, QStringLiteral("item%1").arg(i)), combo->itemText(i));
            }
        } else if (auto* table = qobject_cast<QTableWidget*>(widget)) {
            for (int c = 0; c < table->columnCount(); ++c) {
                if (auto* item = table->horizontalHeaderItem(c)) {
                    texts.insert(key(table, QStringLiteral("header%1").arg(c)), item->text());
                }
                for (int r = 0; r < table->rowCount(); ++r) {
                    if (auto* item = table->item(r, c)) {
                        texts.insert(key(table, QStringLiteral("cell%1,%2").arg(r).arg(c)),
                                     item->text());
                    }
                }
            }
        } else if (auto* list = qobject_cast<QListWidget*>(widget)) {
            for (int i = 0; i < list->count(); ++i) {
                texts.insert(key(list, QStringLiteral("item%1").arg(i)), list->item(i)->text());
            }
        } else if (auto* group = qobject_cast<QGroupBox*>(widget)) {
            texts.insert(key(group, QStringLiteral("title")), group->title());
        } else if (auto* menu = qobject_cast<QMenu*>(widget)) {
            texts.insert(key(menu, QStringLiteral("title")), menu->title());
            for (QAction* action : menu->actions()) {
                texts.insert(key(action, QStringLiteral("action")), action->text());
            }
        }
    }
    return texts;
}

}  // namespace
