#pragma once

#include "app/plot/Figure.h"

#include "core/Demonstration.h"
#include "core/FileIo.h"

#include <QCommandLineParser>
#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <initializer_list>
#include <optional>
#include <stdexcept>

namespace prisca::app::cli {

/// A bad argument or file: main() prints "prisca-cli: <command>: <message>" and exits 2.
class UsageError : public std::runtime_error {
  public:
    /// Control characters in the message are escaped (core::printable): it quotes user input.
    explicit UsageError(const QString& message)
        : std::runtime_error(core::printable(message).toStdString()) {}
};

/// The options every command shares and the parsing of its own. One per command invocation.
class CommandLine {
  public:
    /// @param command      the command's name, for --help and messages
    /// @param description  what the command does (shown by --help)
    CommandLine(const QString& command, const QString& description);

    /// Adds an option taking a value.
    void addValue(const QString& name, const QString& description, const QString& valueName,
                  const QString& defaultValue = {});
    /// Adds a switch.
    void addFlag(const QString& name, const QString& description);
    /// Adds --format with the given choices (the first is the default).
    void addFormat(const QStringList& choices);
    /// Accepts one positional argument more (shown by --help).
    void addPositional(const QString& name, const QString& description);
    QStringList positionalArguments() const { return parser_.positionalArguments(); }

    /// Parses; prints help and returns false for --help; throws UsageError on bad options or
    /// unexpected positional arguments.
    bool parse(const QStringList& arguments);

    bool isSet(const QString& name) const { return parser_.isSet(name); }
    /// The value of a required option; UsageError naming it if missing.
    QString required(const QString& name) const;
    /// The value (or default) of an option.
    QString value(const QString& name) const { return parser_.value(name); }
    /// Every value of an option given several times, in order.
    QStringList values(const QString& name) const { return parser_.values(name); }
    /// A number in [minimum, maximum]; UsageError naming the option and the bad text.
    double number(const QString& name, double minimum, double maximum) const;
    /// An integer in [minimum, maximum].
    long long integer(const QString& name, long long minimum, long long maximum) const;
    /// The chosen output format.
    QString format() const { return parser_.value(QStringLiteral("format")); }

  private:
    QString command_;
    QCommandLineParser parser_;
    QStringList formats_;
    int positionals_ = 0;
};

/// Makes Ctrl-C (SIGINT), SIGTERM, SIGHUP, SIGQUIT and SIGPIPE ask a long command to stop:
/// interrupted() turns true, the command finishes the step it is on, ends its links in failsafe,
/// keeps what finished and exits with interruptedExitCode(). Until a command calls this, those
/// signals end the process at once (in failsafe: devices/ProcessFailsafe.h); a second one does.
void installInterruptHandler();
/// Whether a stopping signal arrived. Any thread.
bool interrupted();
/// The signal that stopped the command, for a message ("SIGTERM").
QString interruptionName();
/// Exit code after an interruption: 128 + the signal, as shells report it (130 for Ctrl-C).
int interruptedExitCode();

/// Reads a demonstration CSV; UsageError with "file:line:column: message" if bad.
core::Demonstration readDemonstration(const QString& path);
/// Writes a demonstration CSV atomically; UsageError if it cannot.
void writeDemonstration(const core::Demonstration& demonstration, const QString& path);

/// Writes a command's output atomically: to path when the work is complete; when it was
/// interrupted, to partialPath(path), leaving a complete previous file at path as it was.
/// @return the path written. UsageError naming the file if it cannot.
QString writeOutput(const QString& path, const QByteArray& bytes, bool complete);
/// Where an interrupted command's output goes: NAME.partial; a figure keeps its extension last,
/// since it names the format (curve.png -> curve.partial.png).
QString partialPath(const QString& path);
/// Saves a figure like writeOutput() (a .png or .svg file); returns the path written.
QString saveFigureOutput(const plot::Figure& figure, const QString& path, bool complete);

/// Adds --verbose: the devices' own lines (the port opened, line settings a pseudo-terminal
/// cannot take, the camera's mode) on stderr. applyVerbosity() after parse() hides them without.
void addVerboseOption(CommandLine& line);
void applyVerbosity(const CommandLine& line);

/// Checks, before the work starts, every output option of `names` that is set: a long
/// computation never ends in "cannot write" (a FIFO, a folder, a missing folder).
/// UsageError naming the option and the file.
void checkOutputs(const CommandLine& line, std::initializer_list<const char*> names);

/// Prints a JSON object on stdout (indented).
void printJson(const QJsonObject& object);
/// Prints text on stdout.
void printText(const QString& text);
/// A progress line on stderr ("\r"-updated when stderr is a terminal, one line per call
/// otherwise). Empty text ends the line.
void printProgress(const QString& text);

/// Saves a figure to a .png or .svg file; UsageError naming the path on failure.
void saveFigureOrThrow(const plot::Figure& figure, const QString& path);

}  // namespace prisca::app::cli
