#pragma once

#include <Eigen/Core>

#include <QString>

#include <vector>

namespace prisca::core {

/// One entry of a feature vector phi_l(s).
struct FeatureTerm {
    enum class Source {
        Deviation,  ///< scale * e[index], the tracking error (the paper's features)
        State,      ///< scale * s[index], the raw state
        Constant,   ///< scale (a bias term; index unused)
        /// scale while the reference is one of the demonstration's samples index ..
        /// index + span - 1, else 0: a correction of u* learned for that stretch of the
        /// manoeuvre (a feedforward indexed by where along the demonstration the robot is).
        Phase
    };
    Source source = Source::Deviation;
    int index = 0;       ///< component of e or s (Phase: the stretch's first sample)
    double scale = 1.0;  ///< multiplies the term (use it to bring units to a common size)
    int span = 0;        ///< Phase only: how many samples the stretch covers (>= 1)
    /// Whether the term moves with the error or the state (a feedback), not with where along
    /// the demonstration the reference is (a feedforward).
    bool isFeedback() const { return source == Source::Deviation || source == Source::State; }
};

/// Per-channel state features phi_l(s) in R^p (Algorithm 1, line 3): column l of the p x m
/// matrix Phi holds phi_l. Every channel has the same number p of terms.
class FeatureMap {
  public:
    FeatureMap() = default;
    /// @param perChannel  m lists of p terms each
    explicit FeatureMap(std::vector<std::vector<FeatureTerm>> perChannel);

    /// The same deviation components for every one of m channels.
    static FeatureMap deviationFeatures(int channels, const std::vector<int>& components);

    int featureCount() const { return featureCount_; }                    ///< p
    int channelCount() const { return static_cast<int>(terms_.size()); }  ///< m
    const std::vector<std::vector<FeatureTerm>>& terms() const { return terms_; }

    /// Phi (p x m) from the deviation e, the state s and the reference's demonstration sample
    /// (Phase terms; -1: none, every Phase term 0). No allocation.
    void evaluate(const Eigen::Ref<const Eigen::VectorXd>& deviation,
                  const Eigen::Ref<const Eigen::VectorXd>& state, Eigen::Ref<Eigen::MatrixXd> phi,
                  int reference = -1) const;

    /// This map with, on every channel, Phase terms of `span` samples each covering samples
    /// 0 .. length - 1 (the last may be shorter).
    FeatureMap withPhases(int length, int span) const;

    /// Empty when every index is within a state of dimension n; else the first problem.
    QString validate(int stateDimension) const;

  private:
    std::vector<std::vector<FeatureTerm>> terms_;
    int featureCount_ = 0;
};

}  // namespace prisca::core
