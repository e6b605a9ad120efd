#pragma once

#include "app/cli/CliCommand.h"

#include <QStringView>

#include <vector>

namespace prisca::app::cli {

/// Exit code for bad input: an unknown or unavailable command, or a malformed option.
constexpr int kExitUsage = 2;

/// Every command of docs/architecture.md "Command line", in the order `--help` lists them.
const std::vector<CliCommand>& commandTable();

/// The command called `name`, or nullptr when there is none.
const CliCommand* findCommand(QStringView name);

}  // namespace prisca::app::cli
