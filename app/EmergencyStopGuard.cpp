#include "app/EmergencyStopGuard.h"

#include "app/widgets/ModalDialog.h"

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDockWidget>
#include <QKeyEvent>
#include <QLineEdit>
#include <QMouseEvent>
#include <QPlainTextEdit>
#include <QTextEdit>
#include <QTimer>

namespace prisca::app {

namespace {

// A field a space is typed into (a number field is none: a space is never part of a number).
bool isTextField(const QWidget* focus) {
    const bool numberField =
        qobject_cast<const QAbstractSpinBox*>(focus) ||
        (focus->parentWidget() && qobject_cast<const QAbstractSpinBox*>(focus->parentWidget()));
    const auto* combo = qobject_cast<const QComboBox*>(focus);
    return !numberField &&
           (qobject_cast<const QLineEdit*>(focus) || qobject_cast<const QTextEdit*>(focus) ||
            qobject_cast<const QPlainTextEdit*>(focus) || (combo && combo->isEditable()));
}

// `window` is `top` or opened from it (a list it dropped down, a dialog it asked).
bool within(const QWidget* window, const QWidget* top) {
    for (const QWidget* w = window; w; w = w->parentWidget()) {
        if (w == top) {
            return true;
        }
    }
    return false;
}

bool isInput(const QEvent* event) {
    switch (event->type()) {
        case QEvent::MouseButtonPress:
        case QEvent::MouseButtonRelease:
        case QEvent::MouseButtonDblClick:
        case QEvent::Wheel:
        case QEvent::KeyPress:
        case QEvent::KeyRelease:
        case QEvent::ShortcutOverride:
        case QEvent::Shortcut:
        case QEvent::ContextMenu:
        case QEvent::TouchBegin:
        case QEvent::TouchUpdate:
        case QEvent::TouchEnd:
        case QEvent::TabletPress:
        case QEvent::Drop:
            return true;
        case QEvent::Close:
            return event->spontaneous();  // the window manager's close button, not close()
        default:
            return false;
    }
}

void closePopups() {
    while (QWidget* popup = QApplication::activePopupWidget()) {
        if (!popup->close()) {
            break;
        }
    }
}

}  // namespace

EmergencyStopGuard::EmergencyStopGuard(QWidget* window, QAbstractButton* button,
                                       std::function<bool()> busy,
                                       std::function<void(const QString&)> press, QObject* parent)
    : QObject(parent),
      window_(window),
      button_(button),
      busy_(std::move(busy)),
      press_(std::move(press)) {
    // Qt's own dialogs everywhere: a platform dialog takes keys this filter never sees.
    QApplication::setAttribute(Qt::AA_DontUseNativeDialogs);
    qApp->installEventFilter(this);
}

EmergencyStopGuard::~EmergencyStopGuard() {
    qApp->removeEventFilter(this);
}

void EmergencyStopGuard::setExtraKeys(const QList<QKeySequence>& keys) {
    extraKeys_.clear();
    for (const QKeySequence& key : keys) {
        if (!key.isEmpty()) {
            extraKeys_ << QKeySequence(key[0]);  // one key each
        }
    }
}

bool EmergencyStopGuard::inMainWindow(const QWidget* widget) const {
    const QWidget* top = widget->window();
    return top == window_ ||
           (qobject_cast<const QDockWidget*>(top) && top->parentWidget() == window_);
}

QString EmergencyStopGuard::emergencyKey(QObject* watched, const QKeyEvent* key) const {
    auto* widget = qobject_cast<QWidget*>(watched);
    if (!widget || key->key() == 0 || key->key() == Qt::Key_unknown) {
        return {};
    }
    const Qt::KeyboardModifiers modifiers = key->modifiers() & ~Qt::KeypadModifier;
    for (const QKeySequence& extra : extraKeys_) {
        if (extra[0] == QKeyCombination(modifiers, static_cast<Qt::Key>(key->key()))) {
            return extra.toString(QKeySequence::NativeText);
        }
    }
    const bool space = key->key() == Qt::Key_Space;
    if ((!space && key->key() != Qt::Key_Escape) || modifiers != Qt::NoModifier) {
        return {};
    }
    const QString name = space ? tr("Space") : tr("Esc");
    if (busy_ && busy_()) {
        return name;  // something moves or runs: in every window, whatever has the focus
    }
    // Nothing under way: the main window's keys, as before; a list or a dialog keeps its own.
    if (QApplication::activePopupWidget() || QApplication::activeModalWidget() ||
        ModalDialog::top() || !inMainWindow(widget) || (space && isTextField(widget))) {
        return {};
    }
    return name;
}

bool EmergencyStopGuard::shielded(QObject* watched, const QWidget* top) const {
    const auto* widget = qobject_cast<const QWidget*>(watched);
    if (!widget) {
        // A shortcut reaches its action: only the active window's shortcuts fire.
        if (watched->isWindowType() || watched == qApp) {
            return false;
        }
        const QWidget* active = QApplication::activeWindow();
        return active && !within(active, top);
    }
    if (button_ && (widget == button_ || button_->isAncestorOf(widget))) {
        return false;  // E-STOP is never blocked
    }
    // A popup (a list the dialog dropped down, its file name completer, a tool tip) can only
    // have been opened from the dialog: the windows under it take no input.
    const Qt::WindowType type = widget->window()->windowType();
    if (type == Qt::Popup || type == Qt::ToolTip) {
        return false;
    }
    return !within(widget->window(), top);
}

bool EmergencyStopGuard::eventFilter(QObject* watched, QEvent* event) {
    switch (event->type()) {
        case QEvent::ShortcutOverride:
        case QEvent::KeyPress: {
            const auto* key = static_cast<QKeyEvent*>(event);
            const QString by = emergencyKey(watched, key);
            if (by.isEmpty()) {
                break;
            }
            // Taken from the shortcut map (ShortcutOverride) and from every widget (KeyPress).
            event->accept();
            if (event->type() == QEvent::KeyPress && !key->isAutoRepeat()) {
                closePopups();
                press_(by);
            }
            return true;
        }
        case QEvent::MouseButtonPress:
        case QEvent::MouseButtonDblClick: {
            // A list or menu open takes every click, the one on E-STOP too (it would only close
            // it).
            auto* widget = qobject_cast<QWidget*>(watched);
            if (QApplication::activePopupWidget() && button_ && button_->isVisible() && widget &&
                widget->window()->windowType() == Qt::Popup) {
                const auto* mouse = static_cast<QMouseEvent*>(event);
                const QPoint at = button_->mapFromGlobal(mouse->globalPosition().toPoint());
                if (button_->rect().contains(at)) {
                    closePopups();
                    press_(tr("the E-STOP button"));
                    return true;
                }
            }
            break;
        }
        default:
            break;
    }
    QDialog* top = ModalDialog::top();
    if (!top) {
        return false;
    }
    if (event->type() == QEvent::WindowActivate) {
        auto* widget = qobject_cast<QWidget*>(watched);
        if (widget && widget->isWindow() && !within(widget, top) && !reactivating_) {
            // A window under the dialog came forward (a click on E-STOP does that): the dialog
            // gets the keys back once the click is handled (a transient dialog stays above it).
            QPointer<QDialog> dialog(top);
            QTimer::singleShot(0, this, [this, dialog] {
                if (dialog && dialog->isVisible()) {
                    reactivating_ = true;
                    dialog->activateWindow();
                    reactivating_ = false;
                }
            });
        }
        return false;
    }
    if (isInput(event) && shielded(watched, top)) {
        event->ignore();
        return true;
    }
    return false;
}

}  // namespace prisca::app
