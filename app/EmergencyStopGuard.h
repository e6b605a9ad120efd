#pragma once

#include <QKeySequence>
#include <QList>
#include <QObject>
#include <QPointer>

#include <functional>

class QAbstractButton;
class QKeyEvent;
class QWidget;

namespace prisca::app {

/// E-STOP over every window of the application. Installed on the application, it reads every
/// key and click before any widget does:
///
/// - While work is under way (`busy`: a run, a rig trial, driving, a recording, an experiment,
///   a latency measurement), Space and Esc are E-STOP in every window: the main window, its
///   dialogs (ModalDialog's), open menus and lists, the operator guide, the replay. A text field
///   gets its space from Shift+Space then.
/// - With nothing under way, Space and Esc are E-STOP in the main window as before (Space types
///   a space in a text field; Esc first closes an open list), and act as usual in a dialog.
/// - The extra keys (a USB foot switch's: setExtraKeys(), the "estop/keys" setting) are E-STOP
///   anywhere, always.
/// - A click on the E-STOP button is E-STOP with a menu or a list open (the click that would
///   only close it).
/// - While a ModalDialog runs, every other window's input is swallowed (the modality Qt would
///   give), except the E-STOP button's.
///
/// GUI thread only; `press` is called once per press (autorepeat ignored) with what pressed it.
class EmergencyStopGuard : public QObject {
    Q_OBJECT
  public:
    /// `window`: the main window (its floating docks count as it); `button`: the E-STOP button.
    EmergencyStopGuard(QWidget* window, QAbstractButton* button, std::function<bool()> busy,
                       std::function<void(const QString&)> press, QObject* parent = nullptr);
    ~EmergencyStopGuard() override;

    /// Keys that are E-STOP anywhere, always (with their modifiers; empty entries ignored).
    void setExtraKeys(const QList<QKeySequence>& keys);
    const QList<QKeySequence>& extraKeys() const { return extraKeys_; }

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    /// What pressed it ("Space", "Esc", "F13") when `event` is an E-STOP key here; empty if not.
    QString emergencyKey(QObject* watched, const QKeyEvent* key) const;
    bool inMainWindow(const QWidget* widget) const;
    /// Input for `watched` that a ModalDialog on top keeps from it.
    bool shielded(QObject* watched, const QWidget* top) const;

    QPointer<QWidget> window_;
    QPointer<QAbstractButton> button_;
    std::function<bool()> busy_;
    std::function<void(const QString&)> press_;
    QList<QKeySequence> extraKeys_;
    bool reactivating_ = false;
};

}  // namespace prisca::app
