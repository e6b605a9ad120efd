#pragma once

#include <QStringList>

namespace prisca::app::cli {

/// Runs one command. `arguments` are those after the command's name (its own options, including
/// --help). Returns the process exit code: 0 on success, 2 on bad input.
using CommandFunction = int (*)(const QStringList& arguments);

/// One entry of prisca-cli's dispatch table. Each command lives in its own source file and
/// exposes one CommandFunction; the table only names it.
struct CliCommand {
    const char* name;               ///< What the user types, e.g. "table1".
    const char* summary;            ///< One line for `prisca-cli --help`.
    CommandFunction run = nullptr;  ///< nullptr while the command is planned but not built yet.
};

}  // namespace prisca::app::cli
