#include "app/rig/RigLinkPage.h"

#include "app/LabSession.h"
#include "app/MessageLog.h"
#include "app/widgets/ChannelMapEditor.h"
#include "rig/RigSession.h"

#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QSerialPortInfo>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

namespace prisca::app {

RigLinkPage::RigLinkPage(rig::RigSession& rig, LabSession& session, QWidget* parent)
    : QWidget(parent),
      rig_(rig),
      portLabel_(new QLabel(this)),
      port_(new QComboBox(this)),
      protocolLabel_(new QLabel(this)),
      protocol_(new QComboBox(this)),
      baudLabel_(new QLabel(this)),
      baud_(new QSpinBox(this)),
      channels_(new ChannelMapEditor(this)),
      linkInfo_(new QLabel(this)) {
    setObjectName(QStringLiteral("rigLink"));
    port_->setObjectName(QStringLiteral("linkPort"));
    port_->setEditable(true);
    protocol_->setObjectName(QStringLiteral("linkProtocol"));
    linkInfo_->setObjectName(QStringLiteral("linkStatus"));
    linkInfo_->setWordWrap(true);
    baud_->setObjectName(QStringLiteral("linkBaud"));
    baud_->setRange(0, 4000000);
    baud_->setSingleStep(100000);
    for (devices::RcProtocol p : {devices::RcProtocol::Crsf, devices::RcProtocol::Sbus,
                                  devices::RcProtocol::Multiprotocol}) {
        protocol_->addItem(devices::protocolName(p).toUpper(), static_cast<int>(p));
    }
    // The trainer-port bridge (devices/firmware): SBUS on the wire, PPM to the transmitter.
    protocol_->addItem(tr("PPM bridge (trainer port)"),
                       static_cast<int>(devices::RcProtocol::PpmBridge));
    const QSettings settings;
    protocol_->setCurrentIndex(settings.value("rig/protocol", 0).toInt());
    baud_->setValue(settings.value("rig/baud", 0).toInt());

    auto* form = new QFormLayout;
    form->addRow(portLabel_, port_);
    form->addRow(protocolLabel_, protocol_);
    form->addRow(baudLabel_, baud_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(channels_);
    layout->addWidget(linkInfo_);
    layout->addStretch(1);

    // A new map takes effect on the next trial (the loop is rebuilt with it).
    connect(channels_, &ChannelMapEditor::channelsChanged, &rig_, &rig::RigSession::setChannels);
    connect(&session, &LabSession::plantChanged, this,
            [this, &session] { channels_->setControlNames(session.profile().info.actionNames); });
    rig_.setChannels(channels_->channels());
    channels_->setControlNames(session.profile().info.actionNames);
    refreshPorts();
    retranslateUi();
}

void RigLinkPage::connectLink() {
    devices::LinkSettings settings;
    settings.port = port_->currentText().trimmed();
    if (settings.port.isEmpty()) {
        showStatus(linkInfo_, tr("Link"), tr("Choose or type the transmitter's port first."));
        return;
    }
    settings.protocol = static_cast<devices::RcProtocol>(protocol_->currentData().toInt());
    settings.failsafe = channels_->channels().failsafe();
    settings.baud = baud_->value();
    settings.sendOnCommand = true;  // a camera frame's command goes out at once
    QSettings saved;
    saved.setValue("rig/baud", baud_->value());
    saved.setValue("rig/port", settings.port);
    saved.setValue("rig/protocol", protocol_->currentIndex());
    rig_.connectLink(settings);
}

void RigLinkPage::refreshPorts() {
    const QString current = port_->currentText();
    port_->clear();
    if (!rig_.virtualPort().isEmpty()) {
        port_->addItem(rig_.virtualPort());
    }
    for (const QSerialPortInfo& info : QSerialPortInfo::availablePorts()) {
        port_->addItem(info.systemLocation());
    }
    port_->setEditText(current.isEmpty() ? QSettings().value("rig/port").toString() : current);
}

void RigLinkPage::chooseVirtualPort() {
    refreshPorts();
    port_->setEditText(rig_.virtualPort());
}

QString RigLinkPage::protocolName() const {
    return protocol_->currentText();
}

void RigLinkPage::setLinked(bool linked) {
    port_->setEnabled(!linked);
    protocol_->setEnabled(!linked);
    baud_->setEnabled(!linked);
}

void RigLinkPage::showLinkStatus(const devices::LinkStatus& status) {
    setLinked(status.connected);
    QString text = status.connected ? tr("Link: connected, %1 frames/s, %2 sent")
                                          .arg(status.measuredRateHz, 0, 'f', 0)
                                          .arg(status.framesSent)
                                    : tr("Link: not connected");
    if (status.connected && status.failsafe != devices::FailsafeReason::None) {
        text += tr("; failsafe (%1)").arg(devices::failsafeReasonText(status.failsafe));
    }
    if (!status.lastError.isEmpty()) {
        text += QStringLiteral("\n") + status.lastError;
    }
    linkInfo_->setText(text);
    // The log gets the link's changes of state, not its every rate update.
    QString state = status.connected ? tr("Link: connected") : tr("Link: not connected");
    if (status.connected && status.failsafe != devices::FailsafeReason::None) {
        state += tr("; failsafe (%1)").arg(devices::failsafeReasonText(status.failsafe));
    }
    if (!status.lastError.isEmpty()) {
        state += QStringLiteral(": ") + status.lastError;
    }
    // Compared by what it means, not its words (a language switch is no change of state).
    const QString key = QStringLiteral("%1/%2/%3")
                            .arg(status.connected)
                            .arg(static_cast<int>(status.connected ? status.failsafe
                                                                   : devices::FailsafeReason::None))
                            .arg(status.lastError);
    if (key != loggedLinkState_) {
        loggedLinkState_ = key;
        logMessage(this, tr("Link"),
                   status.lastError.isEmpty() ? MessageLevel::Info : MessageLevel::Warning, state);
    }
}

void RigLinkPage::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QWidget::changeEvent(event);
}

void RigLinkPage::retranslateUi() {
    portLabel_->setText(tr("Transmitter port:"));
    port_->setToolTip(tr("A serial port found on this computer, or type a device path"));
    protocolLabel_->setText(tr("Protocol:"));
    baudLabel_->setText(tr("Baud rate:"));
    baud_->setSpecialValueText(tr("protocol default"));
    baud_->setToolTip(tr("0: the protocol's own (CRSF 420000; SBUS and Multiprotocol 100000 8E2)"));
    protocol_->setItemText(protocol_->findData(static_cast<int>(devices::RcProtocol::PpmBridge)),
                           tr("PPM bridge (trainer port)"));
    showLinkStatus(rig_.linkStatus());
}

}  // namespace prisca::app
