#pragma once

#include "core/ActionMapping.h"
#include "core/Demonstration.h"
#include "sim/DemonstrationStyles.h"
#include "sim/plants/Plant.h"
#include "sim/plants/PlantParameters.h"
#include "sim/run/RunSetup.h"
#include "sim/run/Task.h"
#include "sim/tuning/MethodTuning.h"

#include <memory>

namespace prisca::app::cli {

class CommandLine;

/// The task the window's session is made the same way from (sim::makeTask).
using Task = sim::Task;

/// Reads the demonstration, checks that it belongs to the plant (names, dimensions), applies a
/// mask text "r0c0,...;r1c0,..." if given, and fits B_v. Throws UsageError naming what is wrong.
Task loadTask(const QString& plant, const QString& demonstrationPath, const QString& mask,
              const core::ActionMappingFitOptions& options = {});

/// Whether every sample's action is the first one (nothing to fit B_v on).
bool actionsNeverChange(const core::Demonstration& demonstration);

/// loadTask() on a demonstration already read (`demonstrationPath` names it in messages).
Task taskFor(const QString& plant, core::Demonstration demonstration,
             const QString& demonstrationPath, const QString& mask,
             const core::ActionMappingFitOptions& options = {});

/// The task of a scripted demonstration, checked as a file would be (written and read back in
/// the format's text, in memory); `sourceName` names it in messages.
Task scriptedTaskFor(const QString& plant, const core::Demonstration& scripted,
                     const QString& sourceName);

/// The plant name, checked against the catalogue; UsageError naming the known plants if not.
QString checkedPlant(const QString& name);

/// The task from a demonstration file if one is given, else from the plant's scripted
/// demonstration with this seed (checked the same way as a file), recorded in `conditions`
/// (the plant file's car, the session day's mismatch).
Task loadOrDemonstrate(const QString& plant, const QString& demonstrationPath,
                       std::uint64_t demoSeed, const sim::RecordingConditions& conditions = {});

/// The task of a scripted demonstration in a style with a seed's hand variation (checked as a
/// file would be), recorded in `conditions`; UsageError for an unknown plant or style.
Task scriptedTask(const QString& plant, const QString& style, std::uint64_t seed,
                  const sim::RecordingConditions& conditions = {});

/// Adds --plant-params FILE (a plant file: the plant's physical parameters).
void addPlantParametersOption(CommandLine& line);
/// The plant file --plant-params names, read and checked against `plant`; null when not given.
/// UsageError naming the file and what is wrong (an unknown key, a value out of its range).
std::shared_ptr<const sim::PlantParameters> plantParametersOption(const CommandLine& line,
                                                                  const QString& plant);

/// The task of a command with --plant-params, --demo and --demo-seed: the demonstration file
/// if one is given, else the plant's scripted demonstration recorded on the plant file's car (as
/// the window records its own). The task keeps the plant file (null: the catalog's car).
Task taskFromOptions(const CommandLine& line, const QString& plant);

/// The styles --styles names for the plant ('all', or a comma-separated list); UsageError for
/// none or an unknown one.
QStringList stylesOption(const CommandLine& line, const QString& plant);

/// Adds --param NAME=VALUE (repeatable): a method parameter as the catalog declares it
/// (sim::MethodCatalog::parameters()); and --start demo|tuned, the law PRISCA and the PD
/// family start from (the parameter `start`).
void addMethodParameterOptions(CommandLine& line);
/// Applies --start, then every --param to the profile, in order; UsageError naming the parameter,
/// the value and what is allowed. A plant from a file (`plantFromFile`) starts from the
/// demonstration unless --start says otherwise.
void applyMethodParameters(const CommandLine& line, sim::MethodTuning& profile,
                           bool plantFromFile = false);

/// Adds the run settings every simulated run shares (sim::RunSettings, with its defaults):
/// --seed, --perturbation, --perturbation-model, --sensor, --pose-filter, --training-trials
/// (described by `trainingHelp`; none for an empty one), --jobs.
void addRunSettingsOptions(CommandLine& line, const QString& trainingHelp);
/// Reads them (--training-trials only if `training`); UsageError naming an option out of range.
void readRunSettings(const CommandLine& line, sim::RunSettings& settings, bool training = true);

}  // namespace prisca::app::cli
