#pragma once

#include <QString>

#include <optional>

class QDialog;
class QWidget;

namespace prisca::app {

/// The one way the window asks the operator something: a dialog that is modal to every other
/// window of the application but never to E-STOP. Qt's own modality would block the window's
/// red button and, under some platforms, route keys past the window's E-STOP filter; here the
/// dialog is shown as a normal window and the EmergencyStopGuard swallows the input meant for
/// every window under it, except the E-STOP button itself. The dialog is placed clear of the
/// widgets marked keepClearOf() (the E-STOP button), and Qt's own file dialog is used (a
/// platform dialog takes keys no filter of ours sees).
///
/// Every function runs a local event loop, as QDialog::exec() does. GUI thread only.
class ModalDialog {
  public:
    /// Runs `dialog` until it is finished; its result (QDialog::Accepted or Rejected; a message
    /// box's clickedButton() says which button).
    static int exec(QDialog& dialog);
    /// The dialog run by exec() that is on top now (the newest still open), or null: the one
    /// window that takes input besides E-STOP.
    static QDialog* top();

    /// Marks `widget` (the E-STOP button) as one no dialog of ours may cover.
    static void keepClearOf(QWidget* widget);
    /// Moves (and if need be shrinks) `window` so it covers no widget marked keepClearOf() and
    /// stays inside its screen. For the dialogs run here and the window's own second windows
    /// (the operator guide, the replay).
    static void placeClear(QWidget* window);

    // Qt's static dialogs, run as above.
    static QString openFileName(QWidget* parent, const QString& caption, const QString& dir,
                                const QString& filter);
    /// Asks before replacing a file that exists. `selectedFilter` in: the filter to preselect;
    /// out: the one chosen.
    static QString saveFileName(QWidget* parent, const QString& caption, const QString& dir,
                                const QString& filter, QString* selectedFilter = nullptr);
    static QString existingDirectory(QWidget* parent, const QString& caption, const QString& dir);
    static void warning(QWidget* parent, const QString& title, const QString& text);
    static void information(QWidget* parent, const QString& title, const QString& text);
    /// Yes or no; `yes` is the default button.
    static bool question(QWidget* parent, const QString& title, const QString& text);
    /// A rich-text about box with the application's icon.
    static void about(QWidget* parent, const QString& title, const QString& text);
    /// A line of text; empty when cancelled.
    static std::optional<QString> text(QWidget* parent, const QString& title, const QString& label,
                                       const QString& initial = QString());

  private:
    static void placeClearNow(QWidget* window);
};

}  // namespace prisca::app
