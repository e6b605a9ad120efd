#pragma once

#include <QObject>
#include <QString>
#include <QTime>

namespace prisca::app {

/// The window's one E-STOP latch. Every job the window runs (a simulated run, a recording,
/// driving on the rig, a rig trial, a latency measurement, an experiment, an identification)
/// stops when it engages (each listens to engaged()); nothing starts while it is latched (each
/// start asks isLatched() and shows refusal()); the panels, the toolbar and the status bar read
/// its state here and follow latchChanged(). What presses it (Space, Esc, the red button, a
/// gamepad button, a foot switch) is the EmergencyStopGuard's and the window's business; this is
/// only the latch. GUI thread only.
class EmergencyStop : public QObject {
    Q_OBJECT
  public:
    explicit EmergencyStop(QObject* parent = nullptr) : QObject(parent) {}

    bool isLatched() const { return latched_; }
    /// When it was last engaged (invalid: never).
    QTime engagedAt() const { return engagedAt_; }
    /// What pressed it last, in the operator's words ("Space", "the E-STOP button").
    const QString& pressedBy() const { return pressedBy_; }
    /// The sentence a start refused by the latch shows.
    QString refusal() const;

  public slots:
    /// Latches and tells every job to stop. Pressed again while latched, the jobs are told
    /// again (what started in between cannot, but a second press costs nothing).
    void engage(const QString& pressedBy);
    /// Releases the latch; jobs may start again (none starts by itself).
    void reset();

  signals:
    /// Every job stops: sent on each press, before anything else reacts.
    void engaged();
    /// The latch was released.
    void released();
    /// The latch's state changed (false after a reset).
    void latchChanged(bool latched);

  private:
    bool latched_ = false;
    QTime engagedAt_;
    QString pressedBy_;
};

}  // namespace prisca::app
