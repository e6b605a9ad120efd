// prisca: the PRISCA Lab desktop application.
#include "app/ApplicationIcon.h"
#include "app/LanguageSwitcher.h"
#include "app/MainWindow.h"
#include "devices/ProcessFailsafe.h"

#include <QApplication>

#include <csignal>

int main(int argc, char* argv[]) {
    // However the window's process ends short of SIGKILL (a signal, a crash, an uncaught
    // exception), a connected link's last frames are failsafe (devices/ProcessFailsafe.h).
    prisca::devices::processfailsafe::install("prisca");
    // A write past a file-size limit fails with an error the saving code reports, instead of
    // killing the window (and the operator's unsaved work) with SIGXFSZ.
    std::signal(SIGXFSZ, SIG_IGN);
    QApplication application(argc, argv);
    // QSettings derives its file location from these names.
    QApplication::setOrganizationName(QStringLiteral("PRISCA Lab"));
    QApplication::setApplicationName(QStringLiteral("prisca"));
    QApplication::setApplicationVersion(QStringLiteral(PRISCA_VERSION));
    QApplication::setWindowIcon(prisca::app::applicationIcon());

    // The language goes in before any widget exists, so the first paint is already translated.
    prisca::app::LanguageSwitcher languages;
    languages.restoreLanguage();

    prisca::app::MainWindow window(languages);
    window.show();
    return QApplication::exec();
}
