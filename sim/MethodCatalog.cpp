// The method catalog: every method in Table I's order, read from its declarations (one family
// to a file under sim/methods/), and the queries on it.
#include "sim/MethodCatalog.h"

#include "sim/methods/Declarations.h"

#include <algorithm>
#include <stdexcept>

namespace prisca::sim {

namespace {

std::vector<MethodSpec> makeMethodCatalog() {
    using namespace methods;
    // The order is Table I's and every list's.
    std::vector<MethodSpec> all{priscaMethod(), priscaPaperMethod()};
    for (MethodSpec& s : pdFamilyMethods()) {
        all.push_back(std::move(s));
    }
    for (MethodSpec s : {lqrMethod(), playbackMethod(), pgsdMethod(), pegasusMethod(), ilcMethod(),
                         mpcMethod(), oracleMethod()}) {
        all.push_back(std::move(s));
    }
    return all;
}

}  // namespace

const std::vector<MethodSpec>& MethodCatalog::all() {
    static const std::vector<MethodSpec> catalog = makeMethodCatalog();
    return catalog;
}

QStringList MethodCatalog::ids() {
    QStringList ids;
    for (const MethodSpec& s : all()) {
        ids << s.id;
    }
    return ids;
}

QStringList MethodCatalog::table1Ids() {
    QStringList ids;
    for (const MethodSpec& s : all()) {
        if (s.inTable1) {
            ids << s.id;
        }
    }
    return ids;
}

QStringList MethodCatalog::defaultTable1Ids() {
    QStringList ids;
    for (const MethodSpec& s : all()) {
        if (s.inTable1 && s.inDefaultTable1) {
            ids << s.id;
        }
    }
    return ids;
}

QStringList MethodCatalog::curveIds() {
    QStringList ids;
    for (const MethodSpec& s : all()) {
        if (s.inCurves) {
            ids << s.id;
        }
    }
    return ids;
}

const MethodSpec* MethodCatalog::find(const QString& id) {
    for (const MethodSpec& s : all()) {
        if (s.id == id) {
            return &s;
        }
    }
    return nullptr;
}

const MethodSpec& MethodCatalog::get(const QString& id) {
    if (const MethodSpec* s = find(id)) {
        return *s;
    }
    throw std::invalid_argument(QStringLiteral("unknown method '%1' (one of: %2)")
                                    .arg(id, ids().join(QLatin1Char(' ')))
                                    .toStdString());
}

Eigen::VectorXd MethodCatalog::value(const MethodTuning& profile, const QString& name) {
    const MethodParameter* declared = parameter(name);
    if (!declared) {
        throw std::invalid_argument(
            QStringLiteral("no method has a parameter '%1'").arg(name).toStdString());
    }
    return declared->value(profile);
}

const core::FeatureMap& MethodCatalog::featuresOf(const MethodTuning& profile,
                                                  const QString& method) {
    const MethodSpec* spec = find(method);
    return profile.featuresFor(spec && spec->ownFeatures);
}

std::unique_ptr<core::Controller> MethodCatalog::create(
    const QString& method, const MethodTuning& profile,
    std::shared_ptr<const core::Demonstration> demonstration, const Eigen::MatrixXd& fittedB,
    const Eigen::MatrixXd* theta, const std::function<bool()>& cancelled) {
    const MethodSpec& s = get(method);
    return s.create(s, MethodInput{profile, std::move(demonstration), fittedB, theta, cancelled});
}

std::vector<const MethodParameter*> MethodCatalog::parameters() {
    std::vector<const MethodParameter*> found;
    for (const MethodSpec& spec : all()) {
        for (const MethodParameter& p : spec.parameters) {
            const bool known =
                std::any_of(found.begin(), found.end(), [&](const MethodParameter* q) {
                    return QLatin1String(q->name) == QLatin1String(p.name);
                });
            if (!known) {
                found.push_back(&p);
            }
        }
    }
    return found;
}

const MethodParameter* MethodCatalog::parameter(const QString& name) {
    for (const MethodParameter* p : parameters()) {
        if (name == QLatin1String(p->name)) {
            return p;
        }
    }
    return nullptr;
}

void MethodCatalog::setParameter(MethodTuning& profile, const QString& assignment) {
    const int equals = assignment.indexOf(QLatin1Char('='));
    if (equals <= 0) {
        throw std::invalid_argument(
            QStringLiteral("'%1' is not NAME=VALUE").arg(assignment).toStdString());
    }
    const QString name = assignment.left(equals).trimmed();
    const MethodParameter* declared = parameter(name);
    if (!declared) {
        QStringList names;
        for (const MethodParameter* p : parameters()) {
            names << QString::fromLatin1(p->name);
        }
        throw std::invalid_argument(QStringLiteral("no method has a parameter '%1' (one of: %2)")
                                        .arg(name, names.join(QLatin1Char(' ')))
                                        .toStdString());
    }
    QString error;
    const auto value =
        declared->parse(assignment.mid(equals + 1), profile.info.actionDimension(), &error);
    if (!value) {
        throw std::invalid_argument(error.toStdString());
    }
    declared->assign(profile, *value);
}

}  // namespace prisca::sim
