#include "sim/tuning/MethodParameter.h"

#include "sim/tuning/MethodTuning.h"

#include <cmath>
#include <stdexcept>

namespace prisca::sim {

namespace {

QString number(double v) {
    return QString::number(v, 'g', 10);
}

}  // namespace

Eigen::VectorXd MethodParameter::value(const MethodTuning& profile) const {
    return get(profile);
}

void MethodParameter::assign(MethodTuning& profile, const Eigen::VectorXd& value) const {
    if (const QString why = check(value, profile.info.actionDimension()); !why.isEmpty()) {
        throw std::invalid_argument(why.toStdString());
    }
    set(profile, value);
}

QString MethodParameter::format(const Eigen::VectorXd& value) const {
    switch (kind) {
        case Kind::Switch:
            return value.size() && value[0] != 0.0 ? QStringLiteral("on") : QStringLiteral("off");
        case Kind::Choice: {
            const int index = value.size() ? static_cast<int>(std::lround(value[0])) : -1;
            return index >= 0 && index < static_cast<int>(choices.size())
                       ? QString::fromLatin1(choices[static_cast<size_t>(index)])
                       : QString();
        }
        case Kind::Real:
        case Kind::Integer:
            break;
    }
    QStringList parts;
    for (Eigen::Index i = 0; i < value.size(); ++i) {
        parts << number(value[i]);
    }
    return parts.join(QLatin1Char(','));
}

QString MethodParameter::range() const {
    switch (kind) {
        case Kind::Switch:
            return QStringLiteral("on | off");
        case Kind::Choice: {
            QStringList names;
            for (const char* c : choices) {
                names << QString::fromLatin1(c);
            }
            return names.join(QStringLiteral(" | "));
        }
        case Kind::Real:
        case Kind::Integer:
            break;
    }
    return QStringLiteral("%1 .. %2").arg(number(minimum), number(maximum));
}

QString MethodParameter::check(const Eigen::VectorXd& value, int channels) const {
    const Eigen::Index expected = perChannel ? channels : 1;
    if (value.size() != expected) {
        return QStringLiteral("%1 takes %2 value%3, got %4")
            .arg(QString::fromLatin1(name))
            .arg(expected)
            .arg(expected == 1 ? "" : "s (one per control)")
            .arg(value.size());
    }
    for (Eigen::Index i = 0; i < value.size(); ++i) {
        const double v = value[i];
        bool ok = std::isfinite(v);
        switch (kind) {
            case Kind::Switch:
                ok = ok && (v == 0.0 || v == 1.0);
                break;
            case Kind::Choice:
                ok =
                    ok && v == std::round(v) && v >= 0.0 && v < static_cast<double>(choices.size());
                break;
            case Kind::Integer:
                ok = ok && v == std::round(v) && v >= minimum && v <= maximum;
                break;
            case Kind::Real:
                ok = ok && v >= minimum && v <= maximum;
                break;
        }
        if (!ok) {
            return QStringLiteral("%1: %2 is outside %3")
                .arg(QString::fromLatin1(name), number(v), range());
        }
    }
    return {};
}

std::optional<Eigen::VectorXd> MethodParameter::parse(const QString& text, int channels,
                                                      QString* error) const {
    const QString t = text.trimmed();
    Eigen::VectorXd value;
    const auto fail = [&](const QString& why) -> std::optional<Eigen::VectorXd> {
        if (error) {
            *error = why;
        }
        return std::nullopt;
    };
    if (kind == Kind::Switch) {
        if (t == QLatin1String("on") || t == QLatin1String("1") || t == QLatin1String("true")) {
            return Eigen::VectorXd::Ones(1);
        }
        if (t == QLatin1String("off") || t == QLatin1String("0") || t == QLatin1String("false")) {
            return Eigen::VectorXd::Zero(1);
        }
        return fail(
            QStringLiteral("%1: '%2' is not one of %3").arg(QString::fromLatin1(name), t, range()));
    }
    if (kind == Kind::Choice) {
        for (size_t i = 0; i < choices.size(); ++i) {
            if (t == QLatin1String(choices[i])) {
                return Eigen::VectorXd::Constant(1, static_cast<double>(i));
            }
        }
        return fail(
            QStringLiteral("%1: '%2' is not one of %3").arg(QString::fromLatin1(name), t, range()));
    }
    const QStringList parts = t.split(QLatin1Char(','));
    // One number for every control is accepted for a per-channel parameter too.
    const int count = perChannel && parts.size() == 1 ? channels : static_cast<int>(parts.size());
    value.resize(count);
    for (int i = 0; i < count; ++i) {
        bool ok = false;
        const QString part = parts[parts.size() == 1 ? 0 : i].trimmed();
        value[i] = part.toDouble(&ok);
        if (!ok) {
            return fail(
                QStringLiteral("%1: '%2' is not a number").arg(QString::fromLatin1(name), part));
        }
    }
    if (const QString why = check(value, channels); !why.isEmpty()) {
        return fail(why);
    }
    return value;
}

}  // namespace prisca::sim
