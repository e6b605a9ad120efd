#include "FeatureMap.h"

#include <stdexcept>

namespace prisca::core {

FeatureMap::FeatureMap(std::vector<std::vector<FeatureTerm>> perChannel)
    : terms_(std::move(perChannel)) {
    if (terms_.empty() || terms_.front().empty()) {
        throw std::invalid_argument("FeatureMap: at least one channel with one feature needed");
    }
    featureCount_ = static_cast<int>(terms_.front().size());
    for (const auto& channel : terms_) {
        if (static_cast<int>(channel.size()) != featureCount_) {
            throw std::invalid_argument("FeatureMap: every channel needs the same number of terms");
        }
    }
}

FeatureMap FeatureMap::deviationFeatures(int channels, const std::vector<int>& components) {
    std::vector<FeatureTerm> channel;
    for (int c : components) {
        channel.push_back({FeatureTerm::Source::Deviation, c, 1.0});
    }
    return FeatureMap(std::vector<std::vector<FeatureTerm>>(channels, channel));
}

void FeatureMap::evaluate(const Eigen::Ref<const Eigen::VectorXd>& deviation,
                          const Eigen::Ref<const Eigen::VectorXd>& state,
                          Eigen::Ref<Eigen::MatrixXd> phi, int reference) const {
    for (int l = 0; l < channelCount(); ++l) {
        const auto& channel = terms_[l];
        for (int i = 0; i < featureCount_; ++i) {
            const FeatureTerm& t = channel[i];
            switch (t.source) {
                case FeatureTerm::Source::Deviation:
                    phi(i, l) = t.scale * deviation[t.index];
                    break;
                case FeatureTerm::Source::State:
                    phi(i, l) = t.scale * state[t.index];
                    break;
                case FeatureTerm::Source::Constant:
                    phi(i, l) = t.scale;
                    break;
                case FeatureTerm::Source::Phase:
                    phi(i, l) =
                        reference >= t.index && reference < t.index + t.span ? t.scale : 0.0;
                    break;
            }
        }
    }
}

FeatureMap FeatureMap::withPhases(int length, int span) const {
    if (length < 1 || span < 1) {
        throw std::invalid_argument("FeatureMap::withPhases: length and span must be >= 1");
    }
    std::vector<std::vector<FeatureTerm>> terms = terms_;
    for (auto& channel : terms) {
        for (int first = 0; first < length; first += span) {
            FeatureTerm t;
            t.source = FeatureTerm::Source::Phase;
            t.index = first;
            t.span = span;
            channel.push_back(t);
        }
    }
    return FeatureMap(std::move(terms));
}

QString FeatureMap::validate(int stateDimension) const {
    for (int l = 0; l < channelCount(); ++l) {
        for (int i = 0; i < featureCount_; ++i) {
            const FeatureTerm& t = terms_[l][i];
            if (t.source == FeatureTerm::Source::Phase) {
                if (t.index < 0 || t.span < 1) {
                    return QStringLiteral(
                               "feature %1 of channel %2: a phase needs a first sample "
                               ">= 0 and a span >= 1 (%3, %4)")
                        .arg(i)
                        .arg(l)
                        .arg(t.index)
                        .arg(t.span);
                }
                continue;
            }
            if (t.source != FeatureTerm::Source::Constant &&
                (t.index < 0 || t.index >= stateDimension)) {
                return QStringLiteral("feature %1 of channel %2 uses component %3, outside 0..%4")
                    .arg(i)
                    .arg(l)
                    .arg(t.index)
                    .arg(stateDimension - 1);
            }
        }
    }
    return {};
}

}  // namespace prisca::core
