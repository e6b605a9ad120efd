// prisca: the PRISCA Lab desktop application.
#include "app/ApplicationIcon.h"
#include "app/LanguageSwitcher.h"
#include "app/MainWindow.h"
#include "devices/ProcessFailsafe.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QCoreApplication>

#include <csignal>
#include <cstring>

namespace {

void nameApplication() {
    // QSettings derives its file location from these names.
    QCoreApplication::setOrganizationName(QStringLiteral("PRISCA Lab"));
    QCoreApplication::setApplicationName(QStringLiteral("prisca"));
    QCoreApplication::setApplicationVersion(QStringLiteral(PRISCA_VERSION));
}

void describe(QCommandLineParser& parser) {
    parser.setApplicationDescription(QStringLiteral(
        "The PRISCA Lab window: record a demonstration from the ceiling camera or a keyboard or "
        "gamepad, fit the action mapping, identify the car, run PRISCA and its baselines on a "
        "simulated plant or on the rig, watch the tracking errors live and export Table I. "
        "E-STOP is Space or Esc, everywhere in the window. Help > Operator guide (F1) is the full "
        "guide; the headless commands are prisca-cli's."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(
        QStringLiteral("session"),
        QStringLiteral("A session file (JSON, as File > Save session writes it) to open at start."),
        QStringLiteral("[session]"));
}

// --help and --version are answered without a display (a terminal over ssh, the manual page's
// generator): before the window's application, which needs one, is made.
bool asksForText(int argc, char* argv[]) {
    for (int i = 1; i < argc; ++i) {
        for (const char* option : {"-h", "--help", "-v", "--version", "--help-all"}) {
            if (std::strcmp(argv[i], option) == 0) {
                return true;
            }
        }
    }
    return false;
}

}  // namespace

int main(int argc, char* argv[]) {
    // However the window's process ends short of SIGKILL (a signal, a crash, an uncaught
    // exception), a connected link's last frames are failsafe (devices/ProcessFailsafe.h).
    prisca::devices::processfailsafe::install("prisca");
    // A write past a file-size limit fails with an error the saving code reports, instead of
    // killing the window (and the operator's unsaved work) with SIGXFSZ.
    std::signal(SIGXFSZ, SIG_IGN);
    if (asksForText(argc, argv)) {
        QCoreApplication text(argc, argv);
        nameApplication();
        QCommandLineParser parser;
        describe(parser);
        parser.process(text);  // prints the help or the version and exits
        return 0;
    }
    QApplication application(argc, argv);
    nameApplication();
    QApplication::setWindowIcon(prisca::app::applicationIcon());
    QCommandLineParser parser;
    describe(parser);
    parser.process(application);  // an unknown option: says so and exits 1
    const QStringList sessions = parser.positionalArguments();
    if (sessions.size() > 1) {
        parser.showHelp(2);
    }

    // The language goes in before any widget exists, so the first paint is already translated.
    prisca::app::LanguageSwitcher languages;
    languages.restoreLanguage();

    prisca::app::MainWindow window(languages);
    window.show();
    if (!sessions.isEmpty()) {
        window.openSession(sessions.first());  // a file it cannot read: says so in a box
    }
    return QApplication::exec();
}
