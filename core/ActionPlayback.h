#pragma once

#include "Controller.h"

namespace prisca::core {

/// Action playback: u_k = u*_k open loop, by time (the last action is held past the end).
/// The observation is used only to report the tracking error against s*_k.
class ActionPlayback : public Controller {
  public:
    explicit ActionPlayback(TrackingProblem problem);

    QString name() const override { return QStringLiteral("playback"); }
    void reset(ResetMode mode = ResetMode::Cold) override;
    const ControlStep& step(const Eigen::Ref<const Eigen::VectorXd>& observation) override;
    std::unique_ptr<Controller> clone() const override;

  private:
    TrackingProblem problem_;
    ControlStep record_;
    int step_ = 0;
};

}  // namespace prisca::core
