#pragma once

#include "rig/RigDoctor.h"

#include <QWidget>

#include <memory>
#include <optional>

class QLabel;
class QPushButton;
class QThread;
class QTreeWidget;

namespace prisca::app {

/// The Rig panel's "This computer" page: prisca-cli doctor's check (rig::diagnose) of the
/// serial ports and their permissions, the cameras, the display, OpenGL and the free space,
/// each line OK or what to do. The system is asked on a thread of its own (a camera's driver
/// may be slow to answer), first when the page is shown, then on Check this computer.
class RigDoctorPage : public QWidget {
    Q_OBJECT
  public:
    explicit RigDoctorPage(QWidget* parent = nullptr);
    ~RigDoctorPage() override;

    /// Asks the system again (nothing if a check is under way).
    void check();
    bool checking() const { return thread_ != nullptr; }
    /// The last report; nullopt before the first check has finished.
    const std::optional<rig::DoctorReport>& report() const { return report_; }

  signals:
    /// A check has finished and its report is shown.
    void checked();

  protected:
    void showEvent(QShowEvent* event) override;
    void changeEvent(QEvent* event) override;

  private:
    void finish();
    void showReport();
    void retranslateUi();

    QPushButton* check_;
    QLabel* summary_;
    QTreeWidget* lines_;
    rig::DoctorRequest request_;
    std::shared_ptr<rig::HostFacts> facts_;  ///< written by the check's thread, read after it
    QThread* thread_ = nullptr;
    std::optional<rig::DoctorReport> report_;
    bool shownOnce_ = false;
};

}  // namespace prisca::app
