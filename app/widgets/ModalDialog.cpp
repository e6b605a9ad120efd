#include "app/widgets/ModalDialog.h"

#include <QApplication>
#include <QDialog>
#include <QEventLoop>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QScreen>
#include <QTimer>

#include <algorithm>

namespace prisca::app {

namespace {

// A dialog run by exec(): the order it was opened in (the newest is on top).
const char* const kOrderProperty = "prisca.modalOrder";
// A widget no dialog may cover (the E-STOP button).
const char* const kKeepClearProperty = "prisca.keepClear";
constexpr int kMargin = 8;      // px between a dialog and what it keeps clear of
constexpr int kSettleMs = 200;  // a window manager frames and places a new window within this

int nextOrder() {
    static int order = 0;  // GUI thread only
    return ++order;
}

QList<QWidget*> keptClear(const QWidget* except) {
    QList<QWidget*> widgets;
    for (QWidget* top : QApplication::topLevelWidgets()) {
        if (top == except || !top->isVisible()) {
            continue;
        }
        for (QWidget* w : top->findChildren<QWidget*>()) {
            if (w->property(kKeepClearProperty).toBool() && w->isVisible()) {
                widgets << w;
            }
        }
    }
    return widgets;
}

// Qt's save dialog asks before replacing a file with an application-modal box of its own, which
// would block E-STOP: this one asks through ModalDialog.
class SaveFileDialog : public QFileDialog {
  public:
    using QFileDialog::QFileDialog;
    void accept() override {
        const QString path = selectedFiles().value(0);
        const QFileInfo info(path);
        if (!path.isEmpty() && info.exists() && !info.isDir() &&
            !ModalDialog::question(
                this, windowTitle(),
                QCoreApplication::translate("prisca::app::ModalDialog",
                                            "%1 already exists.\nDo you want to replace it?")
                    .arg(info.fileName()))) {
            return;
        }
        QFileDialog::accept();
    }
};

}  // namespace

int ModalDialog::exec(QDialog& dialog) {
    // Shown as a window of its own: the guard, not Qt, keeps the other windows from input, and
    // spares the E-STOP button.
    dialog.setWindowModality(Qt::NonModal);
    dialog.setAttribute(Qt::WA_ShowModal, false);
    dialog.setProperty(kOrderProperty, nextOrder());
    dialog.setResult(0);
    QPointer<QDialog> alive(&dialog);
    QEventLoop loop;
    QObject::connect(&dialog, &QDialog::finished, &loop, &QEventLoop::quit);
    QObject::connect(&dialog, &QObject::destroyed, &loop, &QEventLoop::quit);
    dialog.show();
    placeClear(&dialog);
    dialog.activateWindow();
    if (dialog.isVisible()) {  // a dialog may finish while it is shown (an immediate answer)
        loop.exec(QEventLoop::DialogExec);
    }
    if (!alive) {
        return QDialog::Rejected;
    }
    dialog.setProperty(kOrderProperty, QVariant());
    return dialog.result();
}

QDialog* ModalDialog::top() {
    QDialog* newest = nullptr;
    int newestOrder = 0;
    for (QWidget* w : QApplication::topLevelWidgets()) {
        auto* dialog = qobject_cast<QDialog*>(w);
        if (!dialog || !dialog->isVisible()) {
            continue;
        }
        const int order = dialog->property(kOrderProperty).toInt();
        if (order > newestOrder) {
            newestOrder = order;
            newest = dialog;
        }
    }
    return newest;
}

void ModalDialog::keepClearOf(QWidget* widget) {
    widget->setProperty(kKeepClearProperty, true);
}

void ModalDialog::placeClear(QWidget* window) {
    placeClearNow(window);
    // Once the window manager has framed and placed it (its title bar is known then, and it
    // may have moved it), once more.
    QPointer<QWidget> alive(window);
    QTimer::singleShot(kSettleMs, window, [alive] {
        if (alive && alive->isVisible()) {
            placeClearNow(alive);
        }
    });
}

void ModalDialog::placeClearNow(QWidget* window) {
    QScreen* screen = window->screen() ? window->screen() : QGuiApplication::primaryScreen();
    if (!screen) {
        return;
    }
    const QRect available = screen->availableGeometry();
    // The frame's allowance (a window manager's title bar and borders); before the window
    // manager has framed it, a title bar's worth is assumed above it.
    QSize frameExtra = window->frameGeometry().size() - window->geometry().size();
    QRect frame = window->frameGeometry();
    if (frameExtra.isNull()) {
        const int titleBar = window->fontMetrics().height() + 14;
        frameExtra = QSize(0, titleBar);
        frame.setTop(frame.top() - titleBar);
    }
    const auto fitInside = [&] {
        frame.setSize(frame.size().boundedTo(available.size()));
        frame.moveLeft(
            std::clamp(frame.left(), available.left(), available.right() - frame.width() + 1));
        frame.moveTop(
            std::clamp(frame.top(), available.top(), available.bottom() - frame.height() + 1));
    };
    fitInside();
    for (QWidget* keep : keptClear(window)) {
        const QRect r(keep->mapToGlobal(QPoint(0, 0)), keep->size());
        if (!frame.intersects(r.adjusted(-kMargin, -kMargin, kMargin, kMargin))) {
            continue;
        }
        // Below it, as tall as the screen leaves; if that is too short, beside it on the left.
        const int below = r.bottom() + 1 + kMargin;
        const int minimumHeight = window->minimumSizeHint().height() + frameExtra.height();
        if (available.bottom() + 1 - below >= std::max(minimumHeight, 200)) {
            frame.moveTop(below);
            frame.setBottom(std::min(frame.bottom(), available.bottom()));
        } else {
            frame.moveRight(r.left() - 1 - kMargin);
            frame.setLeft(std::max(frame.left(), available.left()));
        }
    }
    const QSize inner = (frame.size() - frameExtra).expandedTo(window->minimumSize());
    if (inner != window->size()) {
        window->resize(inner);
    }
    window->move(frame.topLeft());  // a top-level's position is its frame's
}

QString ModalDialog::openFileName(QWidget* parent, const QString& caption, const QString& dir,
                                  const QString& filter) {
    QFileDialog dialog(parent, caption, dir, filter);
    dialog.setOption(QFileDialog::DontUseNativeDialog);
    dialog.setFileMode(QFileDialog::ExistingFile);
    dialog.setAcceptMode(QFileDialog::AcceptOpen);
    return exec(dialog) == QDialog::Accepted ? dialog.selectedFiles().value(0) : QString();
}

QString ModalDialog::saveFileName(QWidget* parent, const QString& caption, const QString& dir,
                                  const QString& filter, QString* selectedFilter) {
    SaveFileDialog dialog(parent, caption, dir, filter);
    dialog.setOption(QFileDialog::DontUseNativeDialog);
    dialog.setOption(QFileDialog::DontConfirmOverwrite);  // asked by SaveFileDialog::accept
    dialog.setFileMode(QFileDialog::AnyFile);
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    if (selectedFilter && !selectedFilter->isEmpty()) {
        dialog.selectNameFilter(*selectedFilter);
    }
    if (exec(dialog) != QDialog::Accepted) {
        return {};
    }
    if (selectedFilter) {
        *selectedFilter = dialog.selectedNameFilter();
    }
    return dialog.selectedFiles().value(0);
}

QString ModalDialog::existingDirectory(QWidget* parent, const QString& caption,
                                       const QString& dir) {
    QFileDialog dialog(parent, caption, dir);
    dialog.setOptions(QFileDialog::DontUseNativeDialog | QFileDialog::ShowDirsOnly);
    dialog.setFileMode(QFileDialog::Directory);
    return exec(dialog) == QDialog::Accepted ? dialog.selectedFiles().value(0) : QString();
}

void ModalDialog::warning(QWidget* parent, const QString& title, const QString& text) {
    QMessageBox box(QMessageBox::Warning, title, text, QMessageBox::Ok, parent);
    exec(box);
}

void ModalDialog::information(QWidget* parent, const QString& title, const QString& text) {
    QMessageBox box(QMessageBox::Information, title, text, QMessageBox::Ok, parent);
    exec(box);
}

bool ModalDialog::question(QWidget* parent, const QString& title, const QString& text) {
    QMessageBox box(QMessageBox::Question, title, text, QMessageBox::Yes | QMessageBox::No, parent);
    box.setDefaultButton(QMessageBox::Yes);
    exec(box);
    return box.clickedButton() == box.button(QMessageBox::Yes);
}

void ModalDialog::about(QWidget* parent, const QString& title, const QString& text) {
    QMessageBox box(QMessageBox::NoIcon, title, text, QMessageBox::Ok, parent);
    box.setTextFormat(Qt::RichText);
    const QIcon icon = QApplication::windowIcon();
    if (!icon.isNull()) {
        box.setIconPixmap(icon.pixmap(64, 64));
    }
    exec(box);
}

std::optional<QString> ModalDialog::text(QWidget* parent, const QString& title,
                                         const QString& label, const QString& initial) {
    QInputDialog dialog(parent);
    dialog.setWindowTitle(title);
    dialog.setLabelText(label);
    dialog.setTextValue(initial);
    dialog.setInputMode(QInputDialog::TextInput);
    if (exec(dialog) != QDialog::Accepted) {
        return std::nullopt;
    }
    return dialog.textValue();
}

}  // namespace prisca::app
