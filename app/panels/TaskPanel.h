#pragma once

#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace prisca::app {

class LabSession;

/// The target (simulated slide-car, acrobot or aircraft), its physical parameters (the
/// catalog's or a plant file's) and the demonstration to repeat:
/// which one is loaded, open one from a CSV file, save it, or take the scripted operator's in
/// one of the plant's styles (keyboard or stick, left or right, ...) with a seed.
/// A file that cannot be used gets a message box naming the file and the problem.
class TaskPanel : public QWidget {
    Q_OBJECT
  public:
    explicit TaskPanel(LabSession& session, QWidget* parent = nullptr);

    /// Opens a demonstration CSV into the session; on failure shows a message box and leaves
    /// the session as it was. Returns whether it was loaded.
    bool openDemonstration(const QString& path);
    /// Loads a plant file (the plant's physical parameters) into the session; on failure shows
    /// a message box naming the file, the key and the range, and leaves the session as it was.
    bool openPlantParameters(const QString& path);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void retranslateUi();
    void showDemonstration();
    void askOpen();
    void askSave();
    void fillStyles();
    /// A demonstration style's name as shown in the window's language.
    static QString styleLabel(const QString& name);
    void useScripted();
    void showPlantParameters();
    void askOpenPlantParameters();

    LabSession& session_;
    QLabel* targetLabel_;
    QComboBox* target_;
    QLabel* demonstration_;
    QPushButton* open_;
    QPushButton* save_;
    QLabel* styleLabel_;
    QComboBox* style_;
    QSpinBox* seed_;
    QPushButton* scripted_;
    QLabel* plantFileLabel_;
    QLabel* plantFile_;
    QPushButton* openPlantFile_;
    QPushButton* clearPlantFile_;
};

}  // namespace prisca::app
