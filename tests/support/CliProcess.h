#pragma once
// Runs the prisca-cli the test was built with (PRISCA_CLI) and collects what it said.

#include <QProcess>
#include <QString>
#include <QStringList>

namespace prisca::test {

struct CliResult {
    int exitCode = -1;
    QString out, err;
};

/// Runs `prisca-cli arguments...` in `directory` and waits for it (at most `timeoutMs`).
inline CliResult runCli(const QStringList& arguments, const QString& directory,
                        int timeoutMs = 300000) {
    QProcess process;
    process.setWorkingDirectory(directory);
    process.start(QStringLiteral(PRISCA_CLI), arguments);
    process.waitForFinished(timeoutMs);
    return {process.exitCode(), QString::fromUtf8(process.readAllStandardOutput()),
            QString::fromUtf8(process.readAllStandardError())};
}

}  // namespace prisca::test
