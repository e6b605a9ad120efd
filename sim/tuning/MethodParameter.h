#pragma once

#include <Eigen/Core>

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace prisca::sim {

struct MethodTuning;

/// One number a method is tuned by, declared once in the method's catalog entry
/// (MethodCatalog.cpp): the Controller panel, the session file, the command line
/// (`--param NAME=VALUE`, `prisca-cli methods`) and docs/methods.md all read the declaration.
/// Its value lives in a field of the plant's tuning (MethodTuning), so its default is per plant
/// and has one home: the value the plant's tuning function sets (MethodTuning.cpp,
/// DiffDriveTuning.cpp), else the field's own initial value in MethodTuning.h. Plain data; label
/// and help are translated in the context "MethodParameter".
struct MethodParameter {
    enum class Kind {
        Real,     ///< a number in [minimum, maximum]
        Integer,  ///< a whole number in [minimum, maximum]
        Switch,   ///< on (1) or off (0); written on / off
        Choice    ///< one of `choices` (the value is its index); written by name
    };
    const char* name = "";   ///< as the command line and the session spell it, e.g. "prisca.H"
    const char* label = "";  ///< the Controller panel's label, e.g. "Horizon H"
    const char* unit = "";   ///< of the value, e.g. "steps", "Hz"; empty: none
    Kind kind = Kind::Real;
    double minimum = 0.0;              ///< smallest value allowed
    double maximum = 0.0;              ///< largest value allowed
    int decimals = 3;                  ///< shown in the panel (Real)
    std::vector<const char*> choices;  ///< Choice: the names, in value order
    /// One value per control (the action channels), e.g. the PD's Kp; else one value.
    bool perChannel = false;
    /// What a value of 0 means, where it means something else than a number ("none").
    const char* zeroMeans = nullptr;
    const char* help = "";  ///< one line: what it does, the paper's equation where there is one
    /// Where the value lives in a profile: read (size 1, or the number of controls if
    /// perChannel) and write (a value check() allows). Both set in every declaration.
    Eigen::VectorXd (*get)(const MethodTuning&) = nullptr;
    void (*set)(MethodTuning&, const Eigen::VectorXd&) = nullptr;

    /// The value in `profile`.
    Eigen::VectorXd value(const MethodTuning& profile) const;
    /// Sets it; std::invalid_argument (check()'s words) if it is not allowed.
    void assign(MethodTuning& profile, const Eigen::VectorXd& value) const;

    /// The value written out: "10", "0.95", "1,1.2", "on", "closed-loop".
    QString format(const Eigen::VectorXd& value) const;
    /// Parses a value as format() writes it, for a plant with `channels` controls; nullopt and
    /// *error (naming the value and the allowed range or choices) when it is not one.
    std::optional<Eigen::VectorXd> parse(const QString& text, int channels, QString* error) const;
    /// Empty when `value` is allowed (its size, range and kind); else why not.
    QString check(const Eigen::VectorXd& value, int channels) const;
    /// The allowed values in words: "1 .. 200", "on | off", "one-step | closed-loop".
    QString range() const;
};

}  // namespace prisca::sim
