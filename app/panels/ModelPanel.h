#pragma once

#include "app/plot/Figure.h"
#include "app/workers/IdentificationThread.h"

#include <QElapsedTimer>
#include <QThread>
#include <QWidget>

#include <memory>

class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace prisca::app {

class EmergencyStop;
class LabSession;

/// The Model step, after the mapping's fit: the car's physical parameters identified from the
/// demonstration in the background (IdentificationWorker, with `prisca-cli identify`'s
/// settings), with a progress bar and Cancel; the recorded path and the identified model's
/// replay of the same actions drawn together; the parameters with their standard deviations,
/// identified or held at their prior. The model is the session's (LabSession::identifiedModel):
/// saved with it, dropped when the demonstration or the car changes, and what mpc plans
/// through. Only plants identification knows (the slide-car) have one; for the others the
/// panel says so and Identify is off. E-STOP cancels an identification under way and none
/// starts while it is latched; Cancel, like E-STOP, keeps the model the session had.
class ModelPanel : public QWidget {
    Q_OBJECT
  public:
    ModelPanel(LabSession& session, EmergencyStop& emergency, QWidget* parent = nullptr);
    ~ModelPanel() override;

    /// The search's budget (default: sim::IdentificationSettings{}, `prisca-cli identify`'s).
    /// Tests give a short one. Applies to the next Identify.
    void setIdentificationSettings(const sim::IdentificationSettings& settings);
    bool isRunning() const { return running_; }
    /// Model runs done and the budget of the identification under way (0 of 0 when idle).
    long long progressDone() const { return done_; }
    long long progressTotal() const { return total_; }
    /// The figure shown: the recorded path, and the model's replay once there is a model.
    const plot::Figure& figure() const { return figure_; }

  public slots:
    /// Starts identifying the session's car from its demonstration (the Identify button).
    void identify();
    /// Stops the identification under way; the session keeps the model it had.
    void cancel();

  signals:
    /// An identification ended (a model, a refusal, cancelled or failed).
    void finished();

  protected:
    void changeEvent(QEvent* event) override;
    /// The figure is drawn again at its view's size whenever that changes.
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void retranslateUi();
    void setRunning(bool running);
    void showProgress();
    void showResult(int id, std::shared_ptr<const sim::IdentificationResult> result);
    /// The session's model: summary, table and figure (the demonstration's path alone if none).
    void showModel();
    void showFigure();

    LabSession& session_;
    EmergencyStop& emergency_;
    IdentificationThread* identification_;  ///< the search on its own thread
    sim::IdentificationSettings settings_;
    QLabel* intro_;
    QPushButton* identify_;
    QPushButton* cancel_;
    QProgressBar* progress_;
    QLabel* status_;
    QLabel* summary_;
    QLabel* figureView_;
    QTableWidget* table_;
    QLabel* held_;
    class QTimer* ticker_;
    plot::Figure figure_;
    bool running_ = false;
    bool stoppedByEmergency_ = false;
    int requestId_ = 0;
    /// The demonstration the identification under way fits (the session keeps the model only
    /// if it still holds this one).
    std::shared_ptr<const core::Demonstration> identifying_;
    QElapsedTimer clock_;
    long long done_ = 0, total_ = 0;
};

}  // namespace prisca::app
