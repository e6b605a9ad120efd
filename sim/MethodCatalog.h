#pragma once

#include "core/Controller.h"
#include "sim/tuning/MethodSpec.h"
#include "sim/tuning/MethodTuning.h"

#include <QStringList>

#include <functional>
#include <memory>
#include <vector>

namespace prisca::sim {

/// The methods, in the order every list shows them.
class MethodCatalog {
  public:
    static const std::vector<MethodSpec>& all();
    /// Every id; the ids with a Table I row; the ids a learning curve can show.
    static QStringList ids();
    static QStringList table1Ids();
    /// The Table I methods run when none are named (inDefaultTable1).
    static QStringList defaultTable1Ids();
    static QStringList curveIds();
    /// The spec of an id, or null.
    static const MethodSpec* find(const QString& id);
    static bool contains(const QString& id) { return find(id) != nullptr; }
    /// The spec of an id; std::invalid_argument naming the known ids if there is none.
    static const MethodSpec& get(const QString& id);
    /// Every parameter any method declares, once each, in catalog order.
    static std::vector<const MethodParameter*> parameters();
    /// The declaration of a parameter by name, or null.
    static const MethodParameter* parameter(const QString& name);
    /// The value of a declared parameter in a profile; std::invalid_argument for a name no
    /// method declares.
    static Eigen::VectorXd value(const MethodTuning& profile, const QString& name);
    /// The features `method`'s theta is over in a profile (MethodTuning::featuresFor with the
    /// method's ownFeatures; the shared ones for an unknown id).
    static const core::FeatureMap& featuresOf(const MethodTuning& profile, const QString& method);
    /// Applies "NAME=VALUE" (as --param and the session spell it) to a profile; throws
    /// std::invalid_argument naming the parameter, the value and what is allowed (an unknown
    /// name lists the known ones).
    static void setParameter(MethodTuning& profile, const QString& assignment);
    /// The controller of `method` (std::invalid_argument for an unknown one or inconsistent
    /// shapes). "pd-selected" uses profile.pd: pass a profile whose gains were selected.
    static std::unique_ptr<core::Controller> create(
        const QString& method, const MethodTuning& profile,
        std::shared_ptr<const core::Demonstration> demonstration, const Eigen::MatrixXd& fittedB,
        const Eigen::MatrixXd* theta = nullptr, const std::function<bool()>& cancelled = {});
};

}  // namespace prisca::sim
