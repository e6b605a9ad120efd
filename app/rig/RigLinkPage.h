#pragma once

#include "devices/TransmitterLink.h"

#include <QString>
#include <QWidget>

class QComboBox;
class QLabel;
class QSpinBox;

namespace prisca::rig {
class RigSession;
}

namespace prisca::app {

class ChannelMapEditor;
class LabSession;

/// The Rig panel's "Link" page: the transmitter's port (the serial ports found, the virtual
/// car's, or a typed path), protocol, baud rate and channel map, and the link's state. It
/// connects the link through the rig session and logs the link's changes of state.
class RigLinkPage : public QWidget {
    Q_OBJECT
  public:
    RigLinkPage(rig::RigSession& rig, LabSession& session, QWidget* parent = nullptr);

    /// Connects with the settings shown (remembered for next time); says so here if no port.
    void connectLink();
    /// The serial ports seen now, the virtual car's first; the port typed is kept.
    void refreshPorts();
    /// The virtual car's port listed and chosen (the virtual rig has just started).
    void chooseVirtualPort();
    /// The protocol chosen, as the status bar names it.
    QString protocolName() const;
    /// The settings a connected link fixes.
    void setLinked(bool linked);
    void showLinkStatus(const devices::LinkStatus& status);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void retranslateUi();

    rig::RigSession& rig_;
    QLabel* portLabel_;
    QComboBox* port_;
    QLabel* protocolLabel_;
    QComboBox* protocol_;
    QLabel* baudLabel_;
    QSpinBox* baud_;
    ChannelMapEditor* channels_;
    QLabel* linkInfo_;
    QString loggedLinkState_;
};

}  // namespace prisca::app
