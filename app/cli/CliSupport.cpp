#include "app/cli/CliSupport.h"

#include "app/plot/FigureFile.h"

#include "core/DemonstrationCsv.h"
#include "devices/ProcessFailsafe.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonDocument>
#include <QLoggingCategory>

#include <unistd.h>
#include <cmath>
#include <csignal>
#include <cstdio>

namespace prisca::app::cli {

CommandLine::CommandLine(const QString& command, const QString& description) : command_(command) {
    parser_.setApplicationDescription(description);
    parser_.addHelpOption();
}

void CommandLine::addValue(const QString& name, const QString& description,
                           const QString& valueName, const QString& defaultValue) {
    QCommandLineOption option(name, description, valueName);
    if (!defaultValue.isEmpty()) {
        option.setDefaultValue(defaultValue);
    }
    parser_.addOption(option);
}

void CommandLine::addFlag(const QString& name, const QString& description) {
    parser_.addOption(QCommandLineOption(name, description));
}

void CommandLine::addFormat(const QStringList& choices) {
    addValue(QStringLiteral("format"),
             QStringLiteral("Output format: %1 (default %2).")
                 .arg(choices.join(QStringLiteral(", ")), choices.first()),
             QStringLiteral("format"), choices.first());
    formats_ = choices;
}

void CommandLine::addPositional(const QString& name, const QString& description) {
    parser_.addPositionalArgument(name, description);
    ++positionals_;
}

bool CommandLine::parse(const QStringList& arguments) {
    // QCommandLineParser wants the program name first.
    if (!parser_.parse(QStringList{QStringLiteral("prisca-cli %1").arg(command_)} + arguments)) {
        throw UsageError(parser_.errorText());
    }
    if (parser_.isSet(QStringLiteral("help"))) {
        // The usage line names the command as it is typed, not the path the program ran from.
        QString help = parser_.helpText();
        const QString usage =
            QStringLiteral("Usage: %1").arg(QCoreApplication::arguments().value(0));
        if (help.startsWith(usage)) {
            help.replace(0, usage.size(), QStringLiteral("Usage: prisca-cli %1").arg(command_));
        }
        std::printf("%s", help.toLocal8Bit().constData());
        return false;
    }
    if (parser_.positionalArguments().size() > positionals_) {
        throw UsageError(QStringLiteral("unexpected argument '%1' (see --help)")
                             .arg(parser_.positionalArguments().value(positionals_)));
    }
    if (!formats_.isEmpty() && !formats_.contains(format())) {
        throw UsageError(QStringLiteral("--format must be one of %1, got '%2'")
                             .arg(formats_.join(QStringLiteral(", ")), format()));
    }
    return true;
}

QString CommandLine::required(const QString& name) const {
    if (!parser_.isSet(name) || parser_.value(name).isEmpty()) {
        throw UsageError(QStringLiteral("--%1 is required (see --help)").arg(name));
    }
    return parser_.value(name);
}

namespace {

// UsageError naming the option, its range and the value when the value lies outside the range.
template <typename T>
void checkRange(const QString& name, T value, T minimum, T maximum) {
    if (value < minimum || value > maximum) {
        throw UsageError(QStringLiteral("--%1 must lie in [%2, %3], got %4")
                             .arg(name)
                             .arg(minimum)
                             .arg(maximum)
                             .arg(value));
    }
}

}  // namespace

double CommandLine::number(const QString& name, double minimum, double maximum) const {
    const QString text = parser_.value(name);
    bool ok = false;
    const double value = text.toDouble(&ok);
    if (!ok || !std::isfinite(value)) {
        throw UsageError(QStringLiteral("--%1 needs a number, got '%2'").arg(name, text));
    }
    checkRange(name, value, minimum, maximum);
    return value;
}

long long CommandLine::integer(const QString& name, long long minimum, long long maximum) const {
    const QString text = parser_.value(name);
    bool ok = false;
    const long long value = text.toLongLong(&ok);
    if (!ok) {
        throw UsageError(QStringLiteral("--%1 needs a whole number, got '%2'").arg(name, text));
    }
    checkRange(name, value, minimum, maximum);
    return value;
}

void installInterruptHandler() {
    devices::processfailsafe::acceptGracefulStop();
}

bool interrupted() {
    return devices::processfailsafe::stopSignal() != 0;
}

QString interruptionName() {
    return QString::fromLatin1(
        devices::processfailsafe::signalName(devices::processfailsafe::stopSignal()));
}

int interruptedExitCode() {
    const int signal = devices::processfailsafe::stopSignal();
    return 128 + (signal != 0 ? signal : SIGINT);
}

core::Demonstration readDemonstration(const QString& path) {
    core::FileError error;
    auto demonstration = core::readDemonstrationCsv(path, &error);
    if (!demonstration) {
        throw UsageError(error.toString());
    }
    return *demonstration;
}

void writeDemonstration(const core::Demonstration& demonstration, const QString& path) {
    // Numbers no demonstration holds are the data's fault, not the file's: said as such.
    if (const QString invalid = demonstration.validate(); !invalid.isEmpty()) {
        throw UsageError(QStringLiteral("the result is no demonstration a file can hold (%1); "
                                        "nothing was written to %2")
                             .arg(invalid, path));
    }
    core::FileError error;
    if (!core::writeDemonstrationCsv(demonstration, path, &error)) {
        throw UsageError(error.toString());
    }
}

QString partialPath(const QString& path) {
    const QFileInfo info(path);
    const QString suffix = info.suffix().toLower();
    if (suffix == QLatin1String("png") || suffix == QLatin1String("svg")) {
        return path.left(path.size() - suffix.size() - 1) + QStringLiteral(".partial.") +
               info.suffix();
    }
    return path + QStringLiteral(".partial");
}

QString writeOutput(const QString& path, const QByteArray& bytes, bool complete) {
    const QString target = complete ? path : partialPath(path);
    core::FileError error;
    if (!core::writeFileAtomically(target, bytes, &error)) {
        throw UsageError(error.toString());
    }
    return target;
}

QString saveFigureOutput(const plot::Figure& figure, const QString& path, bool complete) {
    const QString target = complete ? path : partialPath(path);
    saveFigureOrThrow(figure, target);
    return target;
}

void addVerboseOption(CommandLine& line) {
    line.addFlag(QStringLiteral("verbose"),
                 QStringLiteral("Also print the devices' own notes (the port opened, line "
                                "settings not applied, the camera's mode) on stderr."));
}

void applyVerbosity(const CommandLine& line) {
    if (!line.isSet(QStringLiteral("verbose"))) {
        // Warnings (a port lost) still show: only the notes of things going as they should go.
        QLoggingCategory::setFilterRules(
            QStringLiteral("prisca.*.info=false\nprisca.*.debug=false"));
    }
}

void checkOutputs(const CommandLine& line, std::initializer_list<const char*> names) {
    for (const char* name : names) {
        const QString option = QString::fromLatin1(name);
        if (!line.isSet(option)) {
            continue;
        }
        core::FileError error;
        if (!core::checkOutputPath(line.value(option), &error)) {
            throw UsageError(QStringLiteral("--%1: %2").arg(option, error.toString()));
        }
    }
}

void printJson(const QJsonObject& object) {
    std::printf("%s", QJsonDocument(object).toJson(QJsonDocument::Indented).constData());
}

void printText(const QString& text) {
    std::printf("%s", text.toLocal8Bit().constData());
    // A line as soon as it is known (a trial's result), also into a pipe: a reader that closes
    // the pipe (head) stops the command at once (SIGPIPE), not at its end.
    std::fflush(stdout);
}

void printProgress(const QString& text) {
    static const bool terminal = isatty(fileno(stderr));
    if (terminal) {
        // Overwrite the line in place; empty text just clears it.
        std::fprintf(stderr, "\r\033[K%s", text.toLocal8Bit().constData());
    } else if (!text.isEmpty()) {
        std::fprintf(stderr, "%s\n", text.toLocal8Bit().constData());
    }
    std::fflush(stderr);
}

void saveFigureOrThrow(const plot::Figure& figure, const QString& path) {
    QString error;
    if (!plot::saveFigure(figure, path, &error)) {
        throw UsageError(error);
    }
}

}  // namespace prisca::app::cli
