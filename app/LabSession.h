#pragma once

#include "core/ActionMapping.h"
#include "core/Demonstration.h"
#include "sim/planning/Identification.h"
#include "sim/run/Task.h"
#include "sim/tuning/MethodTuning.h"

#include <QJsonArray>
#include <QObject>
#include <QString>

#include <cstdint>
#include <memory>
#include <optional>

namespace prisca::app {

/// What the operator is working on: the task (the target plant, its profile with the intuitive
/// mapping B~, the demonstration to repeat and its fit, one validated sim::Task made as the CLI
/// makes its own), and the controller's method and parameters. Lives on the GUI thread;
/// panels read it and change it through its setters, and listen to its signals. It holds plain
/// data only, so a run copies what it needs before crossing to the worker thread.
class LabSession : public QObject {
    Q_OBJECT
  public:
    explicit LabSession(QObject* parent = nullptr);

    /// The target: a sim::PlantCatalog name ("slidecar", "acrobot", ...).
    const QString& plant() const { return task_.plant; }
    /// The whole task: plant, profile, demonstration and fit, always consistent.
    const sim::Task& task() const { return task_; }
    /// Chooses a target: loads its profile (mapping, features, method defaults) and its scripted
    /// demonstration, and fits B_v. Throws std::invalid_argument for an unknown plant.
    void setPlant(const QString& plant);

    /// The plant's physical parameters (a plant file), or null for the catalog's plant.
    std::shared_ptr<const sim::PlantParameters> plantParameters() const {
        return task_.plantParameters;
    }
    /// Runs on a plant of these physical parameters (null: the catalog's). A scripted
    /// demonstration is recorded again on it; a demonstration from a file stays. Throws
    /// std::invalid_argument for another plant's parameters (the session is then unchanged).
    void setPlantParameters(std::shared_ptr<const sim::PlantParameters> parameters);

    /// The demonstration being repeated (never null once a plant is set).
    std::shared_ptr<const core::Demonstration> demonstration() const { return task_.demonstration; }
    /// Where the demonstration came from: a file path, or empty for the scripted one.
    const QString& demonstrationSource() const { return demonstrationSource_; }
    /// The demonstration in words for captions and exports: its file, or the scripted operator's
    /// style and seed.
    QString demonstrationDescription() const;
    /// The scripted operator's style and seed (meaningful while demonstrationSource() is empty).
    const QString& scriptedStyle() const { return scriptedStyle_; }
    std::uint64_t scriptedSeed() const { return scriptedSeed_; }
    /// Replaces the demonstration with the scripted operator's in this style (sim's
    /// DemonstrationStyles of the plant) and seed, and refits B_v. Throws std::invalid_argument
    /// for a style the plant does not have (the session is then unchanged).
    void setScriptedDemonstration(const QString& style, std::uint64_t seed);
    /// Replaces the demonstration and refits B_v. Throws std::invalid_argument if it is not a
    /// demonstration of the plant (sim::makeTask says why); the session is then unchanged.
    void setDemonstration(std::shared_ptr<const core::Demonstration> demonstration,
                          const QString& source);

    /// The demonstration, unchanged, now lives in `source` (saved there): the session names it.
    void setDemonstrationSource(const QString& source);

    /// The plant's profile with the operator's edits (mapping B~, method parameters).
    const sim::MethodTuning& profile() const { return task_.profile; }
    /// Replaces the profile and refits B_v if its mapping changed. Throws std::invalid_argument
    /// if the mapping is not the plant's m x n; the session is then unchanged. The profile's
    /// mpcModel stays the session's identified model, whatever the profile given holds.
    void setProfile(const sim::MethodTuning& profile);

    /// The car identified from this demonstration on this plant (the Model step), with its fit
    /// figures and parameter table; null: none. mpc plans through its parameters
    /// (profile().mpcModel is they). Saved with the session.
    std::shared_ptr<const sim::IdentificationResult> identifiedModel() const { return model_; }
    /// Keeps a model identified from `identifiedFrom`, or clears it (null). Throws
    /// std::invalid_argument, the session unchanged, for a result that is no model (refused or
    /// cancelled), of another plant, or identified from a demonstration the session no longer
    /// holds (it changed while the identification ran).
    void setIdentifiedModel(std::shared_ptr<const sim::IdentificationResult> model,
                            const std::shared_ptr<const core::Demonstration>& identifiedFrom);
    /// What an identification of this session starts from: what a lab measures of its car (the
    /// plant file's mass and geometry, or the catalog's), the rest the catalog's
    /// (sim::measuredPrior), as mpc's own identification does.
    sim::PlantParameters identificationPrior() const;

    /// Options of the last fit of B_v, and the fit itself.
    const core::ActionMappingFitOptions& fitOptions() const { return fitOptions_; }
    void setFitOptions(const core::ActionMappingFitOptions& options);
    const core::ActionMappingFit& fit() const { return task_.fit; }
    /// Fits B_v again as it is (the fit's messages in the interface's language now).
    void refit() { setFitOptions(fitOptions_); }

    /// The method a run uses (sim::MethodCatalog ids).
    const QString& method() const { return method_; }
    void setMethod(const QString& method);

    /// Saves mapping, fit options, method and parameters as JSON (atomically). On failure returns
    /// false and sets *error naming the file and what went wrong.
    bool save(const QString& path, QString* error) const;
    /// The largest session file open() reads (a session is a few KB of settings).
    static constexpr qint64 kMaxSessionBytes = qint64(16) << 20;
    /// Opens a session saved by save(). On failure the session is unchanged, *error says what is
    /// wrong and where (file, key), and false is returned.
    bool open(const QString& path, QString* error);
    /// The session as the JSON save() writes.
    QByteArray toJson() const;
    /// Restores a session from JSON as open() does; `source` names it in errors.
    bool fromJson(const QByteArray& json, const QString& source, QString* error);

    /// What the operator should know about the last session read (empty: nothing), e.g. that
    /// parameters of an earlier version were replaced by today's defaults.
    const QString& notice() const { return notice_; }

    /// The window's message log as saved with the session (MessageLog::toJson()'s lines); the
    /// session carries it and does not read it.
    void setMessages(const QJsonArray& lines) { messages_ = lines; }
    const QJsonArray& messages() const { return messages_; }

  signals:
    /// The plant changed (everything else changed with it).
    void plantChanged(const QString& plant);
    /// The plant's physical parameters changed (a plant file loaded or cleared).
    void plantParametersChanged();
    /// The demonstration changed.
    void demonstrationChanged();
    /// The same demonstration is now named by another file (saved as).
    void demonstrationSourceChanged();
    /// B~, the fit options or the demonstration changed and B_v was refitted.
    void fitChanged();
    /// The method or its parameters changed.
    void controllerChanged();
    /// The identified model was set or cleared. `reason` is empty when the operator set or
    /// cleared it (or a session was opened); else why a model the session had is gone, in the
    /// operator's words ("the demonstration changed").
    void identifiedModelChanged(const QString& reason);

  private:
    /// Drops the identified model because `reason` (nothing when there is none); emits.
    void dropModel(const QString& reason);
    /// The profile's mpcModel from model_.
    void applyModelToProfile();

    sim::Task task_;
    std::shared_ptr<const sim::IdentificationResult> model_;
    QString method_ = QStringLiteral("prisca");
    QString demonstrationSource_;
    QString scriptedStyle_;
    QString notice_;
    QJsonArray messages_;
    std::uint64_t scriptedSeed_ = 1;
    core::ActionMappingFitOptions fitOptions_;
};

}  // namespace prisca::app
