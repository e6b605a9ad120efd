#pragma once

#include "devices/ChannelMap.h"

#include <QStringList>
#include <QWidget>

class QLabel;
class QTableWidget;

namespace prisca::app {

/// The rig's channel map as an editable table: per control (throttle, steering) the transmitter
/// channel, trim, travel limits and direction. An edit that makes an invalid map is named under
/// the table and refused as a whole; a valid one is applied, remembered in the settings
/// ("rig/channels") and announced.
class ChannelMapEditor : public QWidget {
    Q_OBJECT
  public:
    explicit ChannelMapEditor(QWidget* parent = nullptr);

    const devices::ChannelMap& channels() const { return channels_; }
    /// The row captions: the plant's action names.
    void setControlNames(const QStringList& names);

  signals:
    void channelsChanged(const prisca::devices::ChannelMap& channels);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void show();
    void apply();
    void retranslateUi();

    QTableWidget* table_;
    QLabel* problem_;
    devices::ChannelMap channels_ = devices::ChannelMap::car();
    bool updating_ = false;
};

}  // namespace prisca::app
