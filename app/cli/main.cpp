// prisca-cli: the headless front end of PRISCA Lab. It never opens a window.
#include "app/cli/CliSupport.h"
#include "app/cli/CommandTable.h"
#include "core/FileIo.h"
#include "devices/ProcessFailsafe.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>

#include <sys/stat.h>
#include <unistd.h>
#include <csignal>
#include <cstdio>

namespace {

using prisca::app::cli::CliCommand;
using prisca::app::cli::kExitUsage;

// One line on stderr, prefixed so it is clear which program complained inside a script.
int fail(const QString& message) {
    std::fprintf(stderr, "prisca-cli: %s\n",
                 prisca::core::printable(message).toLocal8Bit().constData());
    return kExitUsage;
}

QString describeCommands() {
    QString text = QStringLiteral(
        "PRISCA Lab without a window: simulate plants, fit the action mapping, run PRISCA and "
        "its baselines, and report the paper's metrics.\n\nCommands:\n");
    for (const CliCommand& command : prisca::app::cli::commandTable()) {
        const QString state = command.run ? QString() : QStringLiteral(" (planned)");
        text += QStringLiteral("  %1  %2%3\n")
                    .arg(QLatin1String(command.name), -9)
                    .arg(QLatin1String(command.summary), state);
    }
    text += QStringLiteral("\nRun 'prisca-cli <command> --help' for the options of a command.");
    return text;
}

}  // namespace

int main(int argc, char* argv[]) {
    // First of all: however this process ends short of SIGKILL, an open transmitter link's last
    // frames are failsafe, and stderr says so (devices/ProcessFailsafe.h).
    prisca::devices::processfailsafe::install("prisca-cli");
    // A write past a file-size limit fails with an error (exit 2 naming the file) instead of
    // killing the process with SIGXFSZ and leaving a temporary file behind.
    std::signal(SIGXFSZ, SIG_IGN);
    // A widgets application only because the figures are drawn with QtCharts, which is made of
    // widgets; the offscreen platform means no window and no display are ever needed.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
    }
    // Without a runtime directory Qt warns on stderr, which would break the promise of one line
    // there on error: give it a private one (mode 0700, as the XDG specification asks).
    if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
        const QByteArray runtime = QDir::tempPath().toLocal8Bit() + "/prisca-runtime-" +
                                   QByteArray::number(static_cast<qulonglong>(getuid()));
        ::mkdir(runtime.constData(), 0700);
        qputenv("XDG_RUNTIME_DIR", runtime);
    }
    // The application takes options such as --style and --platform out of argv for itself;
    // every argument here is the command's (demo --style), so it sees only the program name.
    QStringList arguments;
    for (int i = 0; i < argc; ++i) {
        arguments << QString::fromLocal8Bit(argv[i]);
    }
    int applicationArgc = 1;
    QApplication application(applicationArgc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("PRISCA Lab"));
    QCoreApplication::setApplicationName(QStringLiteral("prisca-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(PRISCA_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(describeCommands());
    const QCommandLineOption helpOption = parser.addHelpOption();
    const QCommandLineOption versionOption = parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("command"),
                                 QStringLiteral("One of the commands above."),
                                 QStringLiteral("<command> [<options>...]"));
    // Everything after the command is the command's own, including its --help.
    parser.setOptionsAfterPositionalArgumentsMode(QCommandLineParser::ParseAsPositionalArguments);

    // parse() rather than process(): process() exits with 1 on bad input, we promise 2.
    if (!parser.parse(arguments)) {
        return fail(parser.errorText());
    }
    if (parser.isSet(versionOption)) {
        parser.showVersion();
    }
    if (parser.isSet(helpOption)) {
        parser.showHelp(0);
    }

    const QStringList positional = parser.positionalArguments();
    if (positional.isEmpty()) {
        return fail(QStringLiteral("no command given (see --help)"));
    }
    const QString name = positional.first();
    const CliCommand* command = prisca::app::cli::findCommand(name);
    if (command == nullptr) {
        return fail(QStringLiteral("unknown command '%1' (see --help)").arg(name));
    }
    if (command->run == nullptr) {
        return fail(QStringLiteral("command '%1' is not available in this version").arg(name));
    }
    // Bad arguments and files surface as UsageError; anything else thrown below is a bad
    // argument combination that a layer refused (std::invalid_argument): one line, exit 2.
    // A link the command had open has closed by the time the error is caught (its destructor
    // sends failsafe last): the message says so.
    const auto failsafeNote = [] {
        const int links = prisca::devices::processfailsafe::failsafeEndings();
        return links > 0 ? QStringLiteral(" (the link ended in failsafe)") : QString();
    };
    try {
        return command->run(positional.mid(1));
    } catch (const prisca::app::cli::UsageError& error) {
        return fail(QStringLiteral("%1: %2%3")
                        .arg(name, QString::fromStdString(error.what()), failsafeNote()));
    } catch (const std::exception& error) {
        return fail(QStringLiteral("%1: %2%3")
                        .arg(name, QString::fromStdString(error.what()), failsafeNote()));
    }
}
